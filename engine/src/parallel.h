// OpenMP parallel loops with an explicit thread count (no process-wide
// setting) and a size threshold below which threading costs more than it saves.
#pragma once

#define DEM_PRAGMA(x) _Pragma(#x)
#define DEM_PARALLEL_FOR(threads, n) \
  DEM_PRAGMA(omp parallel for schedule(static) num_threads(threads) if ((threads) > 1 && (n) > 2048))
#define DEM_PARALLEL_FOR_MAX(threads, n, var) \
  DEM_PRAGMA(omp parallel for schedule(static) num_threads(threads) if ((threads) > 1 && (n) > 2048) reduction(max : var))
