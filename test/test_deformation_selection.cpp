// Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#include <CGAL/Spectral_deformation/IO/deformation_selection.h>

#include <catch2/catch.hpp>

#include <sstream>

using CGAL::Spectral_deformation_error;

TEST_CASE(".sel files: statuses, comments, and refusals", "[io]")
{
  std::istringstream good("# per vertex status\n# 4 vertices\n0\n1\n2 1\n");
  const auto status = CGAL::IO::read_selection(good, 4);
  REQUIRE(status.size() == 4);
  CHECK(status[0] == CGAL::IO::FIXED_VERTEX);
  CHECK(status[1] == CGAL::IO::ROI_VERTEX);
  CHECK(status[2] == CGAL::IO::HANDLE_VERTEX);
  CHECK(status[3] == CGAL::IO::ROI_VERTEX);

  for(const char* bad : {"0\n1\n", "0\n1\n2\n1\n0\n", "0\n3\n1\n1\n", "0\nx\n1\n1\n", "0 1 2 -1\n",
                         "\x01\x02garbage", ""})
  {
    std::istringstream is(bad);
    INFO("input: " << bad);
    CHECK_THROWS_AS(CGAL::IO::read_selection(is, 4), Spectral_deformation_error);
  }
  CHECK_THROWS_AS(CGAL::IO::read_selection(std::string("/nonexistent/file.sel"), 4),
                  Spectral_deformation_error);
}

TEST_CASE(".def files: a 4x4 affine matrix, and refusals", "[io]")
{
  std::istringstream good("# 4x4 handle transformation matrix\n"
                          "0 -1 0 1\n1 0 0 2\n0 0 1 3\n0 0 0 1\n");
  const Eigen::Matrix4d T = CGAL::IO::read_handle_transformation(good);
  CHECK(T(0, 1) == -1.0);
  CHECK(T(2, 3) == 3.0);
  for(const char* bad : {"1 0 0 0\n0 1 0 0\n0 0 1 0\n", "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 2",
                         "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1 7", "1 0 0 nan 0 1 0 0 0 0 1 0 0 0 0 1",
                         "a b c"})
  {
    std::istringstream is(bad);
    INFO("input: " << bad);
    CHECK_THROWS_AS(CGAL::IO::read_handle_transformation(is), Spectral_deformation_error);
  }
}
