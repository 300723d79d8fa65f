# Runs PROGRAM with ARGUMENTS (a list) and passes when it exits with
# EXPECTED_EXIT_CODE and its standard error matches the regular expression
# EXPECTED_OUTPUT. Used as: cmake -D ... -P expect_failure.cmake
execute_process(COMMAND ${PROGRAM} ${ARGUMENTS}
  RESULT_VARIABLE exit_code
  OUTPUT_VARIABLE output
  ERROR_VARIABLE errors)
message(STATUS "exit code ${exit_code}; stderr:\n${errors}")
if(NOT exit_code STREQUAL EXPECTED_EXIT_CODE)
  message(FATAL_ERROR "expected exit code ${EXPECTED_EXIT_CODE}, got ${exit_code}")
endif()
if(NOT errors MATCHES "${EXPECTED_OUTPUT}")
  message(FATAL_ERROR "stderr does not match: ${EXPECTED_OUTPUT}")
endif()
if(NOT output STREQUAL "")
  message(FATAL_ERROR "expected nothing on stdout for a bad case, got:\n${output}")
endif()
