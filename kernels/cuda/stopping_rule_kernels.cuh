#pragma once
// The CPU's stopping rule on the device (sweep_verdict in node_update.hpp):
// the tolerance from the mean edge length, and the verdict on each sweep,
// without a host round trip.
#include <cuda_runtime.h>

#include <cstddef>

#include "kernels/cuda/lane_groups.cuh"
#include "kernels/cuda/sweep_state.cuh"
#include "kernels/node_update.hpp"

namespace tetsmooth::cuda {

// Applies the stopping rule to the sweep just finished (one thread) and
// clears the repair flags for the next sweep. `static`: each translation
// unit that launches it keeps its own copy.
static __global__ void verdict_kernel(SweepState* st, SweepCounters c, int max_iterations) {
  if (st->done) return;
  const int s = st->sweep;
  const double disp = sqrt(__longlong_as_double(static_cast<long long>(c.max_disp2_bits[s])));
  const SweepVerdict v =
      sweep_verdict(s + 1, static_cast<long long>(c.accepted[s]), disp, st->tol_abs, max_iterations);
  record_verdict(st, s, v);
  for (int k = 0; k < kMaxRepairPasses; ++k) c.repair_found[k] = 0;
}

// tol_abs = tolerance x mean edge length, once the edge sums are in.
static __global__ void set_tolerance_kernel(SweepState* st, double tolerance) {
  st->tol_abs = st->edge_count ? tolerance * st->edge_sum / static_cast<double>(st->edge_count) : 0.0;
}

// Sum of unique edge lengths (row i, neighbour j > i) in working units.
// kEdgeLanes threads share a row, so a row's loads are not one after
// another; a grid of at most kEdgeMaxBlocks strides over the rows, and each
// block adds its total with one atomic (per warp, the 109k model's sums
// queued 27k atomics on two addresses: 70 us on an H100).
inline constexpr int kEdgeLanes = 8;
inline constexpr unsigned kEdgeMaxBlocks = 2048;

template <class Real, class Coords>
__global__ void edge_length_kernel(MeshView m, Coords xyz, index_t n, SweepState* st) {
  const std::size_t slots = static_cast<std::size_t>(n) * kEdgeLanes;
  double sum = 0;
  unsigned count = 0;
  for (std::size_t g = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x; g < slots;
       g += static_cast<std::size_t>(gridDim.x) * blockDim.x) {
    const index_t i = static_cast<index_t>(g / kEdgeLanes);
    for (index_t k = m.nbr_off[i] + static_cast<index_t>(g % kEdgeLanes); k < m.nbr_off[i + 1]; k += kEdgeLanes) {
      const index_t j = m.nbr[k];
      if (j <= i) continue;
      sum += sqrt(static_cast<double>(norm2(xyz.get(j) - xyz.get(i))));
      ++count;
    }
  }
  block_atomic_add(&st->edge_sum, sum);
  block_atomic_add(&st->edge_count, count);
}

}  // namespace tetsmooth::cuda
