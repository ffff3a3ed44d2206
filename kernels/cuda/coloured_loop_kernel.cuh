#pragma once
// Coloured Form B with the whole sweep loop in one cooperative launch: grid
// barriers separate the colour classes instead of kernel launches, and after
// a sweep's last colour every block applies the stopping rule to the same
// finished counters, so the host neither launches per colour nor looks at
// the device between sweeps. The order of updates is the CPU's coloured
// order: within a sweep, colour by colour.
//
// Lanes per node, G: where a class is small (~1/12 of the nodes) next to
// what the device holds at once, a node's latency sets the pace, so a whole
// warp takes each node and its ~25 tets are one or two per lane instead of a
// few one after another. Where classes are many times the resident threads,
// throughput does, and 8 lanes waste fewer (coloured_loop_launch.cuh chooses).
//
// Two savings that leave every decision as it was:
//  * tet_q caches each tet's radius ratio at the current coordinates. A
//    node that moves rewrites the entries of its incident tets; nodes of one
//    colour share no tet, so those writes never collide. A star's current
//    minimum is then read, and only the quality at the target is computed
//    (and kept for the update). An entry is what a fresh computation would
//    give: the same function of the same coordinates. (Computing the old
//    qualities afresh instead, with no cache to read or write, lost on an
//    H200: smoothing lattice-215 took 424 ms against 343 in float, 1017
//    against 855 in double, and 109k in double 2.31 against 2.13.)
//  * changed[i] says whether node i or a neighbour has moved since i's last
//    turn. A node's decision depends only on its own position and its
//    neighbours' (the corners of its star are exactly its neighbours). Its
//    turn one sweep earlier either evaluated it and it did not move, or
//    skipped it, which by the same argument stands for an evaluation that
//    would not have moved it; so when nothing in the neighbourhood moved
//    since that turn, the same inputs would give the same rejection, and the
//    node is skipped again (skip_settled; a test compares runs with and
//    without it bit for bit). A node that moves flags itself and its
//    neighbours; at its turn a node that does not move clears its flag. Its
//    neighbours have other colours, so a flag is never written by its owner
//    and by a mover in the same step, and movers that flag one neighbour
//    write the same value. A settled node costs its flag and the bounds of
//    its rows (and, with fewer lanes than a warp, its position), read beside
//    the flag so that an active node does not wait on it; neither its rows,
//    its star nor their positions are read. With a warp per node, settled
//    nodes are dropped where a step's openings are staged.
// And some that change no value read, for a node's chain of loads: with a
// warp per node, a step's openings are read for the whole block at once
// (staged_openings.cuh) and each lane's first tet before the centroid
// (star_head.cuh); with fewer lanes, an adaptive node's star is requested
// before the centroid (star_prefetch.cuh).
#include <cooperative_groups.h>

#include "kernels/cuda/node_steps.cuh"
#include "kernels/cuda/star_head.cuh"
#include "kernels/cuda/staged_openings.cuh"
#include "kernels/cuda/star_prefetch.cuh"
#include "kernels/cuda/sweep_state.cuh"
#include "kernels/cuda/tet_quality_pass.cuh"

namespace tetsmooth::cuda {

inline constexpr int kLatencyLanes = 32, kThroughputLanes = 8;
inline constexpr int kMiddleLanes = 16;  // only when asked for (SmoothOptions::coloured_lanes)

// Colour classes on the device: class c lists nodes[off[c] .. off[c+1]).
struct ColourClassesView {
  const index_t* off;  // count + 1
  const index_t* nodes;
  int count;
};

// One block per multiprocessor, as large as the registers allow: more warps
// take more of a class at once (the 109k model's largest class takes 8
// rounds of the resident warps at 16 warps per SM, 5 at 24), and one block
// per SM keeps the grid barrier that ends each colour to one arrival per SM
// (three blocks of 256 threads give three times as many, and lost 0.16 ms
// on the 109k model to one block of 768 threads with the same warps). The
// launch bounds cap the registers: double gets 96 (it wants more: 20-68
// bytes spill), float 64 (8 and 16 lanes spill 20-28 bytes, and are still
// faster than with 72). Smoothing the 109k model on an H100, ms, with nodes
// dealt to warps in a fixed stride:
//   double: 256 x 2 blocks 3.10, 256 x 3 (80 registers) 2.89, 768 x 1 2.73,
//           640 x 1 2.71, 896 x 1 (72 registers, 136 bytes spill) 3.03;
//   float:  256 x 3 1.87, 640 x 1 1.88, 768 x 1 1.74, 896 x 1 1.69;
// and with the shares taken from a counter (below): double 640 x 1 2.38,
// 768 x 1 2.41; float 896 x 1 1.49, 1024 x 1 1.45. Later, in float, 896 x 1
// against 1024 x 1: 109k 1.36 against 1.33, lattice-215 445 against 417;
// with the star prefetch, on an H200, 768 x 1 against 1024 x 1: lattice-215
// 427 against 343, 109k 1.37 against 1.34. With staged openings and the
// star's head, 109k in double on an H100: 512 x 1 (104 registers, no
// spill) 1.89, 576 x 1 1.85, 640 x 1 1.82, 768 x 1 1.96, 896 x 1 2.04,
// 1024 x 1 (64 registers, 96 bytes spill) 2.28.
template <class Real>
inline constexpr int kColouredBlock = sizeof(Real) == 4 ? 1024 : 640;

// A few values in registers, indexed by a run-time round number: the
// unrolled comparisons keep the array out of local memory.
template <class Real, int K>
struct KeptQualities {
  Real v[K];
  __device__ __forceinline__ void put(int r, Real q) {
#pragma unroll
    for (int s = 0; s < K; ++s)
      if (s == r) v[s] = q;
  }
  __device__ __forceinline__ Real get(int r) const {
    Real q = 0;
#pragma unroll
    for (int s = 0; s < K; ++s)
      if (s == r) q = v[s];
    return q;
  }
};

template <class Real, bool kAdaptive, int G, class Coords>
__global__ void __launch_bounds__(kColouredBlock<Real>, 1)
    coloured_loop_kernel(MeshView m, Coords xyz, ColourClassesView cls, Real* tet_q, std::uint8_t* changed, index_t n,
                         index_t num_tets, SweepState* st, SweepCounters c, int max_iterations, bool skip_settled) {
  namespace cg = cooperative_groups;
  cg::grid_group grid = cg::this_grid();
  const unsigned long long tid = grid.thread_rank(), threads = grid.size();
  if (kAdaptive)
    for (unsigned long long t = tid; t < static_cast<unsigned long long>(num_tets); t += threads)
      store_tet_qualities<1>(m.tets, static_cast<std::size_t>(num_tets), t, 0, xyz, tet_q);
  // Every node is evaluated in the first sweep.
  for (unsigned long long i = tid; i < static_cast<unsigned long long>(n); i += threads) changed[i] = 1;
  // Nodes of the block's share of a class handed out so far, one counter for
  // even colour steps and one for odd (see below).
  __shared__ unsigned taken[2];
  if (threadIdx.x < 2) taken[threadIdx.x] = 0;
  grid.sync();

  // Whole warps step through a class together (blockDim is a multiple of
  // 32 and of G), so a group's shuffles find all of its lanes.
  const int lane = static_cast<int>(tid % G);
  const int group_in_warp = static_cast<int>(threadIdx.x % 32) / G;
  const unsigned mask = group_mask<G>();
  const CachedOldQuality<Real> cached{tet_q};
  constexpr int kKept = 32 / G;
  // Ordinary Laplacian reads no star.
  constexpr int kPrefetchRounds = kAdaptive && G < kLatencyLanes ? kKept : 0;
  // A warp per node: a node's latency sets the pace, so a step's openings
  // are read at once (staged_openings.cuh) and the lane's first tet of the
  // star before the centroid (star_head.cuh). On an H100, smoothing the 109k
  // model took 1.94 ms against 2.18 in double with both, 2.08 with the head
  // alone; 1.13 against 1.20 in float. With fewer lanes, where a class is
  // many times what the device holds at once, staging lost: lattice-215 took
  // 1038 ms against 845 in double and 547 against 347 in float with 8 lanes,
  // and 109k 2.23 against 1.93 in double with 16.
  constexpr bool kStaged = G == kLatencyLanes;
  constexpr bool kHead = kAdaptive && G == kLatencyLanes;
  __shared__ StagedOpenings<kStaged ? kColouredBlock<Real> : 1> staged;
  if (kStaged) staged.clear();
  // Where the time goes, colour by colour: the grid's first thread stamps
  // each barrier. Its last stamp waits in shared memory, not in a register
  // that the whole loop would carry (double is short of them).
  __shared__ unsigned long long colour_start;
  const auto stamp_colour = [&](int col) {
    if (tid != 0 || c.colour_ns == nullptr) return;
    const unsigned long long now = global_timer_ns();
    // An atomic add whose result goes unused: nothing waits on a load of the
    // total, which would hold up block 0's next step.
    if (col >= 0) atomicAdd(&c.colour_ns[col], now - colour_start);
    colour_start = now;
  };
  stamp_colour(-1);
  unsigned parity = 0;  // of the colour step (staged: of the chunk), counted over all sweeps
  for (int s = 0; s < max_iterations; ++s) {
    unsigned accepted = 0;
    unsigned evaluated = 0;
    double disp2 = 0;
    // A node's work once its opening is known: the group's lanes all call it
    // (a group past the class's end with o.in_class false).
    const auto visit = [&](const NodeOpening& o) {
      const index_t i = o.i;
      const Vec3<Real> p = o.in_class ? xyz.get(i) : Vec3<Real>{0, 0, 0};
      // Settled: nothing in the neighbourhood moved since this node's turn
      // in the previous sweep; see the top of the file.
      const bool active = o.in_class && (o.flagged || !skip_settled);
      StarHead<Real> head;
      if constexpr (kHead)
        head = read_star_head(m, static_cast<const Real*>(tet_q), o.star_begin, o.star_end, lane, active);
      // With fewer lanes than a warp, a star takes rounds, each waiting on
      // the memory the last one fetched; the prefetch starts them all now
      // (star_prefetch.cuh). On an H100, smoothing lattice-215 (8 lanes)
      // took 372 ms against 417 in float, 900 against 1015 in double; with
      // a warp per node, one round, 109k in float took 1.40 against 1.33,
      // and with the fetch issued before the centroid instead of after it
      // the whole 109k run took 3.27-3.30 ms against 3.22-3.25 in double,
      // 2.36-2.38 against 2.23-2.27 in float.
      StarPrefetch<kPrefetchRounds> star;
      if (kPrefetchRounds > 0) star.read_entries(m, o.star_begin, o.star_end, lane, G, active);
      const Vec3<Real> target = row_centroid_group<Real, G>(m, xyz, o.row_begin, o.row_end, lane, active, mask);
      if (kPrefetchRounds > 0) star.fetch(m, tet_q);
      // The lane's new qualities, kept for the cache update: every round
      // up to kKept (a star of up to 32 tets needs no recomputation).
      KeptQualities<Real, kKept> kept;
      int rounds = 0;
      const auto keep = [&](index_t, Real q) { kept.put(rounds++, q); };
      NodeMove<Real> mv;
      if constexpr (kHead)
        mv = judge_move_with_head<Real, G>(m, xyz, cached, i, p, target, head, lane, active, keep);
      else
        mv = judge_move_group<Real, kAdaptive, G>(m, xyz, i, p, target, lane, active, cached, mask, keep);
      const bool moves = active && takes_move(mv);
      if (moves) {
        // An accepted move computed every round. tet_quality_with never
        // reads node i's stored position, so lane 0 may overwrite it
        // meanwhile.
        if (kAdaptive) {
          int r = 0;
          for (index_t e = o.star_begin + lane; e < o.star_end; e += G, ++r)
            tet_q[m.inc[e]] = r < kKept ? kept.get(r) : tet_quality_with(m, xyz, m.inc[e], i, mv.target);
        }
        for (index_t e = o.row_begin + lane; e < o.row_end; e += G) changed[m.nbr[e]] = 1;
        if (lane == 0) {
          xyz.set(i, mv.target);
          ++accepted;
          disp2 = fmax(disp2, static_cast<double>(mv.displacement2));
        }
      }
      // The group's lanes have all read the flag: the votes and sums above
      // exchanged values that depend on it.
      if (o.in_class && lane == 0 && o.flagged != moves) changed[i] = moves;
      evaluated += active && lane == 0;
    };
    for (int col = 0; col < cls.count; ++col) {
      const long long begin = cls.off[col], end = cls.off[col + 1];
      // The class is cut into shares of a node per group (a warp's worth);
      // block b owns shares b, b + blocks, b + 2 blocks, ..., so every block
      // gets as many and all of them walk the class front to back together
      // (neighbouring nodes, and their data, are taken at about the same
      // time). The block's warps take its shares in order from a counter in
      // shared memory (staged, its kept openings): a warp that drew quick
      // nodes (settled, or rejected at once) takes more, and the class ends
      // with the warps about even. (Each warp requesting into L1 the opening
      // of the share a block's worth of warps ahead, instead of staging,
      // lost: 109k 2.20 ms against 2.18 in double, lattice-215 906 against
      // 870. A counter for the whole grid did the same as the block's, but
      // its one address in L2 queued the claims; contiguous slices per block
      // lost the lattice its cache.) The next step's counter is cleared now:
      // its last user, the step before this one, is behind the barrier.
      // (Shares of 32 nodes, whose flags a warp reads first so that its
      // groups visit only the flagged ones and none idles on a settled node,
      // lost on an H100: lattice-215 467 ms against 374 in float, 983
      // against 904 in double. More stars are then in flight per SM; that
      // they overflow L1 is our reading, not profiled.)
      if constexpr (kStaged) {
        const long long first = begin + blockIdx.x;
        const long long count = first < end ? (end - first + gridDim.x - 1) / gridDim.x : 0;
        for (long long chunk = 0; chunk < count; chunk += kColouredBlock<Real>) {
          const unsigned kept = staged.template stage<kAdaptive>(m, changed, cls.nodes, first, gridDim.x, chunk,
                                                                 count, skip_settled, parity);
          for (;;) {
            const unsigned r = staged.claim(32 / G, parity);
            if (r >= kept) break;  // the same for the whole warp
            visit(staged.opening(r + group_in_warp, kept));
          }
          parity ^= 1u;
        }
      } else {
        if (threadIdx.x == 0) taken[parity ^ 1u] = 0;
        for (;;) {
          const long long share = blockIdx.x + static_cast<long long>(gridDim.x) * warp_claim(&taken[parity], 1u);
          const long long start = begin + share * (32 / G);
          if (start >= end) break;  // the same for the whole warp
          const long long k = start + group_in_warp;
          const bool in_class = k < end;
          // The node's flag and row bounds, read up front and side by side:
          // an active node's row does not wait on its flag (on an H100,
          // smoothing 109k in double took 2.21 ms against 2.29 with the
          // bounds read after the flag, lattice-215 1002 against 1046).
          // Every lane of the group reads the same flag.
          visit(read_opening<kAdaptive>(m, changed, in_class ? cls.nodes[k] : 0, in_class));
        }
        parity ^= 1u;
      }
      // (Instead of these barriers, each node once waited for its own
      // neighbours of earlier colours alone: every node published the colour
      // step it had finished with a release store, and read what others
      // write past L1. The same results, but slower on an H100: the 109k run
      // took 3.48 ms against 3.30 in double and 2.53 against 2.33 in float,
      // lattice-215 800 against 402 in float. A node's own chain of loads,
      // not the barrier, sets a small class's pace, and the release and the
      // neighbours' ready words lengthen it.)
      // A grid barrier costs about 1 us, yet on small classes 5.6 us pass
      // between the last block finishing and the next step starting:
      // coloured_loop_experiments.md has the stamps, and what was tried.
      if (col + 1 < cls.count) {
        grid.sync();  // the next colour reads these moves
        stamp_colour(col);
      }
    }
    add_sweep_stats(c, s, accepted, disp2);
    warp_atomic_add(&st->evaluated, evaluated);
    grid.sync();
    if (cls.count > 0) stamp_colour(cls.count - 1);
    // The counters of sweep s are final now; every block reads them (past
    // L1) and reaches the same verdict.
    const double max_disp = sqrt(__longlong_as_double(static_cast<long long>(__ldcg(&c.max_disp2_bits[s]))));
    const SweepVerdict v = sweep_verdict(s + 1, static_cast<long long>(__ldcg(&c.accepted[s])), max_disp,
                                         __ldcg(&st->tol_abs), max_iterations);
    if (tid == 0) record_verdict(st, s, v);
    if (v != SweepVerdict::Continue) break;
  }
}

}  // namespace tetsmooth::cuda
