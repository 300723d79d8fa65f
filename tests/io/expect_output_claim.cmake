# dem_run into a directory that holds an earlier run's output
# (docs/RELIABILITY.md, "An earlier run's output is never cut"): the second
# fresh run is refused with exit code 2 and the files named, the tables
# left as they were; --overwrite removes the run's files (not the user's
# own) and runs afresh. Used as: cmake -D PROGRAM=... -D CASE=... -D
# OUTPUT_DIRECTORY=... -P expect_output_claim.cmake
file(REMOVE_RECURSE ${OUTPUT_DIRECTORY})
file(MAKE_DIRECTORY ${OUTPUT_DIRECTORY})
file(WRITE ${OUTPUT_DIRECTORY}/notes.txt "the user's own file\n")

function(run_dem expected_code)
  execute_process(COMMAND ${PROGRAM} ${CASE} --out ${OUTPUT_DIRECTORY} --quiet --threads 1 ${ARGN}
    RESULT_VARIABLE code ERROR_VARIABLE errors)
  if(NOT code STREQUAL expected_code)
    message(FATAL_ERROR "dem_run ${ARGN}: expected exit code ${expected_code}, got ${code}:\n${errors}")
  endif()
  set(errors "${errors}" PARENT_SCOPE)
endfunction()

run_dem(0)
file(READ ${OUTPUT_DIRECTORY}/assembly.csv first_table)

run_dem(2)
message(STATUS "refused: ${errors}")
if(NOT errors MATCHES "holds the output of an earlier run \\(assembly.csv, [^\n]*\\), which a new run would cut: continue it with --resume, replace it with --overwrite")
  message(FATAL_ERROR "the refusal does not name the earlier run's files and the ways on:\n${errors}")
endif()
file(READ ${OUTPUT_DIRECTORY}/assembly.csv after_refusal)
if(NOT after_refusal STREQUAL first_table)
  message(FATAL_ERROR "the refused run changed assembly.csv")
endif()

file(WRITE ${OUTPUT_DIRECTORY}/assembly.csv "a table cut short\n")
run_dem(0 --overwrite)
file(READ ${OUTPUT_DIRECTORY}/assembly.csv overwritten)
if(NOT overwritten STREQUAL first_table)
  message(FATAL_ERROR "--overwrite did not run afresh into assembly.csv")
endif()
if(NOT EXISTS ${OUTPUT_DIRECTORY}/notes.txt)
  message(FATAL_ERROR "--overwrite removed a file that no run wrote (notes.txt)")
endif()

run_dem(2 --resume --overwrite)
