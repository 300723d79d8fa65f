# CMakePresets.json names the four configurations the README shows
# (release, debug, asan, tsan) for configure, build and test, and CMake
# reads it without error. Run with -DSOURCE_DIR=<the source tree>.
foreach(kind configure build test)
  execute_process(COMMAND ${CMAKE_COMMAND} --list-presets=${kind} WORKING_DIRECTORY ${SOURCE_DIR}
                  RESULT_VARIABLE status OUTPUT_VARIABLE listed ERROR_VARIABLE errors)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "CMakePresets.json: cmake --list-presets=${kind} failed: ${errors}")
  endif()
  foreach(preset release debug asan tsan)
    if(NOT listed MATCHES "\"${preset}\"")
      message(FATAL_ERROR "CMakePresets.json has no ${kind} preset named ${preset}:\n${listed}")
    endif()
  endforeach()
endforeach()
message(STATUS "CMakePresets.json: release, debug, asan and tsan presets for configure, build and test")
