#pragma once
// The adaptive test's second pass (star_improves in node_update.hpp) for the
// 32 nodes of a warp at once, one node per lane, with the nodes' tets dealt
// out round by round to all 32 lanes.
//
// Why: with a fixed group of lanes per node, a warp runs until its slowest
// node is done, and an accepted node computes its whole star at the target
// while rejected ones stop at their first objecting tet. With about a third
// of the moves accepted (lattice-215), a warp of 8 nodes nearly always holds
// an accepted one, and the lanes of its rejected nodes idle meanwhile. Here
// a round gives each node with tets left at least one slot and fills the
// remaining slots with further tets of the nodes in lane order, so the warp
// computes 32 tets a round for as long as 32 are left. (Nsight Compute on
// an H100, one lattice-215 sweep's node pass in float: 2.11 G warp
// instructions with 4 lanes per node, 1.44 G with this and the lead below;
// the A/B is in sweep_kernels.cuh.)
//
// The decision is star_improves's: a node's move is accepted when none of
// its tets objects (tet_objects), whatever the order they were taken in.
// Tets of a node already rejected are not dealt again; tets dealt in the
// same round as the objecting one are computed anyway (the slots would idle
// otherwise).
#include <cuda_runtime.h>

#include "kernels/cuda/lane_groups.cuh"
#include "kernels/node_update.hpp"

namespace tetsmooth::cuda {

// The incidence entry at place `pos` of a star [begin, end) dealt with
// entry `lead` first and the others in order.
__device__ __forceinline__ index_t dealt_entry(index_t begin, index_t lead, int pos) {
  if (pos == 0) return lead;
  const index_t e = begin + pos - 1;
  return e >= lead ? e + 1 : e;
}

// Whether node i's move from p to target passes the test, for this lane's
// node; `evaluated` is false for a lane without a node to judge (it still
// lends its lane to the others). `old_min` and `old_quality` as in
// star_improves; `lead` is the incidence entry dealt first, the star's
// old minimum (star_old_min's `at`): the tet that must improve for the
// move to pass, and so a likely first objection. Every lane of the warp
// must call it.
template <class Real, class Coords, class OldQuality>
__device__ bool warp_star_improves(const MeshView& m, const Coords& xyz, index_t i, Vec3<Real> p, Vec3<Real> target,
                                   Real old_min, index_t lead, bool evaluated, const OldQuality& old_quality) {
  const int lane = static_cast<int>(threadIdx.x & 31u);
  const index_t begin = evaluated ? m.inc_off[i] : 0;
  const int count = evaluated ? static_cast<int>(m.inc_off[i + 1] - begin) : 0;
  int done = 0;  // places dealt so far
  // As star_improves ends: no tets, or an old minimum never beaten, rejects.
  bool alive = evaluated && count > 0 && old_min < Real(2);
  for (;;) {
    const int pending = alive ? count - done : 0;
    const unsigned busy = __ballot_sync(kFullWarp, pending > 0);
    if (busy == 0) break;
    // This round's slots: an even share first (at least one each), then
    // whatever is left to the nodes in lane order. The share is 32 / busy
    // nodes rounded down to a power of 2: a shift, where the integer
    // division took a 19-instruction call every round (the decision does
    // not depend on the share).
    const int even = 32 >> (32 - __clz(__popc(busy) - 1));
    const int base = min(pending, even), rest = pending - base;
    const int base_incl = warp_inclusive_sum(base), rest_incl = warp_inclusive_sum(rest);
    const int left = 32 - lane_value(base_incl, 31);
    const int first = (base_incl - base) + min(left, rest_incl - rest);  // this node's first slot
    const int take = base + max(0, min(left - (rest_incl - rest), rest));
    const int slots = first + take;  // past this node's last slot
    // Slot `lane` belongs to the first node whose slots reach past it.
    int owner = 0;
    for (int step = 16; step > 0; step >>= 1)
      if (lane_value(slots, owner + step - 1) <= lane) owner += step;
    const bool dealt = lane < lane_value(slots, 31);
    const index_t owner_i = lane_value(i, owner), owner_begin = lane_value(begin, owner);
    const index_t owner_lead = lane_value(lead, owner);
    const int owner_pos = lane_value(done, owner) + lane - lane_value(first, owner);
    const Real owner_min = lane_value(old_min, owner);
    const Vec3<Real> owner_p = lane_value(p, owner), owner_target = lane_value(target, owner);
    bool objects = false;
    if (dealt) {
      Real q_new;
      const index_t t = m.inc[dealt_entry(owner_begin, owner_lead, owner_pos)];
      objects = tet_objects(m, xyz, t, owner_i, owner_p, owner_target, owner_min, old_quality, q_new);
    }
    const unsigned objections = __ballot_sync(kFullWarp, objects);
    const unsigned mine = take == 0 ? 0u : take >= 32 ? kFullWarp : ((1u << take) - 1u) << first;
    if (objections & mine) alive = false;
    done += take;
  }
  return alive;
}

}  // namespace tetsmooth::cuda
