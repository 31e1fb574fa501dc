# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Checks the summary written by benchmark_deformation --summary FILE: the
# timing table of the target case with every peer and phase, and the table of
# the targets with a verdict on each.
# Usage: cmake -DFILE=<summary.md> -P check_summary.cmake
if(NOT EXISTS "${FILE}")
  message(FATAL_ERROR "no summary at ${FILE}")
endif()
file(READ "${FILE}" summary)
foreach(expected
    "CGAL ARAP, original" "CGAL ARAP, SRE" "spatial dual Laplacian"
    "spectral, exact, m = 100" "spectral, soft, m = 100"
    "per constraint set: `preprocess()`" "target change: `deform(10, 0)`" "per iteration"
    "detail transfer" "ARAP energy" "| target | required | measured | met |")
  string(FIND "${summary}" "${expected}" position)
  if(position EQUAL -1)
    message(FATAL_ERROR "the summary ${FILE} lacks \"${expected}\"")
  endif()
endforeach()
# Five targets, each with a verdict.
string(REGEX MATCHALL "\\| (yes|\\*\\*no\\*\\*) \\|" verdicts "${summary}")
list(LENGTH verdicts count)
if(NOT count EQUAL 4)
  message(FATAL_ERROR "the summary ${FILE} has ${count} target verdicts instead of 4")
endif()
