#pragma once
// Device-side bookkeeping of the sweep loop, so convergence is decided on
// the GPU and the host only looks every few sweeps.
#include <cuda_runtime.h>

#include "kernels/node_update.hpp"

namespace tetsmooth::cuda {

struct SweepState {
  int sweep;   // sweeps completed
  int done;    // set once the stopping rule fires; every later launch returns at once
  int verdict; // SweepVerdict of the last sweep
  int pad;
  unsigned long long reverted;  // Form A moves undone by the conflict repair
  unsigned long long evaluated; // nodes evaluated, not skipped as settled (coloured loop only)
  double edge_sum;              // for the mean edge length
  unsigned long long edge_count;
  double tol_abs;               // tolerance x mean edge length, working units
};

// Per-sweep counters, indexed by the sweep number (0-based).
struct SweepCounters {
  unsigned long long* accepted;
  unsigned long long* max_disp2_bits;  // a non-negative double's bits order like the double
  int* repair_found;                   // kMaxRepairPasses flags of the current sweep
};

// Records the stopping rule's verdict on sweep s (0-based), just finished.
__device__ __forceinline__ void record_verdict(SweepState* st, int s, SweepVerdict v) {
  st->sweep = s + 1;
  st->verdict = static_cast<int>(v);
  st->done = v != SweepVerdict::Continue;
}

// Warp-aggregated accumulation of one sweep's accepted moves and largest
// squared displacement. Every lane of the warp must call it.
__device__ __forceinline__ void add_sweep_stats(const SweepCounters& c, int sweep, unsigned accepted, double disp2) {
  for (int offset = 16; offset > 0; offset >>= 1) {
    accepted += __shfl_down_sync(0xffffffffu, accepted, offset);
    disp2 = fmax(disp2, __shfl_down_sync(0xffffffffu, disp2, offset));
  }
  if ((threadIdx.x & 31) == 0 && accepted) {
    atomicAdd(&c.accepted[sweep], static_cast<unsigned long long>(accepted));
    atomicMax(&c.max_disp2_bits[sweep], static_cast<unsigned long long>(__double_as_longlong(disp2)));
  }
}

}  // namespace tetsmooth::cuda
