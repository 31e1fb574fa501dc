// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_BASIS_BASIS_IO_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_BASIS_BASIS_IO_H

#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Triangle_arrays.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cstdint>
#include <istream>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Basis {

using Mesh::Triangle_arrays;
using Mesh::fingerprint;

/// A manifold harmonics basis and the identity of the mesh it belongs to.
struct Basis_data
{
  Eigen::VectorXd eigenvalues;
  Eigen::MatrixXd basis;
  Eigen::VectorXd mass;
  std::uint64_t number_of_faces = 0;
  std::uint64_t fingerprint = 0;

  bool empty() const { return basis.size() == 0; }
};

constexpr char basis_format_tag[8] = {'S', 'S', 'M', 'D', 'M', 'H', 'B', '\0'};
constexpr std::uint32_t basis_format_version = 1;

// FNV-1a over every byte written or read, so that a flipped byte is detected.
class Checksummed_stream
{
public:
  void add(const void* data, std::size_t size)
  {
    const unsigned char* bytes = static_cast<const unsigned char*>(data);
    for(std::size_t i = 0; i < size; ++i)
    {
      m_value ^= bytes[i];
      m_value *= 1099511628211ull;
    }
  }
  std::uint64_t value() const { return m_value; }

private:
  std::uint64_t m_value = 1469598103934665603ull;
};

/// Writes a header (format tag and version, numbers of vertices, faces and
/// frequencies, mesh fingerprint), the eigenvalues, the mass, the basis and a
/// checksum of all of it. Throws IO_ERROR when the stream fails. The basis
/// is `basis`, in double or float (written widened to double), in place of
/// `data.basis`.
template <typename Scalar>
void write_basis(std::ostream& os, const Basis_data& data,
                 const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>& basis)
{
  Checksummed_stream sum;
  auto write = [&](const void* bytes, std::size_t size) {
    os.write(static_cast<const char*>(bytes), static_cast<std::streamsize>(size));
    sum.add(bytes, size);
  };
  const std::uint64_t n = static_cast<std::uint64_t>(basis.rows());
  const std::uint64_t m = static_cast<std::uint64_t>(basis.cols());
  write(basis_format_tag, sizeof(basis_format_tag));
  write(&basis_format_version, sizeof(basis_format_version));
  write(&n, sizeof(n));
  write(&data.number_of_faces, sizeof(data.number_of_faces));
  write(&m, sizeof(m));
  write(&data.fingerprint, sizeof(data.fingerprint));
  write(data.eigenvalues.data(), sizeof(double) * static_cast<std::size_t>(data.eigenvalues.size()));
  write(data.mass.data(), sizeof(double) * static_cast<std::size_t>(data.mass.size()));
  if constexpr(std::is_same<Scalar, double>::value)
    write(basis.data(), sizeof(double) * static_cast<std::size_t>(basis.size()));
  else
  {
    Eigen::VectorXd column;
    for(Eigen::Index j = 0; j < basis.cols(); ++j)
    {
      column = basis.col(j).template cast<double>();
      write(column.data(), sizeof(double) * static_cast<std::size_t>(column.size()));
    }
  }
  const std::uint64_t checksum = sum.value();
  os.write(reinterpret_cast<const char*>(&checksum), sizeof(checksum));
  if(!os)
    throw Spectral_deformation_error(Spectral_deformation_error::IO_ERROR,
                                     "save: writing the basis failed");
}

/// Writes `data` with its own basis (see above).
inline void write_basis(std::ostream& os, const Basis_data& data) { write_basis(os, data, data.basis); }

/// The number of bytes left in `is`, or -1 when the stream cannot tell
/// (a pipe, for instance). The position and state of `is` are kept.
inline std::streamoff remaining_bytes(std::istream& is)
{
  const std::istream::pos_type here = is.tellg();
  if(here == std::istream::pos_type(-1))
  {
    is.clear();
    return -1;
  }
  is.seekg(0, std::ios::end);
  const std::istream::pos_type end = is.tellg();
  is.clear();
  is.seekg(here);
  if(end == std::istream::pos_type(-1) || !is)
  {
    is.clear();
    return -1;
  }
  return static_cast<std::streamoff>(end - here);
}

/// Reads what `write_basis()` wrote. Throws IO_ERROR for a stream that is
/// not a basis, truncated, corrupted, or holds non-finite values.
inline Basis_data read_basis(std::istream& is, std::uint64_t max_vertices = (std::uint64_t(1) << 31))
{
  typedef Spectral_deformation_error Error;
  Checksummed_stream sum;
  auto read = [&](void* bytes, std::size_t size) {
    is.read(static_cast<char*>(bytes), static_cast<std::streamsize>(size));
    if(!is)
      throw Error(Error::IO_ERROR, "load: the basis file is truncated or unreadable");
    sum.add(bytes, size);
  };
  char tag[sizeof(basis_format_tag)];
  read(tag, sizeof(tag));
  if(!std::equal(tag, tag + sizeof(tag), basis_format_tag))
    throw Error(Error::IO_ERROR, "load: the stream does not hold a manifold harmonics basis");
  std::uint32_t version = 0;
  read(&version, sizeof(version));
  if(version != basis_format_version)
    throw Error(Error::IO_ERROR, "load: unsupported basis file version");
  std::uint64_t n = 0, m = 0;
  Basis_data data;
  read(&n, sizeof(n));
  read(&data.number_of_faces, sizeof(data.number_of_faces));
  read(&m, sizeof(m));
  read(&data.fingerprint, sizeof(data.fingerprint));
  // Bound the sizes before allocating: a corrupted header must not ask for
  // terabytes.
  if(n == 0 || n > max_vertices || m < 1 || m > n || n * m > (std::uint64_t(1) << 34))
    throw Error(Error::IO_ERROR, "load: corrupted header (sizes out of range)");
  // Never allocate more than the stream holds: a header that claims huge
  // sizes must fail as a truncated file, not exhaust the memory. The size of
  // a stream that can tell it is checked first; another stream is read in
  // chunks that grow with what actually arrives.
  const std::uint64_t payload = sizeof(double) * (m + n + n * m) + sizeof(std::uint64_t);
  const std::streamoff left = remaining_bytes(is);
  if(left >= 0 && static_cast<std::uint64_t>(left) < payload)
    throw Error(Error::IO_ERROR, "load: the basis file is truncated or unreadable");
  if(left >= 0)
  {
    data.eigenvalues.resize(static_cast<Eigen::Index>(m));
    data.mass.resize(static_cast<Eigen::Index>(n));
    data.basis.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(m));
    read(data.eigenvalues.data(), sizeof(double) * m);
    read(data.mass.data(), sizeof(double) * n);
    read(data.basis.data(), sizeof(double) * n * m);
  }
  else
  {
    auto read_chunked = [&](std::uint64_t count) {
      const std::uint64_t chunk = std::uint64_t(1) << 17; // doubles
      std::vector<double> values;
      while(values.size() < count)
      {
        const std::size_t done = values.size();
        values.resize(done + static_cast<std::size_t>((std::min)(count - done, chunk)));
        read(values.data() + done, sizeof(double) * (values.size() - done));
      }
      return values;
    };
    const std::vector<double> eigenvalues = read_chunked(m);
    const std::vector<double> mass = read_chunked(n);
    const std::vector<double> basis = read_chunked(n * m);
    data.eigenvalues = Eigen::Map<const Eigen::VectorXd>(eigenvalues.data(), static_cast<Eigen::Index>(m));
    data.mass = Eigen::Map<const Eigen::VectorXd>(mass.data(), static_cast<Eigen::Index>(n));
    data.basis = Eigen::Map<const Eigen::MatrixXd>(basis.data(), static_cast<Eigen::Index>(n),
                                                   static_cast<Eigen::Index>(m));
  }
  const std::uint64_t computed = sum.value();
  std::uint64_t stored = 0;
  is.read(reinterpret_cast<char*>(&stored), sizeof(stored));
  if(!is || stored != computed)
    throw Error(Error::IO_ERROR, "load: the basis file is truncated or corrupted");
  if(!data.eigenvalues.allFinite() || !data.mass.allFinite() || !data.basis.allFinite())
    throw Error(Error::IO_ERROR, "load: the basis file holds non-finite values");
  return data;
}

/// Throws MESH_MISMATCH unless `data` was computed on `mesh`.
inline void check_basis_matches(const Basis_data& data, const Triangle_arrays& mesh)
{
  typedef Spectral_deformation_error Error;
  if(static_cast<std::uint64_t>(data.basis.rows()) != static_cast<std::uint64_t>(mesh.number_of_vertices()) ||
     data.number_of_faces != static_cast<std::uint64_t>(mesh.number_of_faces()))
    throw Error(Error::MESH_MISMATCH,
                "load: the basis was computed on a mesh with " + std::to_string(data.basis.rows()) +
                    " vertices and " + std::to_string(data.number_of_faces) + " faces, this mesh has " +
                    std::to_string(mesh.number_of_vertices()) + " and " +
                    std::to_string(mesh.number_of_faces()));
  if(data.fingerprint != fingerprint(mesh))
    throw Error(Error::MESH_MISMATCH, "load: the basis was computed on a different mesh "
                                      "(connectivity or coordinates differ)");
}

} // namespace Basis
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_BASIS_BASIS_IO_H
