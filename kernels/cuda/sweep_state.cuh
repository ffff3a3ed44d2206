#pragma once
// Device-side bookkeeping of the sweep loop, so convergence is decided on
// the GPU and the host only looks every few sweeps.
#include <cuda_runtime.h>

#include "kernels/cuda/lane_groups.cuh"

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
  // SweepProgress::quality's pass (min_mean_quality_kernel.cuh): the radius
  // ratios' sum, and their minimum as an ordered key.
  double quality_sum;
  unsigned long long quality_min_key;
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

// A part of one sweep's counters: accepted moves add up, the squared
// displacement keeps its largest (non-negative, so 0 is its identity). Both
// travel together, so one reduction carries them.
struct SweepStats {
  unsigned accepted;
  double disp2;
};

__device__ __forceinline__ SweepStats shfl_down(SweepStats s, int offset) {
  return {__shfl_down_sync(0xffffffffu, s.accepted, offset), __shfl_down_sync(0xffffffffu, s.disp2, offset)};
}

struct CombineSweepStats {
  __device__ SweepStats operator()(SweepStats a, SweepStats b) const {
    return {a.accepted + b.accepted, fmax(a.disp2, b.disp2)};
  }
};

__device__ __forceinline__ void post_sweep_stats(const SweepCounters& c, int sweep, SweepStats s) {
  if (s.accepted == 0) return;
  atomicAdd(&c.accepted[sweep], static_cast<unsigned long long>(s.accepted));
  atomicMax(&c.max_disp2_bits[sweep], static_cast<unsigned long long>(__double_as_longlong(s.disp2)));
}

// Warp-aggregated accumulation of one sweep's counters: for the coloured
// loop, whose warps reach this point once per sweep, and adaptive MultiBlock
// sweeps (see sweep_kernel). Every lane of the warp must call it.
__device__ __forceinline__ void add_sweep_stats(const SweepCounters& c, int sweep, unsigned accepted, double disp2) {
  const SweepStats s = warp_reduce_to_lane0(SweepStats{accepted, disp2}, CombineSweepStats{});
  if ((threadIdx.x & 31) == 0) post_sweep_stats(c, sweep, s);
}

// The same aggregated over the block, for kernels with a thread (or a few)
// per node, whose warps would otherwise all update the sweep's two counters:
// hundreds of thousands of warps per MultiBlock sweep of a 10M-node mesh,
// all at the same two addresses. Every thread of the block must call it,
// once per kernel.
__device__ __forceinline__ void add_sweep_stats_block(const SweepCounters& c, int sweep, unsigned accepted,
                                                      double disp2) {
  const SweepStats s =
      block_reduce_to_thread0(SweepStats{accepted, disp2}, CombineSweepStats{}, SweepStats{0u, 0.0});
  if (threadIdx.x == 0) post_sweep_stats(c, sweep, s);
}

}  // namespace tetsmooth::cuda
