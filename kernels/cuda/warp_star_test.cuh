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
// a round splits the 32 slots evenly among the nodes with tets left, so the
// warp computes up to 32 tets a round for as long as its nodes have that
// many left. (Nsight Compute on an H100, one lattice-215 sweep's node pass
// in float: 2.11 G warp instructions with 4 lanes per node, 1.44 G with
// warp-shared stars and the lead below, 1.37 G with this deal; the A/B is
// in multiblock_experiments.md.)
//
// A replay of the deal on the host (lattice-48, 30 Jacobi sweeps with the
// CPU's decisions) takes from 18.2 rounds a warp in the first sweep to 13.5
// in the last, where 17.7 and 12.9 would do if every slot of every round
// computed a tet that the decision needed: the rounds are the stars' own
// work, not the deal's waste. Giving each lane two tets a round halves the
// rounds, but the registers for a second tet's corners cost more occupancy
// than the halved deal and shuffles save; so does keeping a slot's deal
// across rounds in which no node drops out. Two tets a slot computed one
// after the other save no instructions either: the coarser slots compute
// tets that the deal would have spared (the A/Bs are in
// multiblock_experiments.md).
//
// Nor can a cleverer choice of tets cut that work by much. In a host replay
// of the CPU's rule (lattice-30, 100 Jacobi sweeps without the repair, 45% of
// the moves accepted), the order dealt here computes 13.4 tets a node. An
// accepted move needs its whole star (24 tets), a rejected one at least the
// tet that objects, so no order does better than 11.4; dealing by ascending
// old quality gives 11.9. Skipping the tets that provably beat the old
// minimum saves less: moving one corner by d changes the volume, the area and
// the circumradius so that the new ratio is at least q (1-e)^2 / (1+e)^3,
// with e = d / (the tet's smallest altitude); some tets come close to it (a
// random search found a drop of 99.95% of the bound's). The lattice's moves
// are a large part of its tets' altitudes, so only 3.9% of the computed tets
// pass it (13.4 to 12.9 a node). Neither was built.
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

// A round's even share of 32 slots among n busy nodes: floor(32 / n) for
// 0 < n <= 32, one load from constant memory instead of a division.
struct ShareTable {
  unsigned char of_busy[33];
};
constexpr ShareTable make_share_table() {
  ShareTable t{};
  for (int n = 1; n <= 32; ++n) t.of_busy[n] = static_cast<unsigned char>(32 / n);
  return t;
}
static __constant__ ShareTable kShare = make_share_table();

// One round of the deal, as this lane sees it: its node's slots, and the
// node whose tet the lane computes.
struct RoundDeal {
  int take = 0;       // slots of this lane's node (0 when none of its tets is pending)
  unsigned mine = 0;  // those slots as a lane mask
  int owner = 0;      // the lane whose node slot `lane` serves
  int offset = 0;     // the slot's place among its owner's; dealt when below the owner's take
};

// Deals a round's 32 slots: 32 / (busy nodes) to each, one more to each of
// the first `extra` by rank (the node's order among the busy lanes), in rank
// order; a node with fewer tets pending leaves the rest of its slots idle.
// Each busy node marks its first slot in one OR over the warp, so a slot's
// owner is the node of the last mark at or below it (slot 0 is always
// marked): a count of bits, where a closed form of the rank took two
// approximate divisions and a branch (100 float MultiBlock sweeps of
// lattice-215 on an H200: 229.2 ms against 233.8, and 464.0 against 476.2
// in double). `ranked` is the warp's own 32-byte row of shared memory, from
// which a slot reads its owner's lane. Every lane of the warp must call it,
// with busy = the ballot of pending > 0.
__device__ __forceinline__ RoundDeal deal_round(unsigned busy, int pending, int lane, unsigned char* ranked) {
  RoundDeal d;
  const int nodes = __popc(busy);
  const int share = kShare.of_busy[nodes], extra = 32 - share * nodes;
  const int rank = __popc(busy & ((1u << lane) - 1u));
  const int first = share * rank + min(rank, extra);  // this node's first slot
  d.take = pending > 0 ? min(pending, share + (rank < extra ? 1 : 0)) : 0;
  d.mine = d.take == 0 ? 0u : d.take >= 32 ? kFullWarp : ((1u << d.take) - 1u) << first;
  __syncwarp();  // the row's readers of the round before are done
  if (pending > 0) ranked[rank] = static_cast<unsigned char>(lane);
  const unsigned marks = __reduce_or_sync(kFullWarp, pending > 0 ? 1u << first : 0u);
  const unsigned upto = marks & (kFullWarp >> (31 - lane));
  __syncwarp();
  d.owner = ranked[__popc(upto) - 1];
  d.offset = lane - (31 - __clz(upto));
  return d;
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
  // The lanes of this warp's busy nodes by rank (their order among the busy
  // lanes), rewritten each round: a row per warp, for blocks of up to 1024.
  __shared__ unsigned char lane_of_rank[32][32];
  unsigned char* const ranked = lane_of_rank[threadIdx.x >> 5];
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
    const RoundDeal deal = deal_round(busy, pending, lane, ranked);
    const int owner = deal.owner, offset = deal.offset;
    const bool dealt = offset < lane_value(deal.take, owner);
    const index_t owner_i = lane_value(i, owner), owner_begin = lane_value(begin, owner);
    const index_t owner_lead = lane_value(lead, owner);
    const Real owner_min = lane_value(old_min, owner);
    const Vec3<Real> owner_p = lane_value(p, owner), owner_target = lane_value(target, owner);
    const int owner_pos = lane_value(done, owner) + offset;
    bool objects = false;
    if (dealt) {
      Real q_new;
      const index_t t = m.inc[dealt_entry(owner_begin, owner_lead, owner_pos)];
      objects = tet_objects(m, xyz, t, owner_i, owner_p, owner_target, owner_min, old_quality, q_new);
    }
    if (__ballot_sync(kFullWarp, objects) & deal.mine) alive = false;
    done += deal.take;
  }
  return alive;
}

}  // namespace tetsmooth::cuda
