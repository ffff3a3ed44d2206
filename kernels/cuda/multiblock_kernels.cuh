#pragma once
// The MultiBlock sweep (the paper's): a thread per node, many blocks, a
// launch per sweep; adaptive sweeps open with the tet pass
// (tet_quality_pass.cuh).
//
// A node's thread fetches its neighbours' positions kMultiBlockChunk at a
// time (row_sum in node_update.hpp). The centroid waits on memory (offsets,
// then indices, then positions, once per fetch), so the fetches are few and
// wide: in the A/B that chose this, ordinary smoothing of lattice-215 on an
// H100 took 0.38 / 0.59 ms a sweep in float / double, against 0.97 / 1.49
// with 8 lanes a node fetching one position each. The adaptive test then reads the star's old
// minimum from tet_q,
// kOldMinChunk entries at a time, and shares the warp's lanes among its 32
// nodes' stars for the new qualities, the old minimum's tet dealt first
// (warp_star_test.cuh).
//
// multiblock_experiments.md holds the measurements behind these choices,
// where the pass spends its time, and the variants that were tried and
// dropped. Read it before trying another.
#include <cuda_runtime.h>

#include <cstddef>
#include <cstdint>

#include "kernels/cuda/node_steps.cuh"
#include "kernels/cuda/sweep_state.cuh"
#include "kernels/cuda/warp_star_test.cuh"
#include "kernels/node_update.hpp"
#include "kernels/smooth_options.hpp"

namespace tetsmooth::cuda {

inline constexpr int kMultiBlockChunk = 8;
inline constexpr int kOldMinChunk = 4;

// A MultiBlock node, start to finish, on this thread (active) or lending
// the thread to its warp's other nodes (not active); the old qualities are
// read from tet_q. Every lane of the warp must call it.
template <class Real, bool kAdaptive, class Coords>
__device__ __forceinline__ NodeMove<Real> evaluate_node_multiblock(const MeshView& m, const Coords& xyz,
                                                                   const Real* tet_q, index_t i, bool active) {
  const Vec3<Real> p = active ? xyz.get(i) : Vec3<Real>{0, 0, 0};
  const Vec3<Real> target = centroid_group<Real, 1, kMultiBlockChunk>(m, xyz, i, 0, active);
  if (!kAdaptive) return decide_move<Real, false>(p, target, Real(1), true);
  const CachedOldQuality<Real> cached{tet_q};
  index_t lead = 0;
  const Real old_min = active ? star_old_min<Real, kOldMinChunk>(m, xyz, i, p, 0, 1, cached, &lead) : Real(2);
  return decide_move<Real, true>(p, target, old_min,
                                 warp_star_improves(m, xyz, i, p, target, old_min, lead, active, cached));
}

// One MultiBlock sweep over all N nodes, a thread per node.
// Adaptive smoothing takes a star's old minimum from tet_q, filled by
// tet_quality_kernel as the sweep began: the paper's test against the
// minimum "calculated in the previous iteration" (its section 3.4). For
// Form A that is exactly the quality at the positions read; in place (Form
// B) neighbours may have moved since, one more way in which the paper's
// in-place sweep reads a half-updated mesh.
// Form A leaves the counting to count_moves_kernel, after the repair.
template <class Real, bool kAdaptive, Form F, class Coords>
__global__ void sweep_kernel(MeshView m, Coords read, Coords write, index_t n, const std::uint8_t* movable,
                             const Real* tet_q, Real* old_min, std::uint8_t* moved, SweepState* st, SweepCounters c) {
  if (st->done) return;
  const std::size_t gid = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  const index_t i = static_cast<index_t>(gid);
  const bool active = gid < static_cast<std::size_t>(n) && movable[i];
  const NodeMove<Real> mv = evaluate_node_multiblock<Real, kAdaptive>(m, read, tet_q, active ? i : 0, active);
  unsigned accepted = 0;
  double disp2 = 0;
  if (active) accepted = apply_move<Real, F>(mv, read, write, i, old_min, moved, disp2);
  // Ordinary smoothing's short nodes leave the sweep's counters as the
  // bottleneck unless a block posts them once; the adaptive test's uneven
  // nodes would wait at the block's barrier instead, so they post by warp
  // (multiblock_experiments.md, "Counting a sweep's moves").
  if constexpr (F == Form::B) {
    if constexpr (kAdaptive)
      add_sweep_stats(c, st->sweep, accepted, disp2);
    else
      add_sweep_stats_block(c, st->sweep, accepted, disp2);
  }
}

}  // namespace tetsmooth::cuda
