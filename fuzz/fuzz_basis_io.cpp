// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the basis cache reader: Manifold_harmonics_basis::load() and
// Spectral_surface_mesh_deformation::load_basis() on a fixed tiny mesh.
// Input: one mode byte, then the stream. Mode bit 0 rewrites the trailing
// checksum so that corrupted sizes and values get past it; bit 1 also
// deforms with a basis the deformation accepted.
//
// Property: load() throws Spectral_deformation_error (IO_ERROR,
// MESH_MISMATCH or INVALID_MESH) and leaves the basis unchanged, or loads a
// finite basis of the right size; load_basis() likewise, and a deformation
// with the loaded basis either succeeds with finite positions or fails with
// a message and leaves the mesh untouched.
#include "fuzz_common.h"

#include <CGAL/Manifold_harmonics_basis.h>
#include <CGAL/Spectral_surface_mesh_deformation.h>

#include <sstream>

namespace {

using namespace ssmd_fuzz;
typedef CGAL::Manifold_harmonics_basis<Mesh> Basis;
typedef CGAL::Spectral_deformation_error Error;

struct Fixture
{
  Mesh mesh = basis_fixture_mesh();
  Basis reference{mesh, basis_fixture_frequencies};
};

const Fixture& fixture()
{
  static const Fixture f;
  return f;
}

bool documented_load_error(const Error& e)
{
  return e.code() == Error::IO_ERROR || e.code() == Error::MESH_MISMATCH ||
         e.code() == Error::INVALID_MESH;
}

void check_basis_loader(const std::string& bytes)
{
  const Fixture& f = fixture();
  Basis basis = f.reference;
  std::istringstream is(bytes);
  try
  {
    basis.load(is, f.mesh);
    require(basis.number_of_vertices() == f.mesh.number_of_vertices(), "load: wrong number of rows");
    require(basis.number_of_frequencies() >= 1 &&
                basis.number_of_frequencies() <= basis.number_of_vertices(),
            "load: number of frequencies out of range");
    require(basis.eigenvalues().size() == static_cast<Eigen::Index>(basis.number_of_frequencies()) &&
                basis.mass().size() == static_cast<Eigen::Index>(basis.number_of_vertices()),
            "load: inconsistent sizes");
    require(basis.basis().allFinite() && basis.eigenvalues().allFinite() && basis.mass().allFinite(),
            "load: non-finite values accepted");
    require(basis.mesh_fingerprint() == f.reference.mesh_fingerprint(), "load: another mesh accepted");
  }
  catch(const Error& e)
  {
    require(documented_load_error(e), std::string("load: unexpected error code: ") + e.what());
    require(basis.basis() == f.reference.basis() && basis.eigenvalues() == f.reference.eigenvalues() &&
                basis.mass() == f.reference.mass(),
            "load: a failed load changed the basis");
  }
  catch(...)
  {
    violation("load: undocumented exception");
  }
}

void check_deformation_loader(const std::string& bytes, bool deform)
{
  Mesh mesh = fixture().mesh;
  const std::vector<Point> before = positions(mesh);
  CGAL::Spectral_surface_mesh_deformation<Mesh> deformation(mesh);
  const std::vector<Vertex> all(mesh.vertices().begin(), mesh.vertices().end());
  deformation.insert_roi_vertices(all.begin(), all.end());
  deformation.insert_control_vertex(all.front());
  deformation.insert_control_vertex(all.back());
  deformation.translate(all.back(), Eigen::Vector3d(0.1, 0.2, 0.3));
  bool loaded = false;
  std::istringstream is(bytes);
  try
  {
    deformation.load_basis(is);
    loaded = true;
  }
  catch(const Error& e)
  {
    require(documented_load_error(e), std::string("load_basis: unexpected error code: ") + e.what());
  }
  catch(...)
  {
    violation("load_basis: undocumented exception");
  }
  require(same_positions(positions(mesh), before), "load_basis changed the mesh");
  if(!loaded || !deform)
    return;
  try
  {
    deformation.deform();
  }
  catch(...)
  {
    violation("deform() threw with a loaded basis");
  }
  const std::vector<Point> after = positions(mesh);
  if(deformation.deform_report().success)
  {
    require(!deformation.preprocess_report().basis_computed, "the loaded basis was not used");
    for(const Point& p : after)
      require(finite_point(p), "deform() succeeded with non-finite positions");
  }
  else
  {
    require(!deformation.deform_report().message.empty(), "deform() failed without a message");
    require(same_positions(after, before), "a failed deform() changed the mesh");
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size < 1)
    return 0;
  const std::uint8_t mode = data[0];
  std::string bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
  if(mode & 1)
    fix_basis_checksum(bytes);
  check_basis_loader(bytes);
  check_deformation_loader(bytes, (mode & 2) != 0);
  return 0;
}
