# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# ssmd_check_version_header(HEADER VERSION): stops the configuration when the
# version macros of HEADER (CGAL_SSMD_VERSION_MAJOR, _MINOR, _PATCH and _STR)
# do not name VERSION, the version of project(). Code compiled against the
# headers sees the macros, find_package() sees the project's version: both
# must say the same.
function(ssmd_check_version_header header version)
  file(STRINGS "${header}" lines REGEX "^#define CGAL_SSMD_VERSION_(MAJOR|MINOR|PATCH|STR) ")
  foreach(part MAJOR MINOR PATCH)
    if(NOT lines MATCHES "#define CGAL_SSMD_VERSION_${part} +([0-9]+)")
      message(FATAL_ERROR "${header}: no CGAL_SSMD_VERSION_${part}")
    endif()
    set(${part} ${CMAKE_MATCH_1})
  endforeach()
  if(NOT lines MATCHES "#define CGAL_SSMD_VERSION_STR +\"([^\"]*)\"")
    message(FATAL_ERROR "${header}: no CGAL_SSMD_VERSION_STR")
  endif()
  set(string ${CMAKE_MATCH_1})
  if(NOT "${MAJOR}.${MINOR}.${PATCH}" STREQUAL "${version}" OR NOT string STREQUAL "${version}")
    message(FATAL_ERROR
      "The version header and project() disagree: ${header} says "
      "${MAJOR}.${MINOR}.${PATCH} (CGAL_SSMD_VERSION_STR \"${string}\"), project() says "
      "${version}. Change both (and CHANGELOG.md).")
  endif()
endfunction()
