#pragma once
// What a `threads` argument of the library asks OpenMP for: 0 means all
// cores (OpenMP's default team, omp_get_max_threads(), which
// OMP_NUM_THREADS sets), 1 or less one thread, the serial reference.
// For sources built with OpenMP (every library target links it).
#include <algorithm>

#include <omp.h>

namespace tetsmooth {

inline int team_size(int threads) { return threads == 0 ? omp_get_max_threads() : std::max(threads, 1); }

}  // namespace tetsmooth
