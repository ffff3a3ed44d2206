#pragma once
// The smoothing kernels. Every strategy runs the per-node math of
// node_update.hpp: SingleBlock through evaluate_node on one thread, the
// others through the same steps split over lanes: centroid_group and
// judge_move_group below for a group of lanes that share a node (Coloured),
// warp_star_improves for a warp whose lanes share their nodes' stars
// (MultiBlock).
//   MultiBlock: a thread per node, a launch per sweep (the paper's).
//   Coloured:   one colour class at a time, all sweeps in one cooperative
//               launch (coloured_loop_kernel.cuh); nodes of one colour share
//               no tet, so in-place updates are race-free.
//   SingleBlock: one block of 1024 threads runs every sweep in one launch,
//               __syncthreads() between sweeps.
// Form A (Jacobi) reads `read` and writes `write`; Form B reads and writes
// `read` in place (racy under MultiBlock and SingleBlock, as in the paper).
#include <cuda_runtime.h>

#include "kernels/cuda/lane_groups.cuh"
#include "kernels/cuda/sweep_state.cuh"
#include "kernels/cuda/warp_star_test.cuh"
#include "kernels/node_update.hpp"
#include "kernels/smooth_options.hpp"

namespace tetsmooth::cuda {

inline constexpr int kSingleBlockThreads = 1024;

// A MultiBlock sweep gives each node a thread, which fetches its
// neighbours' positions kMultiBlockChunk at a time (row_sum in
// node_update.hpp). The centroid waits on memory: offsets, then neighbour
// indices, then positions, once per fetch. For ordinary smoothing, where the
// centroid is the whole job, one thread per node fetching 8 at a time took
// 0.38 ms a sweep in float and 0.59 in double (H100, lattice-215), against
// 0.97 and 1.49 with 8 lanes fetching one at a time; 2 lanes x 4 gave 0.41
// and 0.57, 2 x 8 0.46 and 0.74 (more registers), 1 x 16 0.45 and 0.67,
// 4 x 4 0.63 and 0.98.
// Adaptive smoothing then reads the star's old minimum from tet_q,
// kOldMinChunk entries at a time, and shares the warp's lanes among its 32
// nodes' stars for the new qualities, the old minimum's tet dealt first
// (warp_star_test.cuh). 100 sweeps of lattice-215 on an H100, ms, float /
// double, medians of 3:
//   4 lanes per node, each fetching 4 positions at a time        325.5 / 648.9
//   warp-shared stars, tets dealt in star order (a)              366.9 / 595.9
//     with each tet's four nodes in one 16-byte load (tet_nodes) 343.6 / 578.4
//     and the old minimum's tet first                            291.8 / 520.4
//     and old qualities 4 at a time (b; 8 at a time 285.3 / 515.7) 284.9 / 514.7
//     and the even share a power of 2 (c)                       271.7 / 500.7
//     slots dealt by rank in closed form, no scans (d)           267.4 / 489.3
// (a) in a run where the first line took 324.5 / 645.8; (b) in a run where
// the line above took 290.0 / 522.4; (c) against 282.0 / 510.5 in the same
// run, and 280.3 / 504.4 against 284.6 / 511.2 in another; (d) against
// 278.6 / 502.6, and 271.4 / 488.3 against 278.7 / 503.4 in another, where
// the deal's owners' values read from shared memory instead of shuffled
// took 279.3 / 506.4, and the leads judged by their own lanes before any
// deal 267.2 / 484.8, against 266.6 / 488.1 (both with two tets a thread in
// the tet pass). The closed form leaves a node's slots idle past its last
// tet; the slots of the deal before, with no slot idle, computed without
// shuffles (prefix sums from six ballots, the owners from the set bits of
// the nodes' first slots) took 271.0 / 495.0 and 271.4 / 495.2 against
// 257.4 / 487.2 and 259.1 / 487.3.
// Nsight Compute on one float sweep's node pass: 2.67 ms, 2.11 G warp
// instructions and 1.19 G L1 sectors read with 4 lanes per node; 3.01 ms,
// 1.85 G and 2.10 G with warp-shared stars in star order; 2.33 ms, 1.44 G
// and 1.45 G with 16-byte tet loads and the old minimum first. The old
// minimum's tet must improve for a move to pass; dealt first, it ends many
// rejections in the first round instead of somewhere in the star.
// Also tried: at most 40 registers, for 6 blocks of 256 per SM, 288.4 /
// 1173 against 290.0 / 522.4 (double spills); x, y and z of a point as two
// aligned pair loads instead of three, 307.6 / 729.0 against 281.8 / 512.7;
// and, though L1 is the node pass's busiest unit (79%), points padded to
// four values and read in one load (float) or two (double), 276.1 / 526.6
// against 283.8 / 510.2, with Coloured slower in both: not worth a layout.
// Nsight Compute's source view of the float node pass (12.4 rounds of the
// star test per warp, about 320 instructions each) puts its longest stalls
// on the reads of a dealt tet's index and then its nodes. Tried against
// that, each against 282.0 / 510.5 or so in its own run:
//   star faces: each incidence entry's other three corners as places in
//   the node's neighbour row (4 B per entry, built with the topology), the
//   rows' positions staged in shared memory by the centroid: 311.9 / 735.1
//   (43 KB of shared memory a block leaves L1 too little for the gathers,
//   and the extra registers cost double a block per SM); the same faces
//   with the corners read through the row instead of shared memory,
//   280.0 / 507.5 with a fallback to the tets for rows over 256 places
//   (272.9 / 492.5 without one): 1-3% for a new topology array;
//   dealing each round's successor before computing it, so that the next
//   tets' index and node reads overlap the radius ratios (re-dealt after a
//   round with an objection): 326.0 / 664.4, and 304.5 / 547.8 held to
//   48 / 80 registers, against 271.7 / 500.7 without it.
// Tried after (d), none kept, each against the code above in the same run
// (its figures in brackets):
//   a bound that spares a tet its square roots and division when it beats
//   the old minimum by a margin (Cauchy-Schwarz on the face norms; exact,
//   it never changes a decision), with the three shuffles of the owner's
//   position that a cached old quality never reads left out: 271.9 / 496.9
//   [264.2 / 488.5]. A warp runs the full ratio whenever any of its 32
//   lanes needs it, which is nearly always; the serial CPU sweep got slower
//   with it too (59k model, 2687 ms against 2374 on a 2-core host);
//   the same three shuffles left out alone: 259.1 / 488.4 [258.3 / 487.8,
//   and 261.1 / 488.0 in a repeat];
//   two tets a lane each round, both requested before either is judged
//   (warp_star_test.cuh): 312.2 / 605.7, and 282.8 / 875.7 held to 64
//   registers [264.2 / 488.5];
//   128 threads a block 264.7 / 477.6, 512 278.4 / 616.2, 128 held to 42
//   registers (12 blocks an SM in float) 269.7 / 1079, all held to 64
//   registers (4 blocks an SM in double) 258.7 / 491.1 [as above];
//   a persistent grid (as many blocks as the device holds, each striding
//   over blocks of nodes, counters posted once a block): 350.7 / 562.0
//   [258.9 / 488.8], and ordinary smoothing 28.7 / 117.9 [26.4 / 33.2];
//   each node's incidence row requested into L1 before the centroid, then
//   every tet of its star with prefetch.global (star_prefetch.cuh does it
//   for Coloured) before the old minimum: 422.3 / 526.8 into L1, 422.5 /
//   526.8 into L2 [257.2 / 486.2, and 259.9 / 486.3 in a repeat];
//   a sweep in one launch: blocks took tet tiles (512 tets' qualities) and
//   node tiles (256 nodes) in turn from a ticket counter, each node tile
//   after, and waiting on flags for, the tet tiles its stars read, so that
//   the tet pass's streaming overlapped the node pass's gathers and those
//   found their tets in L2: 329.8 / 558.5 [248.4 / 482.2]. Its waits read
//   the flags with acquire loads, each followed in the SASS by an L1
//   invalidation (CCTL.IVALL); polled without them, 296.3 / 541.0 [249.0 /
//   482.6]; with node tiles put 256 or 1024 tet tiles after their last
//   need, so that they seldom wait, 300.6 / 549.5 and 304.3 / 561.0, and
//   the latter with one acquire fence a node tile 318.2 / 576.5 [246.4 /
//   483.5]. Not the waits, then: tet tiles beside node tiles on an SM cost
//   the node tiles more than the overlap gains (our reading, not profiled);
//   nodes renumbered along a Morton curve of their positions, tets sorted
//   by their first corner (on the host, before the timed pipeline): 269.6 /
//   508.7 [248.7 / 482.6], the lattice's own order being the better one. On
//   the 109k TetGen model, whose node order has little locality, MultiBlock
//   took 0.888 ms against 1.506 in float and 1.49 against 2.01 in double,
//   but Coloured, the pipeline that the 109k figures time, only 1.14
//   against 1.21 and 2.11 against 2.18, about 0.07 ms that a renumbering
//   inside the timed pipeline would have to cost less than (not built);
//   a slot's deal (its owner, the owner's values, its place in the star)
//   kept across rounds while the warp's busy nodes stay the same, only the
//   place advancing: 253.4 / 570.4 at the 56 / 92 registers it takes, and
//   251.1 / 495.9 held to 48 / 80 (spilling) [245.6 / 482.1, and 246.1 /
//   481.8 in a repeat];
//   after the round of leads, two tets a slot, computed one after the
//   other so that no second tet's corners are held, to halve the deal and
//   the votes a tet: 255.4 in float, 255.7 with three a slot, 257.6 with
//   four, 259.0 with two in the leads' round as well, 255.1 with two held
//   to 48 registers [245.0, and 244.7 at the end of the run]. Nsight
//   Compute counts as many instructions as before (1.225 G against 1.223 G):
//   the coarser slots compute the tets that the deal would have spared;
//   the most L1 the SM offers (8 KB of shared memory, the rank rows of
//   warp_star_test.cuh cut to the block's 8 warps, so that 5 blocks still
//   fit): an L1 hit rate of 84.3% against 83.8%, and 244.6 / 243.9 in
//   float [245.7 / 245.1]; without the cut, 4 blocks fit: 261.9 [244.9];
//   each warp taking its next 32 nodes from a ticket counter (a grid of as
//   many blocks as the device holds, reset by the tet pass), so that no
//   block keeps its place on an SM for its slowest warp: 246.3 / 246.3 in
//   float [245.2 / 245.2], and 275.3 held to 40 registers (6 blocks an SM):
//   blocks that wait on their last warp cost nothing measurable;
//   the incidence rows, their offsets, the neighbour rows and tet_q read
//   through the read-only path (__ldg), as the tets already are: 234.4 /
//   234.4 in float and 478.5 / 480.5 in double [233.8 / 233.9 and 476.1 /
//   477.7], on an H200 (the only figures here not taken on an H100);
//   a node pass tiled in shared memory (a prototype, its tiles built on the
//   host outside the timed run): a block first stages the positions of all
//   nodes its 256 nodes' stars touch (1,627 on average, at most 1,636, in
//   2,048 slots of 12 B), then reads neighbours and corners from there
//   through 16-bit places kept for each neighbour entry and four for each
//   incidence entry (2.4 GB more on the device): 233.2 in float [245.5].
//   Nsight Compute: a node pass of 1.83 ms against 1.95, with 40 registers
//   and 65% of warps active against 48 and 52%, but 1.33 G instructions
//   against 1.22 G, 70% of issue slots used, and 3.37 GB of DRAM reads
//   against 3.04. Bound by issue now, it would need 93% of the issue slots
//   for 2x; not kept, for 5% at the cost of 2.4 GB and a topology step.
//   no deal at all: a thread a node settles the centroid, the old minimum
//   and the lead tet, queues the nodes still undecided in shared memory,
//   and groups of G lanes then take the queue, each node's other tets G a
//   round, a group taking the next node as soon as its own is settled
//   (a prototype, 40 registers): 255.6 / 500.2 with G = 8 and 254.0 /
//   508.1 with G = 4 [244.5 / 482.3, and 244.6 / 481.3 at the end of the
//   run]; not profiled further, since it lost in both precisions.
//   The same without groups, to drop every per-round shuffle and vote: a
//   warp's lanes settle 32 nodes' centroids, old minima and leads at a time,
//   queue the undecided ones in shared memory (a ring of 64 a warp, 12 KB a
//   block) and then each walk one queued node's other tets alone, a tet a
//   step, with the incidence row read a quad at a time (a prototype, 64
//   registers). A lane that took its next node as soon as its own was settled
//   left the warp's lanes at unrelated places in unrelated stars: 436.7 /
//   767.6 with 8 chunks of 32 nodes a warp, on an H100 [237.8 / 461.9, and
//   238.4 / 462.7 at the end of the run]. Lanes that took their nodes all
//   together, so that they walked neighbouring stars in step: 333.7 / 712.6
//   with 4 chunks a warp and 355.3 / 711.1 with 8, on an H200 [232.3 / 457.2].
//   Nsight Compute (that H200, one float node pass): 2.86 ms, 1.48 G warp
//   instructions, 5.98 GB read from DRAM and an L1 hit rate of 72%, against
//   1.72 ms, 1.12 G, 2.94 GB and 82% for the deal: lanes that wait in step for
//   the slowest of 32 stars issue more, not fewer (our reading), and DRAM
//   served twice the bytes. Its nodes' centroids were all summed before any of
//   their moves, so it accepted more moves (384 M against 354 M in float).
//   Each SM's warps taking 32-node chunks from a contiguous range of its own
//   (a grid of resident blocks, a counter per %smid, reset by the tet pass;
//   a warp whose range was done helped the first range with chunks left),
//   so that the 40 warps of an SM share their stars' lines in L1 (a
//   prototype): 247.0 / 467.4 and 246.6 / 466.2 against 225.2 / 456.0 and
//   222.6 / 455.8, on an H200. Nsight Compute (one float node pass): an L1
//   hit rate of 84.5%, but 4.77 GB read from DRAM against the 2.94 GB
//   above: 132 ranges spread over the mesh share no planes in L2, where the
//   GPU's one front through the node order does. Each range swept in order
//   also let more moves through (392.6 M against 354.4 M in float), and so
//   more whole stars. Keeping the one front, with pieces of 1,024 nodes
//   dealt to the SMs in turn (piece k to SM k % 132, its warps taking the
//   piece's chunks in order): 236.7 / 457.7 and 239.3 / 458.6 against
//   230.9 / 454.8 and 231.1 / 456.2 in another H200 run. A float node pass
//   then had an L1 hit rate of 83.1% against 81.5%, but read 3.47 GB from
//   DRAM against 2.94, issued 1.22 G instructions against 1.12 G (370 M
//   moves accepted against 354 M) and took 1.74 ms against 1.72.
// Nsight Compute's source counters (the float node pass at 98121a7, H100)
// split a round of the star test, 252 instructions, into the deal (67: the
// slots' owners, then nine shuffles of their values), the dealt tet's
// index, nodes and corners (50), its radius ratio (105) and the vote (30);
// the rounds are 80% of the pass's 1.22 G instructions. Of the stall
// samples, 39% wait in the round's dependent loads, 20% in the radius
// ratio, 13% in the deal, 10% in the old minimum and 8% in the centroid.
// Kept from that: the owners found by one OR of the nodes' first slots
// (deal_round in warp_star_test.cuh) and AoS points addressed in 64 bits
// (kernels/coords.hpp), 2-3% together; a shared-memory row addressed in 32
// bits once instead of every round (inline PTX) saved nothing measurable
// (229.5 / 464.7 against 229.2 / 464.0 on an H200). Tried after it, against
// 240.6 / 470.7 and 240.3 / 471.5 (H100): each node's first 8 incidence
// entries in dealt order staged in shared memory before the rounds (read
// again from L1 just after the old minimum), so that a round's first
// level of loads is a shared-memory read: 257.6 / 585.6 and 258.5 / 586.9,
// and 258.6 / 594.0 with 16 (10 KB and 18 KB of shared memory a block;
// not profiled, having lost in both precisions).
// The same source counters count L1 tag requests: a lane reading its own
// row entry by entry makes each load of the warp look up about 24 lines
// (32 rows side by side), so the old minimum's walk of the incidence rows
// took 576 lookups a warp and the centroid's neighbour rows about 290, a
// third of the pass's. Read a 16-byte quad at a time (RowWalk in
// node_update.hpp), ms for 100 sweeps and Ordinary MultiBlock's ms a sweep,
// float / double, one H100 run:
//   entry by entry (the code before)        240.2 / 471.9, 0.376 / 0.472
//   both rows in quads                      233.4 / 468.1, 0.383 / 0.541
//   the incidence rows only (kept)          229.8 / 462.5, 0.373 / 0.490
//     and 8 old qualities at a time         232.6 / 461.7
//   both, 8 old qualities at a time         235.6 / 471.4
// with that code at 229.7 / 461.1 again at the end of the run (kept with
// RowWalk's check of a row's start left to quads). A row walked in aligned
// quads takes a step more when it starts late in a quad: the lattice's
// neighbour rows of 14 entries then span three steps of 8, not two, and
// Ordinary smoothing, whose sweep is that walk, waits on it. Tried with
// both rows in quads, against 232.4 to 233.6 in float in the same runs:
// 40 registers (6 blocks an SM) 239.9, 32
// (8 blocks) 316.8, 53 (4 blocks) 250.6, so more warps only crowd L1; the
// neighbour rows read past L1 (ld.global.nc.L1::no_allocate) 241.0, since
// a row's quads share lines; the tet pass's tets read past L1 233.2, and
// blocks that take a 32 x 4 x 2 brick of lattice nodes (lattice-specific
// indexing, for the A/B only) 235.0 in float but 562.5 in double against
// 471.3, with 240.9 in float for the code before RowWalk.
// row_sum then went back to its own loop (each entry's index and position
// requested together), as before RowWalk: in the same H100 run, 100 sweeps
// 229.7 / 463.1 and Ordinary MultiBlock 0.376 / 0.470 ms a sweep, against
// 230.2 / 464.6 and 0.374 / 0.493 with RowWalk's neighbour rows (230.3 /
// 465.1 and 0.372 / 0.497 again at the end of the run). Tried in that run,
// against the same figures: points padded to four values again (one load
// in float, two in double), 235.9 / 478.3; a tet's corners requested as the
// three that are not node i, in an order that keeps the orientation, so
// that 9 loads replace 12 predicated ones (the round's SASS read 4 x 3),
// 234.1 / 465.9: choosing the three puts compares and selects between the
// tet's nodes and the corners' loads; and both, 238.0 / 479.7. In a later
// H100 run, against 229.3 / 462.6 and 229.0 / 462.1: the star's second
// lowest old quality dealt second as well (tracked by the old minimum's
// walk, one more shuffle a round), 233.1 / 564.9 and 233.6 / 564.8 (in
// double 82 registers, allocated as 88: two blocks an SM instead of three).
// Where the node pass waits (Nsight Compute's warp stall samples by SASS
// instruction, one float sweep at f4667ee, H100): 77% of them fall
// in the star test's rounds, 9% in the old minimum and 9% in the centroid.
// The three dependent reads of a round hold most: 11% of all samples wait
// on the dealt incidence entry, 21% on that tet's nodes and 11% on its
// corners. The pass is bound by the latency of that chain (58% of its
// stalls are on L1TEX loads, 60% of issue slots used), not by its
// instructions or its DRAM traffic (1.6 TB/s).
// What 2x of the memory floor asks of the two passes (float, lattice-215: a
// floor of 0.956 ms, so 1.91 ms a sweep). The node pass keeps L1/TEX 73%
// busy for 1.79 ms, the tet pass DRAM 74% for 0.525 ms
// (results/h100/ncu_lattice_MultiBlock.txt, the code above at ea476b5; 79%
// for 1.89 ms before RowWalk, 77% for 1.95 ms before deal_round). With the
// loads they make now, the node pass cannot take less than 1.31 ms, nor the
// tet pass less than 0.39 ms, even with its busiest unit at full
// throughput: 1.70 ms together, 1.78x. So 2x needs both passes near their
// peak (the node pass at 1.39 ms, 94% of L1's throughput), or fewer
// L1 requests for each tet the star test computes and then more of their
// latency hidden. The cuts of L1 requests tried (each corner in one padded
// load, star faces read through the row) saved at most 3%, and padded
// corners lost 2.5% once the incidence rows came in quads (the A/B above):
// what holds the pass is its reads' latency, not L1's throughput. Profiled
// once more (H100, one float node pass at d3f41e0), padded points halve the
// pass's L1 requests (44.1 M against 83.6 M) and cut its L1 sectors by a
// third (0.84 G against 1.28 G), yet the pass takes 1.81 ms against 1.79:
// L1's hit rate falls from 82% to 69%, and L2, already as busy as L1 (73%),
// goes to 76%. 100 sweeps, in which the tet pass reads padded points too:
// 234.9 and 234.6 ms against 237.1 and 238.4 in float. Nor does a
// level of the chain come out for free: an incidence entry that carries
// its tet's other three corners (16 B with the tet's index, 3.8 GB for
// lattice-215) would replace 1.9 GB of incidence entries and tets with
// 3.8 GB, leaving the node pass about 4.9 GB to read: 1.48 ms at the
// H100's peak DRAM bandwidth (3.35 TB/s), so as tight as now (not built).
// The tiled node pass above takes the tets' level out, and serves the
// corners from shared memory, for 0.33 GB more DRAM reads; it still takes
// 2.33 ms a sweep, 2.44x of that floor.
// Nor is it the DRAM latency of first touches. A prototype had one lane per
// array in each block's last warp ask the copy engine to prefetch into L2
// (cp.async.bulk.prefetch.L2, sm_90) the data of the block D blocks ahead.
// That data was the block's incidence and neighbour rows with their
// offsets, and the tets whose lowest corner is among its nodes, with their
// qualities. The lattice's tets are stored in that order, so those are one
// contiguous range, which a binary search found for each block before the
// sweeps. 100 float sweeps of lattice-215 on an H100, medians of 3, one
// run:
//   the code above                                  235.4, and 235.4 at the end
//   the range table alone, nothing prefetched       234.1
//   all of it, D = 64                               242.7
//   all of it, D = 16                               239.1
//   tets and qualities, D = 64                      240.6
//   tets and qualities of the block itself, D = 0   235.5
//   rows and offsets, D = 64                        237.5
// None kept. The pass reads 3.04 GB from DRAM, against about 2.9 GB in the
// arrays it reads (sizes counted for lattice-215), so each byte comes from
// DRAM about once. The first touches are not what it waits on; our reading is
// that a round waits on the trip from L1 to L2, three loads deep.
inline constexpr int kMultiBlockChunk = 8;
inline constexpr int kOldMinChunk = 4;

// Applies an evaluated move; returns whether the node moved.
template <class Real, Form F, class Coords>
__device__ __forceinline__ bool apply_move(const NodeMove<Real>& mv, const Coords& read, const Coords& write, index_t i,
                                           Real* old_min, std::uint8_t* moved, double& disp2) {
  const bool take = mv.accept && mv.displacement2 > Real(0);
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
// loads stay coalesced. 100 sweeps of lattice-215 on an H100, ms, float /
// double: 272.4 / 489.6 with one tet a thread, 262.5 / 488.7 with two,
// 268.4 / 496.7 with four (the float node pass held to 40 registers in all
// three).
// The paper's threads instead rewrite the qualities of a moved node's tets
// "in memory" (its section 3.4), which would spare this pass. Tried in Form
// B: the star test kept each new quality by incidence entry, a mover copied
// its star's into tet_q, and this pass ran only before the first sweep.
// Where two corners of a tet move in one sweep, the entry then holds a
// quality computed with the other one's old position, and the stale old
// minima let more moves through: on an H100, 100 sweeps of lattice-215
// accepted 497.0 M moves against 353.5 M in float (513.0 M against 425.8 M
// in double) and took 526.0 / 696.6 ms against 240.1 / 463.5, and the 109k
// model ended with 85 inverted tets against 19 in float (56 against 21).
inline constexpr int kTetsPerThread = 2;

template <class Real, class Coords>
__global__ void tet_quality_kernel(const index_t* tets, index_t num_tets, Coords xyz, Real* tet_q,
                                   const SweepState* st) {
  if (st->done) return;
  const std::size_t t0 = static_cast<std::size_t>(blockIdx.x) * blockDim.x * kTetsPerThread + threadIdx.x;
  store_tet_qualities<kTetsPerThread>(tets, static_cast<std::size_t>(num_tets), t0, blockDim.x, xyz, tet_q);
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
  // bottleneck unless a block posts them once (on an H100, lattice-215
  // MultiBlock, when it still ran 8 lanes per node: 0.98 ms a sweep against
  // 2.35 in float, 1.48 against 2.48 in double); the adaptive test's uneven
  // nodes would wait at the block's barrier instead (574.7 ms against 557.9
  // for 100 sweeps in float; with the warp-shared test, 292.4 against 290.0
  // in float, 521.7 against 522.4 in double).
  if constexpr (F == Form::B) {
    if constexpr (kAdaptive)
      add_sweep_stats(c, st->sweep, accepted, disp2);
    else
      add_sweep_stats_block(c, st->sweep, accepted, disp2);
  }
}

// The steps of the Form A repair, shared by the multi-launch kernels and
// single_block_kernel.

// Flags the movers of tet t when it objects to the sweep's result.
template <class Real, class Coords>
__device__ __forceinline__ bool flag_objecting_tet(const index_t* tets, index_t t, const Coords& before,
                                                   const Coords& after, const std::uint8_t* moved, const Real* old_min,
                                                   std::uint8_t* revert) {
  const index_t* tet = tets + 4 * t;
  if (!tet_rejects_movers(tet, before, after, moved, old_min)) return false;
  for (int k = 0; k < 4; ++k)
    if (moved[tet[k]]) revert[tet[k]] = 1;  // every writer stores the same value
  return true;
}

// Puts node i back where it was when flagged (or when undoing the whole
// sweep); clears its flag. Returns whether it was reverted.
template <class Coords>
__device__ __forceinline__ bool revert_if_flagged(index_t i, const Coords& before, const Coords& after,
                                                  std::uint8_t* moved, std::uint8_t* revert, bool undo_all) {
  const bool back = moved[i] && (revert[i] || undo_all);
  if (back) {
    after.set(i, before.get(i));
    moved[i] = 0;
  }
  revert[i] = 0;
  return back;
}

// Squared length of node i's surviving move (0 when it did not move).
template <class Coords>
__device__ __forceinline__ double surviving_disp2(index_t i, const Coords& before, const Coords& after,
                                                  const std::uint8_t* moved) {
  return moved[i] ? static_cast<double>(norm2(after.get(i) - before.get(i))) : 0.0;
}

// Form A conflict repair, pass `pass` (see node_update.hpp): flag the movers
// of objecting tets. Skipped when the previous pass found nothing.
template <class Real, class Coords>
__global__ void repair_check_kernel(const index_t* tets, index_t num_tets, Coords before, Coords after,
                                    const std::uint8_t* moved, const Real* old_min, std::uint8_t* revert,
                                    SweepState* st, SweepCounters c, int pass) {
  if (st->done || (pass > 0 && !c.repair_found[pass - 1])) return;
  const index_t t = static_cast<index_t>(blockIdx.x * blockDim.x + threadIdx.x);
  if (t < num_tets && flag_objecting_tet(tets, t, before, after, moved, old_min, revert)) c.repair_found[pass] = 1;
}

template <class Coords>
__global__ void repair_apply_kernel(index_t n, Coords before, Coords after, std::uint8_t* moved, std::uint8_t* revert,
                                    SweepState* st, SweepCounters c, int pass) {
  if (st->done || !c.repair_found[pass]) return;
  const bool undo_all = pass == kMaxRepairPasses - 1;
  const index_t i = static_cast<index_t>(blockIdx.x * blockDim.x + threadIdx.x);
  unsigned reverted = i < n && revert_if_flagged(i, before, after, moved, revert, undo_all);
  warp_atomic_add(&st->reverted, reverted);
}

// Form A: count the moves that survived the repair.
template <class Coords>
__global__ void count_moves_kernel(index_t n, Coords before, Coords after, const std::uint8_t* moved, SweepState* st,
                                   SweepCounters c) {
  if (st->done) return;
  const index_t i = static_cast<index_t>(blockIdx.x * blockDim.x + threadIdx.x);
  const bool live = i < n && moved[i];
  add_sweep_stats_block(c, st->sweep, live, live ? surviving_disp2(i, before, after, moved) : 0.0);
}

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

// The whole sweep loop in one block (SingleBlock). The per-node body and the
// repair are the same functions the other strategies use; only the loops
// and barriers differ.
template <class Real, bool kAdaptive, Form F, class Coords>
__global__ void __launch_bounds__(kSingleBlockThreads)
    single_block_kernel(MeshView m, Coords buf0, Coords buf1, index_t n, index_t num_tets,
                        const std::uint8_t* movable, Real* old_min, std::uint8_t* moved, std::uint8_t* revert,
                        SweepState* st, SweepCounters c, int max_iterations) {
  __shared__ unsigned long long s_accepted;
  __shared__ double s_disp2;
  __shared__ int s_flag;
  for (int s = 0; s < max_iterations; ++s) {
    const Coords read = (F == Form::A && (s & 1)) ? buf1 : buf0;
    const Coords write = (F == Form::A && (s & 1)) ? buf0 : buf1;
    if (threadIdx.x == 0) {
      s_accepted = 0;
      s_disp2 = 0;
    }
    __syncthreads();
    unsigned accepted = 0;
    double disp2 = 0;
    for (index_t i = threadIdx.x; i < n; i += blockDim.x) {
      if (!movable[i]) continue;
      double d2 = 0;
      if (smooth_node<Real, kAdaptive, F>(m, read, write, i, old_min, moved, d2)) {
        ++accepted;
        disp2 = fmax(disp2, d2);
      }
    }
    if (F == Form::A) {
      __syncthreads();
      for (int pass = 0; kAdaptive && pass < kMaxRepairPasses; ++pass) {
        if (threadIdx.x == 0) s_flag = 0;
        __syncthreads();
        for (index_t t = threadIdx.x; t < num_tets; t += blockDim.x)
          if (flag_objecting_tet(m.tets, t, read, write, moved, old_min, revert)) atomicOr(&s_flag, 1);
        __syncthreads();
        const int found = s_flag;
        if (!found) break;
        const bool undo_all = pass == kMaxRepairPasses - 1;
        unsigned reverted = 0;
        for (index_t i = threadIdx.x; i < n; i += blockDim.x)
          reverted += revert_if_flagged(i, read, write, moved, revert, undo_all);
        if (reverted) atomicAdd(&st->reverted, static_cast<unsigned long long>(reverted));
        __syncthreads();
      }
      accepted = 0;
      disp2 = 0;
      for (index_t i = threadIdx.x; i < n; i += blockDim.x) {
        accepted += moved[i];
        disp2 = fmax(disp2, surviving_disp2(i, read, write, moved));
      }
    }
    if (accepted) {
      atomicAdd(&s_accepted, static_cast<unsigned long long>(accepted));
      atomicMax(reinterpret_cast<unsigned long long*>(&s_disp2), static_cast<unsigned long long>(__double_as_longlong(disp2)));
    }
    __syncthreads();
    if (threadIdx.x == 0) {
      c.accepted[s] = s_accepted;
      c.max_disp2_bits[s] = static_cast<unsigned long long>(__double_as_longlong(s_disp2));
      const SweepVerdict v = sweep_verdict(s + 1, static_cast<long long>(s_accepted), sqrt(s_disp2), st->tol_abs,
                                           max_iterations);
      record_verdict(st, s, v);
      s_flag = st->done;
    }
    __syncthreads();
    if (s_flag) break;
    __syncthreads();
  }
}

// Input (double AoS, mesh units) -> working coordinates: (x - centre) * inv_scale.
template <class Real, class Coords>
__global__ void load_coords_kernel(const double* in, Coords out, index_t n, double cx, double cy, double cz,
                                   double inv_scale) {
  const index_t i = static_cast<index_t>(blockIdx.x * blockDim.x + threadIdx.x);
  if (i >= n) return;
  out.set(i, Vec3<Real>{static_cast<Real>((in[3 * i] - cx) * inv_scale), static_cast<Real>((in[3 * i + 1] - cy) * inv_scale),
                        static_cast<Real>((in[3 * i + 2] - cz) * inv_scale)});
}

// Only movable nodes are written back, so the others keep their input bits
// even when the working precision is float.
template <class Real, class Coords>
__global__ void store_coords_kernel(Coords in, double* out, const std::uint8_t* movable, index_t n, double cx,
                                    double cy, double cz, double scale) {
  const index_t i = static_cast<index_t>(blockIdx.x * blockDim.x + threadIdx.x);
  if (i >= n || !movable[i]) return;
  const Vec3<Real> v = in.get(i);
  out[3 * i] = static_cast<double>(v.x) * scale + cx;
  out[3 * i + 1] = static_cast<double>(v.y) * scale + cy;
  out[3 * i + 2] = static_cast<double>(v.z) * scale + cz;
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
