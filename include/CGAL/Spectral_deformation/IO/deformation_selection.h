// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// This header is part of the Spectral Surface Mesh Deformation package, which
// builds on CGAL but is not part of the CGAL library.

#ifndef CGAL_SPECTRAL_DEFORMATION_IO_DEFORMATION_SELECTION_H
#define CGAL_SPECTRAL_DEFORMATION_IO_DEFORMATION_SELECTION_H

#include <CGAL/Spectral_deformation/Spectral_deformation_error.h>

#include <Eigen/Dense>

#include <cmath>
#include <fstream>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace IO {

/// \ingroup PkgSpectralSurfaceMeshDeformationIO
/// The role of a vertex in a deformation selection (`.sel` file of the
/// benchmark of Botsch and Sorkine 2008). The region of interest of a
/// `Spectral_surface_mesh_deformation` is made of the `ROI_VERTEX` and
/// `HANDLE_VERTEX` vertices, and its control vertices of the
/// `HANDLE_VERTEX` vertices.
enum Deformation_vertex_status {
  FIXED_VERTEX = 0,   ///< outside the region of interest: does not move
  ROI_VERTEX = 1,     ///< in the region of interest, free
  HANDLE_VERTEX = 2   ///< a control vertex, moved by the handle transformation
};

/// \ingroup PkgSpectralSurfaceMeshDeformationIO
/// Reads a `.sel` file: one status (0, 1 or 2, see
/// `Deformation_vertex_status`) per vertex, in the vertex order of the mesh
/// file, separated by white space; a `#` starts a comment that runs to the
/// end of its line.
///
/// \param is the stream
/// \param number_of_vertices the expected number of statuses
/// \returns one status per vertex
/// \throws Spectral_deformation_error (`IO_ERROR`) when the stream holds
///         anything else than comments and statuses, a status other than 0, 1
///         or 2, or not exactly `number_of_vertices` of them, or cannot be
///         read.
inline std::vector<Deformation_vertex_status> read_selection(std::istream& is,
                                                             std::size_t number_of_vertices)
{
  typedef Spectral_deformation_error Error;
  std::vector<Deformation_vertex_status> status;
  status.reserve(number_of_vertices);
  std::string line;
  std::size_t line_number = 0;
  while(std::getline(is, line))
  {
    ++line_number;
    std::istringstream words(line);
    std::string word;
    if(!(words >> word) || word[0] == '#')
      continue;
    do
    {
      if(word[0] == '#')
        break;
      if(word.size() != 1 || word[0] < '0' || word[0] > '2')
        throw Error(Error::IO_ERROR, "selection line " + std::to_string(line_number) +
                                         ": expected a status 0, 1 or 2, got '" + word + "'");
      if(status.size() == number_of_vertices)
        throw Error(Error::IO_ERROR, "selection: more statuses than the " +
                                         std::to_string(number_of_vertices) + " vertices of the mesh");
      status.push_back(static_cast<Deformation_vertex_status>(word[0] - '0'));
    } while(words >> word);
  }
  if(is.bad())
    throw Error(Error::IO_ERROR, "selection: the stream could not be read");
  if(status.size() != number_of_vertices)
    throw Error(Error::IO_ERROR, "selection: " + std::to_string(status.size()) +
                                     " statuses for a mesh of " + std::to_string(number_of_vertices) +
                                     " vertices");
  return status;
}

/// \ingroup PkgSpectralSurfaceMeshDeformationIO
/// Reads a `.def` file: a 4×4 affine matrix, row-major, that moves the
/// handle vertices (homogeneous coordinates, points as columns: a point `p`
/// goes to the first three entries of the product of the matrix with
/// `(p, 1)`). A `#` starts a comment that runs to the end of its line.
///
/// \param is the stream
/// \returns the matrix
/// \throws Spectral_deformation_error (`IO_ERROR`) when the stream does not
///         hold exactly 16 finite numbers besides comments, or the last row
///         is not `0 0 0 1`.
inline Eigen::Matrix4d read_handle_transformation(std::istream& is)
{
  typedef Spectral_deformation_error Error;
  std::string content, line;
  while(std::getline(is, line))
  {
    const std::size_t hash = line.find('#');
    content += line.substr(0, hash) + "\n";
  }
  std::istringstream numbers(content);
  Eigen::Matrix4d transformation;
  for(int i = 0; i < 4; ++i)
    for(int j = 0; j < 4; ++j)
      if(!(numbers >> transformation(i, j)) || !std::isfinite(transformation(i, j)))
        throw Error(Error::IO_ERROR, "handle transformation: expected 16 finite numbers");
  std::string extra;
  if(numbers >> extra)
    throw Error(Error::IO_ERROR, "handle transformation: unexpected content '" + extra + "'");
  if((transformation.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-12)
    throw Error(Error::IO_ERROR, "handle transformation: the last row must be 0 0 0 1");
  return transformation;
}

/// \ingroup PkgSpectralSurfaceMeshDeformationIO
/// Opens and reads a `.sel` file; see the overload that reads a stream.
///
/// \param filename the name of the file
/// \param number_of_vertices the expected number of statuses
/// \returns one status per vertex
/// \throws Spectral_deformation_error (`IO_ERROR`) when the file cannot be
///         opened or its content is not valid.
inline std::vector<Deformation_vertex_status> read_selection(const std::string& filename,
                                                             std::size_t number_of_vertices)
{
  std::ifstream is(filename);
  if(!is)
    throw Spectral_deformation_error(Spectral_deformation_error::IO_ERROR,
                                     "cannot open the selection file " + filename);
  return read_selection(is, number_of_vertices);
}

/// \ingroup PkgSpectralSurfaceMeshDeformationIO
/// Opens and reads a `.def` file; see the overload that reads a stream.
///
/// \param filename the name of the file
/// \returns the matrix
/// \throws Spectral_deformation_error (`IO_ERROR`) when the file cannot be
///         opened or its content is not valid.
inline Eigen::Matrix4d read_handle_transformation(const std::string& filename)
{
  std::ifstream is(filename);
  if(!is)
    throw Spectral_deformation_error(Spectral_deformation_error::IO_ERROR,
                                     "cannot open the handle transformation file " + filename);
  return read_handle_transformation(is);
}

} // namespace IO
} // namespace CGAL

#endif // CGAL_SPECTRAL_DEFORMATION_IO_DEFORMATION_SELECTION_H
