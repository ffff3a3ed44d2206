#pragma once
// Host side of the coloured loop (coloured_loop_kernel.cuh): picks the lanes
// per node and starts the one cooperative launch.
#include <algorithm>
#include <cstddef>

#include "kernels/cuda/coloured_loop_kernel.cuh"
#include "kernels/cuda/cuda_check.hpp"
#include "kernels/cuda/resident_blocks.cuh"
#include "kernels/cuda/sweep_loop.hpp"

namespace tetsmooth::cuda {

// A warp per node while the largest class takes at most this many rounds of
// the resident warps, else kThroughputLanes: the 109k model has 6 in double
// and 4 in float, a 10M-node lattice hundreds. (On an H100 the whole 109k
// run took 3.33 ms in double and 2.44 in float with 16 lanes, 3.89 and 2.72
// with 8, against 3.30 and 2.33 with 32 in an earlier run that day.)
inline constexpr std::size_t kMaxLatencyWaves = 16;

// As many blocks as fit on the device at once (a grid barrier needs them all
// resident), fewer when the largest class needs fewer or the options cap them.
template <class Real, bool kAdaptive, int G, class Coords>
void launch_coloured_loop_with(const SweepLoopArgs& a, const SmoothOptions& o, Coords xyz) {
  const auto kernel = coloured_loop_kernel<Real, kAdaptive, G, Coords>;
  constexpr int block = kColouredBlock<Real>;
  const std::size_t wanted = static_cast<std::size_t>(std::max<index_t>(a.largest_class, 1)) * G;
  std::size_t blocks = std::min<std::size_t>((wanted + block - 1) / block, resident_blocks(kernel, block));
  if (o.coloured_blocks > 0) blocks = std::min<std::size_t>(blocks, static_cast<std::size_t>(o.coloured_blocks));
  MeshView view = a.view;
  ColourClassesView cls{a.class_off, a.class_nodes, a.num_colours};
  Real* tet_q = static_cast<Real*>(a.tet_quality);
  std::uint8_t* changed = a.changed;
  index_t n = a.n, num_tets = a.num_tets;
  SweepState* st = a.state;
  SweepCounters counters = a.counters;
  int max_iterations = o.max_iterations;
  bool skip = o.skip_settled;
  void* params[] = {&view, &xyz, &cls, &tet_q, &changed, &n, &num_tets, &st, &counters, &max_iterations, &skip};
  CUDA_CHECK(cudaLaunchCooperativeKernel(reinterpret_cast<const void*>(kernel), dim3(static_cast<unsigned>(blocks)),
                                         dim3(block), params, 0, a.stream));
  CUDA_CHECK_LAUNCH();
}

// Starts the coloured loop on `xyz` (in place); returns the lanes per node.
template <class Real, bool kAdaptive, class Coords>
int launch_coloured_loop(const SweepLoopArgs& a, const SmoothOptions& o, Coords xyz) {
  int lanes = o.coloured_lanes;
  if (lanes == 0) {
    constexpr int block = kColouredBlock<Real>;
    const std::size_t resident =
        std::size_t{resident_blocks(coloured_loop_kernel<Real, kAdaptive, kLatencyLanes, Coords>, block)} * block;
    const std::size_t largest = static_cast<std::size_t>(std::max<index_t>(a.largest_class, 1));
    lanes = largest * kLatencyLanes <= kMaxLatencyWaves * resident ? kLatencyLanes : kThroughputLanes;
  }
  if (lanes == kLatencyLanes)
    launch_coloured_loop_with<Real, kAdaptive, kLatencyLanes>(a, o, xyz);
  else if (lanes == kMiddleLanes)
    launch_coloured_loop_with<Real, kAdaptive, kMiddleLanes>(a, o, xyz);
  else
    launch_coloured_loop_with<Real, kAdaptive, kThroughputLanes>(a, o, xyz);
  return lanes;
}

}  // namespace tetsmooth::cuda
