// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Writes the seeds of the basis cache harness with the package's own save
// functions: `ssmd_fuzz_make_seeds DIR` (DIR is fuzz/corpus/fuzz_basis_io).
// Seeds start with the harness's mode byte (see fuzz_basis_io.cpp).
#include "fuzz_common.h"

#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>

#include <fstream>
#include <iostream>
#include <sstream>

using namespace ssmd_fuzz;

static void write_seed(const std::string& directory, const std::string& name, char mode,
                       const std::string& bytes)
{
  std::ofstream out(directory + "/" + name, std::ios::binary);
  out.put(mode);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if(!out)
    throw std::runtime_error("cannot write " + directory + "/" + name);
}

int main(int argc, char** argv)
{
  if(argc != 2)
  {
    std::cerr << "usage: " << argv[0] << " OUTPUT_DIRECTORY\n";
    return 2;
  }
  const std::string directory = argv[1];
  const Mesh mesh = basis_fixture_mesh();

  std::ostringstream basis_stream;
  CGAL::Manifold_harmonics_basis<Mesh>(mesh, basis_fixture_frequencies).save(basis_stream);
  const std::string basis = basis_stream.str();

  // The same region through the deformation class, with m = 3.
  Mesh copy = mesh;
  CGAL::Spectral_surface_mesh_deformation<Mesh> deformation(copy);
  const std::vector<Vertex> all(copy.vertices().begin(), copy.vertices().end());
  deformation.insert_roi_vertices(all.begin(), all.end());
  deformation.insert_control_vertex(all.front());
  deformation.set_number_of_frequencies(3);
  if(!deformation.preprocess())
    throw std::runtime_error(deformation.preprocess_report().message);
  std::ostringstream region_stream;
  deformation.save_basis(region_stream);
  const std::string region = region_stream.str();

  write_seed(directory, "valid_m6", 0, basis);
  write_seed(directory, "valid_m6_deform", 2, basis);
  write_seed(directory, "valid_m3_region_deform", 3, region);
  write_seed(directory, "truncated_header", 0, basis.substr(0, 30));
  write_seed(directory, "truncated_payload", 1, basis.substr(0, basis.size() / 2));
  std::string flipped = basis;
  flipped[flipped.size() / 2] ^= 0x40;
  write_seed(directory, "flipped_byte", 0, flipped);
  write_seed(directory, "flipped_byte_fixed_checksum", 3, flipped);
  std::string huge = basis;
  const std::uint64_t n = std::uint64_t(1) << 30; // header claims 2^30 vertices
  std::memcpy(&huge[12], &n, sizeof(n));
  write_seed(directory, "huge_header", 1, huge);
  write_seed(directory, "not_a_basis", 0, "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  return 0;
}
