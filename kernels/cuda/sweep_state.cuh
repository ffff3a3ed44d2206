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
  // Coloured loop only (else null): nanoseconds spent on each colour class,
  // summed over the sweeps, one entry per colour. A colour's step runs from
  // the grid barrier that ends the previous one to the barrier that ends it,
  // read by one thread on the device's global timer (so barrier waits count
  // with the colour that caused them).
  unsigned long long* colour_ns;
};

// The device's global nanosecond timer (the same clock on every SM).
__device__ __forceinline__ unsigned long long global_timer_ns() {
  unsigned long long t;
  asm volatile("mov.u64 %0, %%globaltimer;" : "=l"(t));
  return t;
}

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
