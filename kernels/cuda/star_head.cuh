#pragma once
// The adaptive test for a warp per node (the coloured loop,
// coloured_loop_kernel.cuh) with each lane's first tet read before the
// centroid: its incidence entry, its cached quality and its four nodes.
//
// Why: with a warp per node, the lane's first entry is the whole star for
// most nodes (up to 32 tets), and a node's latency sets a small colour
// class's pace. Read after the centroid, as judge_move_group does, the
// entry, then the tet's nodes and quality, then its corners wait one after
// another behind the centroid's own chain; read here they are on their way
// beside the neighbours' positions, and only the corners are left. The
// test is the same (node_update.hpp's pieces over the same entries in the
// same order): the first entry of each lane as tet_objects_at takes it, the
// rest as star_old_min_in and no_tet_objects_in do.
//
// Tried on the 109k model in double on an H100, none kept: the tet's corner
// positions read early too (2.66 ms of smoothing against 2.08: the registers
// spill); the tets of a lane's later entries requested into L1 during the old
// minimum's pass (1.94 against 1.94); the neighbour and incidence rows read
// with an evict-first hint, so that they leave L2 to the positions, tets and
// qualities that neighbours read again (1.82 against 1.82, and lattice-215
// 846 against 830 ms in double). A dependent load that hits L2 takes about
// 280 cycles on an H100 and one from DRAM about 660 (a pointer chase over
// 4-32 MB and over 400 MB).
#include "kernels/cuda/lane_groups.cuh"
#include "kernels/node_update.hpp"

namespace tetsmooth::cuda {

// Node i's incidence row and what the lane has read of its first entry,
// begin + lane (t = -1 where the lane has none, or the node is not active).
template <class Real>
struct StarHead {
  index_t begin = 0, end = 0;
  index_t t = -1;
  Real q = Real(2);  // t's cached quality; 2, no radius ratio, where t = -1
  TetNodes nodes{};
};

template <class Real>
__device__ __forceinline__ StarHead<Real> read_star_head(const MeshView& m, const Real* tet_q, index_t begin,
                                                         index_t end, int lane, bool active) {
  StarHead<Real> h;
  h.begin = begin;
  h.end = end;
  if (active && begin + lane < end) {
    h.t = m.inc[begin + lane];
    h.q = tet_q[h.t];
    h.nodes = tet_nodes(m.tets, static_cast<std::size_t>(h.t));
  }
  return h;
}

// judge_move_group (node_steps.cuh) for a warp per node (G = 32) whose lanes
// have read their first entry into `h`, old qualities from the cache.
template <class Real, int G, class Coords, class KeepNew>
__device__ __forceinline__ NodeMove<Real> judge_move_with_head(const MeshView& m, const Coords& xyz,
                                                               const CachedOldQuality<Real>& cached, index_t i,
                                                               Vec3<Real> p, Vec3<Real> target,
                                                               const StarHead<Real>& h, int lane, bool active,
                                                               KeepNew&& keep_new) {
  static_assert(G == 32, "a lane's first entry is a round of the test only with a warp per node");
  const auto any = [](bool objects) { return group_any<G>(objects); };
  Real old_min = Real(2);
  if (active) {
    const Real rest = star_old_min_in(m, xyz, i, p, h.begin + G, h.end, lane, G, cached);
    old_min = lowers_min(rest, h.q) ? rest : h.q;
  }
  old_min = group_min<G>(old_min);
  bool improves = false;
  if (active) {
    bool objects = false;
    if (h.t >= 0) {
      Real q_new;
      objects = tet_objects_at(m, xyz, h.t, h.nodes, i, p, target, old_min, cached, q_new);
      keep_new(h.begin + lane, q_new);
    }
    improves = !any(objects) &&
               no_tet_objects_in(m, xyz, i, p, target, old_min, h.begin + G, h.end, lane, G, cached, keep_new, any) &&
               star_can_improve(h.begin, h.end, old_min);
  }
  return decide_move<Real, true>(p, target, old_min, improves);
}

}  // namespace tetsmooth::cuda
