// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_INTERNAL_BASIS_BASIS_IN_REGION_ORDER_H
#define CGAL_SPECTRAL_DEFORMATION_INTERNAL_BASIS_BASIS_IN_REGION_ORDER_H

#include <CGAL/Spectral_deformation/internal/Basis/basis_io.h>
#include <CGAL/Spectral_deformation/internal/Mesh/Region.h>

#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace Spectral_deformation {
namespace internal {
namespace Basis {

/// Whether `data` was computed on the arrays of `region` (its own vertex
/// order) or on the same arrays in the mesh's order (`Mesh::in_mesh_order()`:
/// a basis of the whole mesh, or a basis file of version 0.1).
enum class Basis_match
{
  NONE,
  REGION_ORDER,
  MESH_ORDER
};

/// `region_fingerprint` is `fingerprint(region.arrays)`, which the callers
/// need anyway.
inline Basis_match basis_match(const Basis_data& data, const Mesh::Region_geometry& region,
                               std::uint64_t region_fingerprint)
{
  if(data.empty() || data.basis.rows() != region.number_of_vertices() ||
     data.number_of_faces != static_cast<std::uint64_t>(region.arrays.number_of_faces()))
    return Basis_match::NONE;
  if(data.fingerprint == region_fingerprint)
    return Basis_match::REGION_ORDER;
  if(data.fingerprint == fingerprint(Mesh::in_mesh_order(region)))
    return Basis_match::MESH_ORDER;
  return Basis_match::NONE;
}

/// `data` with its rows in the order of the region's vertices; `data` must
/// match `region` (`basis_match()` not `NONE`).
inline Basis_data in_region_order(const Basis_data& data, const Mesh::Region_geometry& region, Basis_match match,
                                  std::uint64_t region_fingerprint)
{
  if(match != Basis_match::MESH_ORDER)
    return data;
  Basis_data result;
  result.eigenvalues = data.eigenvalues;
  result.number_of_faces = data.number_of_faces;
  result.basis.resize(data.basis.rows(), data.basis.cols());
  result.mass.resize(data.mass.size());
  const std::vector<int>& local = region.vertex_from_mesh_order;
  for(std::size_t k = 0; k < local.size(); ++k)
  {
    result.basis.row(local[k]) = data.basis.row(static_cast<Eigen::Index>(k));
    result.mass[local[k]] = data.mass[static_cast<Eigen::Index>(k)];
  }
  result.fingerprint = region_fingerprint;
  return result;
}

} // namespace Basis
} // namespace internal
} // namespace Spectral_deformation
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_INTERNAL_BASIS_BASIS_IN_REGION_ORDER_H
