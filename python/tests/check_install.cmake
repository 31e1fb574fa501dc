# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs the component "python" into PREFIX and imports the package from
# there, with a clean environment: the package installs into a prefix.
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --component python --prefix ${PREFIX}
                RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "cmake --install --component python failed")
endif()
if(IS_ABSOLUTE ${PYTHON_DIR})
  set(site ${PYTHON_DIR})
else()
  set(site ${PREFIX}/${PYTHON_DIR})
endif()
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${site} PYTHONNOUSERSITE=1
          ${PYTHON} -c "import ssmd, os; assert os.path.realpath(ssmd.__file__).startswith(os.path.realpath('${site}')), ssmd.__file__; print('imported', ssmd.__version__, 'from', os.path.dirname(ssmd.__file__))"
  WORKING_DIRECTORY ${PREFIX}
  RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "the installed package ssmd cannot be imported from ${site}")
endif()
