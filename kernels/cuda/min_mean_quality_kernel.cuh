#pragma once
// The mesh's smallest and mean radius ratio where the working coordinates
// stand: SweepProgress::quality of a CUDA run, for a progress display (the
// CPU's is min_mean_quality in mesh/quality_summary.hpp). Computed in the
// run's precision; float's coordinates sit in the unit box, which the ratio,
// free of scale, does not see.
#include <cuda_runtime.h>

#include <cmath>
#include <cstddef>

#include "kernels/cuda/lane_groups.cuh"
#include "kernels/cuda/sweep_state.cuh"
#include "kernels/node_update.hpp"
#include "kernels/ordered_double.hpp"

namespace tetsmooth::cuda {

inline constexpr unsigned kQualityMaxBlocks = 2048;

// Adds every tet's radius ratio into st->quality_sum and lowers
// st->quality_min_key to the smallest's ordered_key, one atomic of each a
// block; the caller clears both first (the key to all ones, above every
// double). A grid of any size strides over the tets. The minimum starts at
// 1, as summarize_quality's does.
template <class Real, class Coords>
__global__ void min_mean_quality_kernel(const index_t* tets, index_t num_tets, Coords xyz, SweepState* st) {
  double lowest = 1, sum = 0;
  for (std::size_t t = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
       t < static_cast<std::size_t>(num_tets); t += static_cast<std::size_t>(gridDim.x) * blockDim.x) {
    const TetNodes tet = tet_nodes(tets, t);
    const double q = radius_ratio(xyz.get(tet.v[0]), xyz.get(tet.v[1]), xyz.get(tet.v[2]), xyz.get(tet.v[3]));
    lowest = fmin(lowest, q);
    sum += q;
  }
  lowest = block_reduce_to_thread0(lowest, [](double a, double b) { return fmin(a, b); }, 1.0);
  if (threadIdx.x == 0) atomicMin(&st->quality_min_key, static_cast<unsigned long long>(ordered_key(lowest)));
  __syncthreads();  // block_reduce_to_thread0's rule before another reduction in the block
  block_atomic_add(&st->quality_sum, sum);
}

}  // namespace tetsmooth::cuda
