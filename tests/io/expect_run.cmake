# Runs PROGRAM with ARGUMENTS (a list) in a fresh OUTPUT_DIRECTORY and passes
# when it exits with 0 and each file named in EXPECTED_HEADERS (a list of
# FILE=HEADER items) starts with that header line.
# Used as: cmake -D ... -P expect_run.cmake
file(REMOVE_RECURSE ${OUTPUT_DIRECTORY})
execute_process(COMMAND ${PROGRAM} ${ARGUMENTS}
  RESULT_VARIABLE exit_code
  OUTPUT_VARIABLE output
  ERROR_VARIABLE errors)
message(STATUS "exit code ${exit_code}; stdout:\n${output}stderr:\n${errors}")
if(NOT exit_code STREQUAL "0")
  message(FATAL_ERROR "expected exit code 0, got ${exit_code}")
endif()
foreach(expected IN LISTS EXPECTED_HEADERS)
  string(FIND "${expected}" "=" split)
  string(SUBSTRING "${expected}" 0 ${split} name)
  math(EXPR header_start "${split} + 1")
  string(SUBSTRING "${expected}" ${header_start} -1 header)
  if(NOT EXISTS ${OUTPUT_DIRECTORY}/${name})
    message(FATAL_ERROR "${name} was not written")
  endif()
  file(STRINGS ${OUTPUT_DIRECTORY}/${name} lines LIMIT_COUNT 2)
  list(GET lines 0 first)
  if(NOT first STREQUAL header)
    message(FATAL_ERROR "${name} starts with\n  ${first}\nexpected\n  ${header}")
  endif()
  list(LENGTH lines count)
  if(count LESS 2)
    message(FATAL_ERROR "${name} has no rows")
  endif()
endforeach()
