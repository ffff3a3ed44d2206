#pragma once
// The per-node steps of node_update.hpp as the device strategies run them:
// on one thread (SingleBlock), or split over the G lanes of a group that
// share a node (Coloured, and MultiBlock's centroid). Form A (Jacobi) reads
// `read` and writes `write`; Form B reads and writes `read` in place (racy
// under MultiBlock and SingleBlock, as in the paper).
#include <cuda_runtime.h>

#include <cstdint>

#include "kernels/cuda/lane_groups.cuh"
#include "kernels/node_update.hpp"
#include "kernels/smooth_options.hpp"

namespace tetsmooth::cuda {

// Applies an evaluated move; returns whether the node moved.
template <class Real, Form F, class Coords>
__device__ __forceinline__ bool apply_move(const NodeMove<Real>& mv, const Coords& read, const Coords& write, index_t i,
                                           Real* old_min, std::uint8_t* moved, double& disp2) {
  const bool take = takes_move(mv);
  if (F == Form::A) {
    write.set(i, take ? mv.target : read.get(i));
    moved[i] = take;
    if (take) old_min[i] = mv.old_min;
  } else if (take) {
    read.set(i, mv.target);
  }
  if (take) disp2 = static_cast<double>(mv.displacement2);
  return take;
}

// Evaluates node i on one thread and applies the move (SingleBlock).
template <class Real, bool kAdaptive, Form F, class Coords>
__device__ __forceinline__ bool smooth_node(const MeshView& m, const Coords& read, const Coords& write, index_t i,
                                            Real* old_min, std::uint8_t* moved, double& disp2) {
  return apply_move<Real, F>(evaluate_node<Real, kAdaptive>(m, read, i), read, write, i, old_min, moved, disp2);
}

// evaluate_node split over the G lanes of a group (lane = this thread's
// place in it), in two steps so that a caller can act between them. Every
// lane named in `mask` (lane_groups.cuh) must call them; lanes of an inactive
// group contribute nothing. All lanes of a group get the same result.

// The centroid of the neighbours in row [begin, end) of the neighbour CSR,
// for a caller that has the row's bounds already.
template <class Real, int G, int kChunk = 1, class Coords>
__device__ __forceinline__ Vec3<Real> row_centroid_group(const MeshView& m, const Coords& xyz, index_t begin,
                                                         index_t end, int lane, bool active,
                                                         unsigned mask = 0xffffffffu) {
  Vec3<Real> sum{0, 0, 0};
  if (active) sum = row_sum<Real, kChunk>(m, xyz, begin, end, lane, G);
  sum = Vec3<Real>{group_sum<G>(sum.x, mask), group_sum<G>(sum.y, mask), group_sum<G>(sum.z, mask)};
  const Real degree = active ? Real(end - begin) : Real(1);
  return (Real(1) / degree) * sum;
}

// The centroid of node i's neighbours.
template <class Real, int G, int kChunk = 1, class Coords>
__device__ __forceinline__ Vec3<Real> centroid_group(const MeshView& m, const Coords& xyz, index_t i, int lane,
                                                     bool active, unsigned mask = 0xffffffffu) {
  // One call for every lane: the group sums inside shuffle across groups.
  const index_t begin = active ? m.nbr_off[i] : 0, end = active ? m.nbr_off[i + 1] : 0;
  return row_centroid_group<Real, G, kChunk>(m, xyz, begin, end, lane, active, mask);
}

// The decision on moving node i from p to target; `old_quality` and
// `keep_new` as in star_improves (node_update.hpp). The group settles the
// star's old minimum first, then votes round by round on the new qualities,
// so a rejected move stops at the round of its first objecting tet.
template <class Real, bool kAdaptive, int G, class Coords, class OldQuality = FreshOldQuality,
          class KeepNew = IgnoreNewQuality>
__device__ __forceinline__ NodeMove<Real> judge_move_group(const MeshView& m, const Coords& xyz, index_t i,
                                                           Vec3<Real> p, Vec3<Real> target, int lane, bool active,
                                                           const OldQuality& old_quality = {},
                                                           unsigned mask = 0xffffffffu, KeepNew&& keep_new = {}) {
  if (!kAdaptive) return decide_move<Real, false>(p, target, Real(1), true);
  Real old_min = active ? star_old_min(m, xyz, i, p, lane, G, old_quality) : Real(2);
  old_min = group_min<G>(old_min, mask);
  // The votes name only this group's lanes: other groups of the warp may
  // have other star sizes, or be idle.
  const bool improves =
      active && star_improves(m, xyz, i, p, target, old_min, lane, G, old_quality, keep_new,
                              [](bool objects) { return group_any<G>(objects); });
  return decide_move<Real, true>(p, target, old_min, improves);
}

}  // namespace tetsmooth::cuda
