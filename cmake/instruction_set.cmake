# The instruction set the whole build targets: one for every target, since
# inline functions from shared headers must not be compiled for two.
#
# DEM_ARCH=auto (the default) picks the widest level the building machine
# runs: x86-64-v4 (AVX-512) where it has it, else x86-64-v3 (AVX2, FMA:
# x86-64 processors since about 2015). The force pass's law loops run eight
# contacts to a vector instruction at v4 against four at v3; on the plate
# benchmark that is about 1.19x (docs/PERFORMANCE.md). A build meant for
# other machines (a container image, a package, a cluster whose nodes
# differ from its login node) names its level, e.g. -DDEM_ARCH=x86-64-v3;
# a program started on a processor that lacks its level says so and exits
# (engine/src/instruction_set_check.cpp) instead of dying of SIGILL.
# Any other value is passed to -march as is; empty keeps the compiler's
# baseline.
#
# Sets DEM_ARCH_FLAGS (the options every target and every program built
# against the installed libraries compiles with) and DEM_ARCH_LEVEL (the
# x86-64 level the check at start-up asks of the processor: 1-4).
set(DEM_ARCH "auto" CACHE STRING "Instruction set (-march) for the whole build: auto, x86-64-v3, x86-64-v4, native, ...; empty for the compiler default")

function(dem_host_runs_x86_64_v4 result)
  set(probe "${CMAKE_BINARY_DIR}/CMakeFiles/dem_probe_v4.cpp")
  # x86-64-v4's AVX-512 subsets (GCC's own name for the level is not one
  # Clang knows).
  file(WRITE "${probe}" [=[
int main() {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                 __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
                 __builtin_cpu_supports("avx512cd")
             ? 0
             : 1;
}
]=])
  try_run(run_result compile_result "${CMAKE_BINARY_DIR}/CMakeFiles/dem_probe_v4" "${probe}"
          COMPILE_DEFINITIONS -march=x86-64-v4)
  if(compile_result AND run_result EQUAL 0)
    set(${result} TRUE PARENT_SCOPE)
  else()
    set(${result} FALSE PARENT_SCOPE)
  endif()
endfunction()

set(DEM_ARCH_FLAGS "")
set(DEM_ARCH_LEVEL 1)
set(dem_march "${DEM_ARCH}")
if(dem_march STREQUAL "auto")
  set(dem_march "x86-64-v3")
  if(NOT CMAKE_CROSSCOMPILING AND CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
    dem_host_runs_x86_64_v4(dem_v4)
    if(dem_v4)
      set(dem_march "x86-64-v4")
    endif()
  endif()
endif()
if(dem_march)
  include(CheckCXXCompilerFlag)
  check_cxx_compiler_flag("-march=${dem_march}" DEM_ARCH_SUPPORTED_${dem_march})
  if(DEM_ARCH_SUPPORTED_${dem_march})
    list(APPEND DEM_ARCH_FLAGS "-march=${dem_march}")
    if(dem_march STREQUAL "x86-64-v4")
      # The generic tuning keeps vectors at 256 bits; the law loops gain from
      # all 512 (1.19x against 1.17x on the plate benchmark).
      list(APPEND DEM_ARCH_FLAGS "-mprefer-vector-width=512")
      set(DEM_ARCH_LEVEL 4)
    elseif(dem_march STREQUAL "x86-64-v3")
      set(DEM_ARCH_LEVEL 3)
    endif()
  else()
    message(WARNING "DEM_ARCH=${dem_march} is not supported by this compiler: building for its default")
  endif()
endif()
add_compile_options(${DEM_ARCH_FLAGS})
message(STATUS "dem: instruction set ${dem_march} (DEM_ARCH=${DEM_ARCH}): ${DEM_ARCH_FLAGS}")
