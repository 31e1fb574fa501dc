# Copyright (c) 2026 The Spectral Surface Mesh Deformation authors.
# SPDX-License-Identifier: GPL-3.0-or-later
# Builds TARGET in BINARY_DIR and passes when the build fails with every
# message of the list EXPECTED (separated by '|') in its output: a build that
# succeeds, or fails for another reason, is a failure of the test.
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY_DIR} --target ${TARGET}
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(result EQUAL 0)
  message(FATAL_ERROR "${TARGET} compiled; it must not")
endif()
string(REPLACE "|" ";" expected "${EXPECTED}")
foreach(message IN LISTS expected)
  string(FIND "${output}" "${message}" position)
  if(position EQUAL -1)
    message(FATAL_ERROR "${TARGET} did not fail with \"${message}\":\n${output}")
  endif()
endforeach()
message(STATUS "${TARGET} fails to compile with the expected messages")
