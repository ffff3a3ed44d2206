#pragma once
// The tet pass of the cached-quality sweeps (MultiBlock and Coloured): the
// radius ratio of every tet where its corners stand, into tet_q, which the
// old minimum of the accept test then reads (CachedOldQuality in
// node_update.hpp). tet_q has one entry per tet, in the order of m.tets.
#include <cuda_runtime.h>

#include <cstddef>

#include "kernels/cuda/sweep_state.cuh"
#include "kernels/node_update.hpp"

namespace tetsmooth::cuda {

// The radius ratios of tets t0, t0 + stride, ... (K of them, those below
// num_tets) where their corners stand now, into tet_q (the cache that
// CachedOldQuality reads). All K tets' nodes, then all their corners, are
// requested before any quality is computed, so that a thread has K tets'
// loads in flight at once.
template <int K, class Real, class Coords>
__device__ __forceinline__ void store_tet_qualities(const index_t* tets, std::size_t num_tets, std::size_t t0,
                                                    std::size_t stride, const Coords& xyz, Real* tet_q) {
  TetNodes tet[K];
  for (int k = 0; k < K; ++k)
    tet[k] = t0 + k * stride < num_tets ? tet_nodes(tets, t0 + k * stride) : TetNodes{{0, 0, 0, 0}};
  Vec3<Real> v[K][4];
  for (int k = 0; k < K; ++k)
    for (int c = 0; c < 4; ++c) v[k][c] = xyz.get(tet[k].v[c]);  // node 0 stands in past the end
  for (int k = 0; k < K; ++k)
    if (t0 + k * stride < num_tets) tet_q[t0 + k * stride] = radius_ratio(v[k][0], v[k][1], v[k][2], v[k][3]);
}

// Opens an adaptive MultiBlock sweep: every tet's quality before the sweep
// moves anything. Each tet is computed here once instead of once by each of
// its four corners, and the old half of the accept test becomes a read.
// A thread takes kTetsPerThread tets a block's width apart, so a warp's
// loads stay coalesced (two beat one and four). The paper's threads instead
// rewrite a moved node's tets' qualities "in memory" (its section 3.4),
// which would spare this pass; in Form B the stale minima that leaves let
// more moves through, invert more tets and take longer
// (multiblock_experiments.md, "The tet pass").
inline constexpr int kTetsPerThread = 2;

template <class Real, class Coords>
__global__ void tet_quality_kernel(const index_t* tets, index_t num_tets, Coords xyz, Real* tet_q,
                                   const SweepState* st) {
  if (st->done) return;
  const std::size_t t0 = static_cast<std::size_t>(blockIdx.x) * blockDim.x * kTetsPerThread + threadIdx.x;
  store_tet_qualities<kTetsPerThread>(tets, static_cast<std::size_t>(num_tets), t0, blockDim.x, xyz, tet_q);
}

}  // namespace tetsmooth::cuda
