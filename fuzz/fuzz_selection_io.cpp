// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Fuzzes the readers of the .sel/.def deformation format. Input: one byte
// (with the next one) giving the expected number of vertices of the .sel
// reader, then the file content, read by both readers.
//
// Property: each reader either throws Spectral_deformation_error (IO_ERROR)
// or returns what its documentation promises (exactly that many statuses in
// {0, 1, 2}; 16 finite numbers with the last row 0 0 0 1).
#include "fuzz_common.h"

#include <CGAL/Spectral_deformation/IO/deformation_selection.h>

#include <sstream>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  using ssmd_fuzz::require;
  using ssmd_fuzz::violation;
  if(size < 2)
    return 0;
  const std::size_t number_of_vertices = (std::size_t(data[0]) | (std::size_t(data[1]) << 8)) % 1024;
  const std::string content(reinterpret_cast<const char*>(data) + 2, size - 2);

  {
    std::istringstream is(content);
    try
    {
      const auto status = CGAL::IO::read_selection(is, number_of_vertices);
      require(status.size() == number_of_vertices, "read_selection: wrong number of statuses");
      for(auto s : status)
        require(s == CGAL::IO::FIXED_VERTEX || s == CGAL::IO::ROI_VERTEX || s == CGAL::IO::HANDLE_VERTEX,
                "read_selection: status out of range");
    }
    catch(const CGAL::Spectral_deformation_error& e)
    {
      require(e.code() == CGAL::Spectral_deformation_error::IO_ERROR, "read_selection: not IO_ERROR");
      require(std::string(e.what()).size() > 0, "read_selection: empty message");
    }
    catch(...)
    {
      violation("read_selection: undocumented exception");
    }
  }
  {
    std::istringstream is(content);
    try
    {
      const Eigen::Matrix4d T = CGAL::IO::read_handle_transformation(is);
      require(T.allFinite(), "read_handle_transformation: non-finite entry");
      require((T.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() <= 1e-12,
              "read_handle_transformation: last row is not 0 0 0 1");
    }
    catch(const CGAL::Spectral_deformation_error& e)
    {
      require(e.code() == CGAL::Spectral_deformation_error::IO_ERROR,
              "read_handle_transformation: not IO_ERROR");
    }
    catch(...)
    {
      violation("read_handle_transformation: undocumented exception");
    }
  }
  return 0;
}
