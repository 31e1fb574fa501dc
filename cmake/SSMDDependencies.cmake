# Dependencies of the Spectral_surface_mesh_deformation package. Used both by
# the source tree and by the installed package configuration.
include(CMakeFindDependencyMacro)

find_dependency(CGAL 5.5)
find_dependency(Eigen3 3.4 NO_MODULE)
find_dependency(Boost 1.66)
find_dependency(spectra 1.0)
find_dependency(Threads)

# CHOLMOD is optional: when found, sparse SPD factorizations use it instead of
# Eigen's SimplicialLDLT.
set(SSMD_HAS_CHOLMOD OFF)
if(NOT DEFINED SSMD_USE_CHOLMOD OR SSMD_USE_CHOLMOD)
  find_path(SSMD_CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
  find_library(SSMD_CHOLMOD_LIBRARY cholmod)
  # SuiteSparse's allocator, which the package sets while CHOLMOD factors.
  find_library(SSMD_SUITESPARSECONFIG_LIBRARY suitesparseconfig)
  if(SSMD_CHOLMOD_INCLUDE_DIR AND SSMD_CHOLMOD_LIBRARY AND SSMD_SUITESPARSECONFIG_LIBRARY)
    set(SSMD_HAS_CHOLMOD ON)
    if(NOT TARGET SSMD::cholmod)
      add_library(SSMD::cholmod INTERFACE IMPORTED)
      set_target_properties(SSMD::cholmod PROPERTIES
        INTERFACE_INCLUDE_DIRECTORIES "${SSMD_CHOLMOD_INCLUDE_DIR}"
        INTERFACE_LINK_LIBRARIES "${SSMD_CHOLMOD_LIBRARY};${SSMD_SUITESPARSECONFIG_LIBRARY}")
    endif()
  endif()
endif()

# OpenBLAS is optional: when found, the tall dense products of the block
# eigensolver call its dgemm (vector instructions chosen at run time) instead
# of Eigen's product, and CHOLMOD, which loads the system BLAS, gets the same
# optimized kernels when Debian's alternatives point to it.
set(SSMD_HAS_OPENBLAS OFF)
if(NOT DEFINED SSMD_USE_OPENBLAS OR SSMD_USE_OPENBLAS)
  find_library(SSMD_OPENBLAS_LIBRARY NAMES openblas)
  if(SSMD_OPENBLAS_LIBRARY)
    set(SSMD_HAS_OPENBLAS ON)
    if(NOT TARGET SSMD::openblas)
      add_library(SSMD::openblas INTERFACE IMPORTED)
      set_target_properties(SSMD::openblas PROPERTIES
        INTERFACE_LINK_LIBRARIES "${SSMD_OPENBLAS_LIBRARY}")
    endif()
  endif()
endif()

# OpenMP is optional: when found, the per-iteration passes over the basis and
# Eigen's own dense products use every core (OMP_NUM_THREADS limits them).
set(SSMD_HAS_OPENMP OFF)
if(NOT DEFINED SSMD_USE_OPENMP OR SSMD_USE_OPENMP)
  find_package(OpenMP QUIET COMPONENTS CXX)
  if(OpenMP_CXX_FOUND)
    set(SSMD_HAS_OPENMP ON)
  endif()
endif()
