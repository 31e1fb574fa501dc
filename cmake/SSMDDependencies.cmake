# Dependencies of the Spectral_surface_mesh_deformation package. Used both by
# the source tree and by the installed package configuration.
include(CMakeFindDependencyMacro)

find_dependency(CGAL 5.5)
find_dependency(Eigen3 3.4 NO_MODULE)
find_dependency(Boost 1.66)
find_dependency(spectra 1.0)

# CHOLMOD is optional: when found, sparse SPD factorizations use it instead of
# Eigen's SimplicialLDLT.
set(SSMD_HAS_CHOLMOD OFF)
if(NOT DEFINED SSMD_USE_CHOLMOD OR SSMD_USE_CHOLMOD)
  find_path(SSMD_CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
  find_library(SSMD_CHOLMOD_LIBRARY cholmod)
  if(SSMD_CHOLMOD_INCLUDE_DIR AND SSMD_CHOLMOD_LIBRARY)
    set(SSMD_HAS_CHOLMOD ON)
    if(NOT TARGET SSMD::cholmod)
      add_library(SSMD::cholmod INTERFACE IMPORTED)
      set_target_properties(SSMD::cholmod PROPERTIES
        INTERFACE_INCLUDE_DIRECTORIES "${SSMD_CHOLMOD_INCLUDE_DIR}"
        INTERFACE_LINK_LIBRARIES "${SSMD_CHOLMOD_LIBRARY}")
    endif()
  endif()
endif()
