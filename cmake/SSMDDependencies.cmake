# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Dependencies of the Spectral_surface_mesh_deformation package. Used both by
# the source tree and by the installed package configuration.
#
# The required dependencies are found here. The optional ones are found by
# the macros below, which the source tree calls for its own programs and the
# package configuration calls only for the components a consumer asks for:
# nothing optional is looked for, linked or defined unless asked.
include(CMakeFindDependencyMacro)

# CGAL 5.5 to 6.x. CGAL's version file accepts only the major version that is
# asked for, and sees only the lower end of a version range, so the range is
# checked here instead of in find_dependency().
find_dependency(CGAL)
if(CGAL_VERSION VERSION_LESS 5.5 OR NOT CGAL_VERSION VERSION_LESS 7)
  set(_ssmd_cgal_message
      "Spectral_surface_mesh_deformation needs CGAL 5.5 to 6.x, found CGAL ${CGAL_VERSION} in ${CGAL_DIR}")
  if(CMAKE_FIND_PACKAGE_NAME)
    # Inside find_package(): the package is not found, with the reason.
    set(${CMAKE_FIND_PACKAGE_NAME}_FOUND FALSE)
    set(${CMAKE_FIND_PACKAGE_NAME}_NOT_FOUND_MESSAGE "${_ssmd_cgal_message}")
    return()
  endif()
  message(FATAL_ERROR "${_ssmd_cgal_message}")
endif()
find_dependency(Eigen3 3.4 NO_MODULE)
find_dependency(Boost 1.66)
find_dependency(spectra 1.0)
find_dependency(Threads)

# CHOLMOD (SuiteSparse): sparse SPD factorizations use it instead of Eigen's
# SimplicialLDLT. Sets SSMD_HAS_CHOLMOD and, when found, the imported target
# SSMD::cholmod_libraries.
macro(ssmd_find_cholmod)
  find_path(SSMD_CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
  find_library(SSMD_CHOLMOD_LIBRARY cholmod)
  # SuiteSparse's allocator, which the package sets while CHOLMOD factors
  # when process-wide tuning is asked for.
  find_library(SSMD_SUITESPARSECONFIG_LIBRARY suitesparseconfig)
  set(SSMD_HAS_CHOLMOD OFF)
  if(SSMD_CHOLMOD_INCLUDE_DIR AND SSMD_CHOLMOD_LIBRARY AND SSMD_SUITESPARSECONFIG_LIBRARY)
    set(SSMD_HAS_CHOLMOD ON)
    if(NOT TARGET SSMD::cholmod_libraries)
      add_library(SSMD::cholmod_libraries INTERFACE IMPORTED)
      set_target_properties(SSMD::cholmod_libraries PROPERTIES
        INTERFACE_INCLUDE_DIRECTORIES "${SSMD_CHOLMOD_INCLUDE_DIR}"
        INTERFACE_LINK_LIBRARIES "${SSMD_CHOLMOD_LIBRARY};${SSMD_SUITESPARSECONFIG_LIBRARY}")
    endif()
  endif()
endmacro()

# OpenBLAS: the tall dense products of the block eigensolver call its dgemm
# (vector instructions chosen at run time) instead of Eigen's product, and
# CHOLMOD, which loads the system BLAS, gets the same optimized kernels when
# Debian's alternatives point to it. Sets SSMD_HAS_OPENBLAS and, when found,
# the imported target SSMD::openblas_library.
macro(ssmd_find_openblas)
  find_library(SSMD_OPENBLAS_LIBRARY NAMES openblas)
  set(SSMD_HAS_OPENBLAS OFF)
  if(SSMD_OPENBLAS_LIBRARY)
    set(SSMD_HAS_OPENBLAS ON)
    if(NOT TARGET SSMD::openblas_library)
      add_library(SSMD::openblas_library INTERFACE IMPORTED)
      set_target_properties(SSMD::openblas_library PROPERTIES
        INTERFACE_LINK_LIBRARIES "${SSMD_OPENBLAS_LIBRARY}")
    endif()
  endif()
endmacro()

# OpenMP: the per-iteration passes over the basis, the rotation fits and the
# eigensolver's dense products use every core (OMP_NUM_THREADS limits them).
# Sets SSMD_HAS_OPENMP; OpenMP::OpenMP_CXX is CMake's own target.
macro(ssmd_find_openmp)
  find_package(OpenMP QUIET COMPONENTS CXX)
  set(SSMD_HAS_OPENMP OFF)
  if(OpenMP_CXX_FOUND)
    set(SSMD_HAS_OPENMP ON)
  endif()
endmacro()
