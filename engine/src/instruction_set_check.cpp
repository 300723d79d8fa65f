// The check, before anything else of a program runs, that the processor has
// the instructions the build was compiled for (DEM_ARCH,
// cmake/instruction_set.cmake). A build for AVX-512 started on a processor
// without it would otherwise die of SIGILL somewhere in its first loop,
// with nothing to say why. This file alone is compiled for the baseline
// x86-64, so that the check itself runs anywhere; the linker is told to
// keep it in every program that links the engine.
#include <cstdio>
#include <cstdlib>

#ifndef DEM_ARCH_LEVEL
#error "DEM_ARCH_LEVEL: the x86-64 level the build targets (cmake/instruction_set.cmake)"
#endif

namespace {

bool has_level(int level) {
#if defined(__x86_64__) || defined(_M_X64)
  __builtin_cpu_init();
  // (x86-64-v3's features that both GCC and Clang can name here.)
  if (level >= 3 &&
      !(__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") && __builtin_cpu_supports("bmi2"))) {
    return false;
  }
  if (level >= 4 &&
      !(__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") && __builtin_cpu_supports("avx512bw") &&
        __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512cd"))) {
    return false;
  }
#else
  (void)level;
#endif
  return true;
}

}  // namespace

// Priority 101: before the C++ initialisers of the program's own files,
// which are compiled for the build's level.
extern "C" [[gnu::constructor(101)]] void dem_check_instruction_set() {
  if (has_level(DEM_ARCH_LEVEL)) return;
  std::fprintf(stderr,
               "dem: this build was compiled for x86-64-v%d (%s), which this processor does not support; "
               "rebuild with -DDEM_ARCH=auto on this machine, or -DDEM_ARCH=x86-64-v3 for any processor "
               "since about 2015 (docs/INSTALL.md)\n",
               DEM_ARCH_LEVEL, DEM_ARCH_LEVEL >= 4 ? "AVX-512" : "AVX2 and FMA");
  std::_Exit(70);  // EX_SOFTWARE
}
