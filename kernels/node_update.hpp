#pragma once
// The per-node math of Laplacian smoothing, once for every backend: the
// centroid of a node's neighbours, the quality of its incident tets with the
// node at its old and at its candidate position, and the accept rule.
//
// Adaptive accept rule for node i moving from p to the centroid c:
//   * the minimum radius ratio over i's incident tets must strictly rise, and
//   * no incident tet that was valid (q > 0) may become invalid (q <= 0), and
//   * no incident tet that was already invalid may get worse.
// So a move never creates an inverted tet, never lowers the minimum quality
// of the moved node's tets, and never makes an inverted input tet worse.
// Ordinary Laplacian accepts every move.
#include <cstdint>

#include "kernels/coords.hpp"
#include "mesh/hd.hpp"
#include "mesh/tet_mesh.hpp"
#include "mesh/tet_quality.hpp"
#include "mesh/topology.hpp"

namespace tetsmooth {

// Raw pointers into the topology (CSR rows, see mesh/topology.hpp), valid on
// the host or on the device depending on where they were allocated.
struct MeshView {
  const index_t* tets;      // 4 per tet
  const index_t* nbr_off;   // N + 1
  const index_t* nbr;       // neighbours
  const index_t* inc_off;   // N + 1
  const index_t* inc;       // incident tets
};

// The view of a mesh and its topology both held on the host (the CPU
// backend, tests). The GPU's comes from DeviceTopology::view.
inline MeshView host_view(const TetMesh& mesh, const Topology& topo) {
  return MeshView{mesh.tets.data(), topo.neighbours.offsets.data(), topo.neighbours.items.data(),
                  topo.node_tets.offsets.data(), topo.node_tets.items.data()};
}

template <class Real>
struct NodeMove {
  Vec3<Real> target;  // the centroid
  Real old_min;       // min q over incident tets at the old position
  Real displacement2; // squared move length
  bool accept;
};

// The pieces below take a lane and a stride so that a group of GPU threads
// can share one node (lane l handles entries l, l + stride, ...) and combine
// the parts; the CPU calls them with lane 0 and stride 1.

// A lane's walk over entries [begin, end) of a CSR row array, kChunk
// entries a step: entries first + u * stride for u < kChunk, those in
// [begin, end) valid. On the device, a lone lane (lane 0, stride 1) with
// whole quads of entries a step walks aligned quads from the quad holding
// `begin` instead, each one 16-byte load where four scalar loads took a tag
// lookup each (a warp whose lanes read 32 rows touches as many cache lines
// per load either way). The price is a step more for a row that starts
// late in a quad, so only star_old_min's incidence rows take it; row_sum
// requests each neighbour's index and then its position, one entry at a
// time (the A/Bs are in kernels/cuda/multiblock_experiments.md). Quads need
// every device CSR array 16-byte aligned and readable to its last whole
// quad (DeviceBuffer pads its allocations to that).
template <int kChunk>
struct RowWalk {
  index_t begin, end;
  int stride;
  bool quads;
  TS_HD RowWalk(index_t b, index_t e, int lane, int s) : begin(b), end(e), stride(s), quads(false) {
#ifdef __CUDA_ARCH__
    quads = kChunk % 4 == 0 && lane == 0 && s == 1;
#endif
    first = quads ? (b & ~index_t(3)) : b + lane;
  }
  index_t first;  // the chunk's first entry
  TS_HD bool more() const { return first < end; }
  TS_HD void next() { first += kChunk * stride; }
  TS_HD index_t entry(int u) const { return first + u * stride; }
  TS_HD bool valid(int u) const { return (!quads || entry(u) >= begin) && entry(u) < end; }
  // The chunk's items of `row` (those of invalid entries unspecified).
  TS_HD void fetch(const index_t* row, index_t (&item)[kChunk]) const {
#ifdef __CUDA_ARCH__
    if (quads) {
      for (int q = 0; q < kChunk / 4; ++q) {
        const int4 v = first + 4 * q < end ? __ldg(reinterpret_cast<const int4*>(row + first) + q) : int4{0, 0, 0, 0};
        item[4 * q] = v.x;
        item[4 * q + 1] = v.y;
        item[4 * q + 2] = v.z;
        item[4 * q + 3] = v.w;
      }
      return;
    }
#endif
    for (int u = 0; u < kChunk; ++u) item[u] = valid(u) ? row[entry(u)] : index_t(0);
  }
};

// Sum of the positions of the neighbours in entries [begin, end) of the
// neighbour CSR (a node's row, or none), over this lane's share. The lane
// fetches kChunk of its entries before adding any, so a GPU lane with
// several entries waits on memory once per chunk rather than once per
// entry (at the cost of kChunk positions in registers); the additions keep
// the entries' order, so the sum has the same bits whatever kChunk is.
template <class Real, int kChunk = 1, class Coords>
TS_HD Vec3<Real> row_sum(const MeshView& m, const Coords& xyz, index_t begin, index_t end, int lane, int stride) {
  Vec3<Real> s{0, 0, 0};
  for (index_t first = begin + lane; first < end; first += kChunk * stride) {
    Vec3<Real> v[kChunk]{};  // entries past the row stay unused
    for (int u = 0; u < kChunk; ++u) {
      const index_t k = first + u * stride;
      if (k < end) v[u] = xyz.get(m.nbr[k]);
    }
    for (int u = 0; u < kChunk; ++u)
      if (first + u * stride < end) s = s + v[u];
  }
  return s;
}

// The same over node i's row.
template <class Real, class Coords>
TS_HD Vec3<Real> neighbour_sum(const MeshView& m, const Coords& xyz, index_t i, int lane, int stride) {
  return row_sum<Real>(m, xyz, m.nbr_off[i], m.nbr_off[i + 1], lane, stride);
}

// The node indices of tet t (`tets` holds four per tet). On the device, one
// 16-byte load: device buffers come from cudaMalloc, so every tet's four are
// aligned, and a warp's gather of tets costs L1 one sector per lane instead
// of four.
struct TetNodes {
  index_t v[4];
};
TS_HD TetNodes tet_nodes(const index_t* tets, std::size_t t) {
#ifdef __CUDA_ARCH__
  const int4 q = __ldg(reinterpret_cast<const int4*>(tets) + t);
  return {{q.x, q.y, q.z, q.w}};
#else
  const index_t* p = tets + 4 * t;
  return {{p[0], p[1], p[2], p[3]}};
#endif
}

// The four corners of a tet with nodes `tet`, node i replaced by `at`.
template <class Real, class Coords>
TS_HD void tet_corners(const Coords& xyz, const TetNodes& tet, index_t i, Vec3<Real> at, Vec3<Real> (&v)[4]) {
  for (int k = 0; k < 4; ++k) v[k] = tet.v[k] == i ? at : xyz.get(tet.v[k]);
}

// The tet-level part of the accept rule, shared with the Form A conflict check.
template <class Real>
TS_HD bool keeps_validity(Real q_old, Real q_new) {
  return q_old > Real(0) ? q_new > Real(0) : q_new >= q_old;
}

// A tet's radius ratio with node i at `at` (the tet's own corner order),
// for a caller that has its nodes already.
template <class Real, class Coords>
TS_HD Real tet_quality_at(const Coords& xyz, const TetNodes& tet, index_t i, Vec3<Real> at) {
  Vec3<Real> v[4];
  tet_corners(xyz, tet, i, at, v);
  return radius_ratio(v[0], v[1], v[2], v[3]);
}

// The same for tet t.
template <class Real, class Coords>
TS_HD Real tet_quality_with(const MeshView& m, const Coords& xyz, index_t t, index_t i, Vec3<Real> at) {
  return tet_quality_at(xyz, tet_nodes(m.tets, static_cast<std::size_t>(t)), i, at);
}

// Where the adaptive test gets a tet's quality with the node where it
// stands now: recomputed from the coordinates (the reference, every
// backend), or read from a per-tet cache that the caller keeps current (the
// GPU coloured loop; see kernels/cuda/coloured_loop_kernel.cuh).
struct FreshOldQuality {
  template <class Real, class Coords>
  TS_HD Real operator()(const MeshView& m, const Coords& xyz, index_t t, index_t i, Vec3<Real> p) const {
    return tet_quality_with(m, xyz, t, i, p);
  }
};

template <class Real>
struct CachedOldQuality {
  const Real* q;  // one per tet
  template <class Coords>
  TS_HD Real operator()(const MeshView&, const Coords&, index_t t, index_t, Vec3<Real>) const {
    return q[t];
  }
};

// The adaptive test in two passes. The first finds the star's minimum
// quality with the node where it stands (this lane's share; a group takes
// the minimum over its lanes). The second computes each tet's quality with
// the node at the target and stops at the first tet that objects: the
// accept rule holds exactly when every tet's new quality beats that minimum
// and keeps its validity, so the first objection settles the rejection and
// the remaining tets need not be computed. A tet whose new quality beats
// the minimum and is positive keeps its validity whatever its old quality,
// so the old quality is looked at again only for a new q <= 0 (rare).
// `at`, where given, receives the incidence entry of the minimum (that of
// the lane's first entry when the lane has none below 2). The lane takes
// kChunk of its entries' qualities before comparing any, as row_sum fetches
// positions; the comparisons keep the entries' order.
//
// Entries are taken in order, and the minimum moves to a later one only when
// it is lower, or a NaN (which then stays, and rejects the move as it does
// tet by tet): so the minimum of a row's entries is the minimum of its first
// entries' and of the rest's, in that order (lowers_min).
template <class Real>
TS_HD bool lowers_min(Real q, Real q_min) {
  return q < q_min || q != q;
}

// The first pass over entries [begin, end) of node i's incidence row (a
// caller that has taken the row's first entries itself passes the rest).
template <class Real, int kChunk = 1, class Coords, class OldQuality = FreshOldQuality>
TS_HD Real star_old_min_in(const MeshView& m, const Coords& xyz, index_t i, Vec3<Real> p, index_t begin,
                           index_t end, int lane, int stride, const OldQuality& old_quality = {},
                           index_t* at = nullptr) {
  Real q_min = Real(2);
  index_t k_min = begin + lane;
  for (RowWalk<kChunk> w(begin, end, lane, stride); w.more(); w.next()) {
    index_t t[kChunk];
    w.fetch(m.inc, t);
    Real q[kChunk];
    for (int u = 0; u < kChunk; ++u) q[u] = w.valid(u) ? old_quality(m, xyz, t[u], i, p) : Real(2);
    for (int u = 0; u < kChunk; ++u)
      if (lowers_min(q[u], q_min)) {
        q_min = q[u];
        k_min = w.entry(u);
      }
  }
  if (at) *at = k_min;
  return q_min;
}

// The first pass over node i's whole row.
template <class Real, int kChunk = 1, class Coords, class OldQuality = FreshOldQuality>
TS_HD Real star_old_min(const MeshView& m, const Coords& xyz, index_t i, Vec3<Real> p, int lane, int stride,
                        const OldQuality& old_quality = {}, index_t* at = nullptr) {
  return star_old_min_in<Real, kChunk>(m, xyz, i, p, m.inc_off[i], m.inc_off[i + 1], lane, stride, old_quality, at);
}

// Does nothing with a tet's quality at the target (see star_improves).
struct IgnoreNewQuality {
  template <class Real>
  TS_HD void operator()(index_t, Real) const {}
};

// One thread per node: a lane's objection is the node's.
struct SoleLane {
  TS_HD bool operator()(bool objects) const { return objects; }
};

// Whether tet t (its nodes `tet`), incident to node i, objects to i moving
// from p to target (the second pass's test, tet by tet); q_new receives t's
// quality with i at the target. Written so that a NaN objects.
template <class Real, class Coords, class OldQuality = FreshOldQuality>
TS_HD bool tet_objects_at(const MeshView& m, const Coords& xyz, index_t t, const TetNodes& tet, index_t i,
                          Vec3<Real> p, Vec3<Real> target, Real old_min, const OldQuality& old_quality, Real& q_new) {
  q_new = tet_quality_at(xyz, tet, i, target);
  return !(q_new > old_min) || (!(q_new > Real(0)) && !keeps_validity(old_quality(m, xyz, t, i, p), q_new));
}

// The same, the tet's nodes read from the mesh.
template <class Real, class Coords, class OldQuality = FreshOldQuality>
TS_HD bool tet_objects(const MeshView& m, const Coords& xyz, index_t t, index_t i, Vec3<Real> p, Vec3<Real> target,
                       Real old_min, const OldQuality& old_quality, Real& q_new) {
  return tet_objects_at(m, xyz, t, tet_nodes(m.tets, static_cast<std::size_t>(t)), i, p, target, old_min,
                        old_quality, q_new);
}

// The second pass's rounds over entries [begin, end) of node i's row: false
// at the first round in which a tet objects. Lanes take the tets in rounds of
// `stride`; `any(objects)` tells every lane of the group whether any lane's
// tet in the round objected (all lanes of the group call it, the same number
// of times). `keep_new(k, q)` receives the new quality q of the tet at
// incidence entry k, round by round, for a caller that stores what it may
// need again. `old_min` is the whole star's minimum (star_old_min).
#ifdef __CUDACC__
#pragma nv_exec_check_disable
#endif
template <class Real, class Coords, class OldQuality = FreshOldQuality, class KeepNew = IgnoreNewQuality,
          class Any = SoleLane>
TS_HD bool no_tet_objects_in(const MeshView& m, const Coords& xyz, index_t i, Vec3<Real> p, Vec3<Real> target,
                             Real old_min, index_t begin, index_t end, int lane, int stride,
                             const OldQuality& old_quality = {}, KeepNew&& keep_new = {}, Any&& any = {}) {
  for (index_t base = begin; base < end; base += stride) {
    const index_t k = base + lane;
    bool objects = false;
    if (k < end) {
      Real q_new;
      objects = tet_objects(m, xyz, m.inc[k], i, p, target, old_min, old_quality, q_new);
      keep_new(k, q_new);
    }
    if (any(objects)) return false;
  }
  return true;
}

// The rule's verdict once no tet of a row [begin, end) objects: a node
// without tets has nothing to improve, and an old minimum of 2 or more (no
// radius ratio reaches it) is the rule's starting value, never beaten.
template <class Real>
TS_HD bool star_can_improve(index_t begin, index_t end, Real old_min) {
  return end > begin && old_min < Real(2);
}

// The second pass over node i's whole row.
#ifdef __CUDACC__
#pragma nv_exec_check_disable
#endif
template <class Real, class Coords, class OldQuality = FreshOldQuality, class KeepNew = IgnoreNewQuality,
          class Any = SoleLane>
TS_HD bool star_improves(const MeshView& m, const Coords& xyz, index_t i, Vec3<Real> p, Vec3<Real> target,
                         Real old_min, int lane, int stride, const OldQuality& old_quality = {},
                         KeepNew&& keep_new = {}, Any&& any = {}) {
  const index_t begin = m.inc_off[i], end = m.inc_off[i + 1];
  return no_tet_objects_in(m, xyz, i, p, target, old_min, begin, end, lane, stride, old_quality,
                           static_cast<KeepNew&&>(keep_new), static_cast<Any&&>(any)) &&
         star_can_improve(begin, end, old_min);
}

// The decision, once the centroid and the adaptive test are known.
template <class Real, bool kAdaptive>
TS_HD NodeMove<Real> decide_move(Vec3<Real> p, Vec3<Real> target, Real old_min, bool improves) {
  NodeMove<Real> mv;
  mv.target = target;
  mv.displacement2 = norm2(target - p);
  mv.old_min = kAdaptive ? old_min : Real(1);
  mv.accept = !kAdaptive || improves;
  return mv;
}

// Whether an evaluated move is made: accepted, and going somewhere. A move
// of length zero changes nothing, and counting it would keep a sweep of such
// moves from ever stopping the run for want of moves.
template <class Real>
TS_HD bool takes_move(const NodeMove<Real>& mv) {
  return mv.accept && mv.displacement2 > Real(0);
}

// One node, start to finish, on one thread (the CPU and SingleBlock).
template <class Real, bool kAdaptive, class Coords>
TS_HD NodeMove<Real> evaluate_node(const MeshView& m, const Coords& xyz, index_t i) {
  const Vec3<Real> p = xyz.get(i);
  const Real inv_degree = Real(1) / Real(m.nbr_off[i + 1] - m.nbr_off[i]);
  const Vec3<Real> target = inv_degree * neighbour_sum<Real>(m, xyz, i, 0, 1);
  if (!kAdaptive) return decide_move<Real, false>(p, target, Real(1), true);
  const Real old_min = star_old_min(m, xyz, i, p, 0, 1);
  return decide_move<Real, true>(p, target, old_min, star_improves(m, xyz, i, p, target, old_min, 0, 1));
}

// Form A conflict check for a tet where two or more nodes moved in the same
// Jacobi sweep (a tet with a single mover was already judged exactly by that
// mover's own test). The tet passes when its final quality beats every
// mover's old minimum and it keeps its validity; otherwise its movers are
// reverted. With this, Jacobi keeps the adaptive guarantees.
template <class Real>
TS_HD bool tet_conflict_ok(Real q_before, Real q_after, Real max_mover_old_min) {
  return q_after > max_mover_old_min && keeps_validity(q_before, q_after);
}

// Reverting movers can leave a tet with three or more movers in conflict
// again, so the check-and-revert pass repeats. Every backend runs at most
// this many passes; if the last one still found a conflict, every move of
// the sweep is reverted, which is always safe. Cascades that deep are rare.
inline constexpr int kMaxRepairPasses = 8;

// Whether repair pass `pass` (from 0) is the last, which undoes every move
// of the sweep if it still finds a conflict. Runs always take
// kMaxRepairPasses; a test passes fewer to reach the undo, which the meshes
// it can build rarely need.
TS_HD bool repair_undoes_sweep(int pass, int max_passes = kMaxRepairPasses) { return pass == max_passes - 1; }

// A repair pass's step for node i: puts it back where it was (`before`) when
// it moved and a conflict flagged it, or when the pass undoes the sweep;
// clears its flag. Returns whether it was reverted.
template <class Coords>
TS_HD bool revert_if_flagged(index_t i, const Coords& before, const Coords& after, std::uint8_t* moved,
                             std::uint8_t* revert, bool undo_all) {
  const bool back = moved[i] && (revert[i] || undo_all);
  if (back) {
    after.set(i, before.get(i));
    moved[i] = 0;
  }
  revert[i] = 0;
  return back;
}

// Squared length of node i's move that survived the repair (0 when it did
// not move).
template <class Coords>
TS_HD double surviving_disp2(index_t i, const Coords& before, const Coords& after, const std::uint8_t* moved) {
  return moved[i] ? static_cast<double>(norm2(after.get(i) - before.get(i))) : 0.0;
}

// Checks one tet after a Jacobi sweep (`before`/`after` are the two
// buffers): true when it has two or more movers and objects to the result.
// The caller then reverts all of the tet's movers.
template <class Real, class Coords>
TS_HD bool tet_rejects_movers(const index_t* tet, const Coords& before, const Coords& after,
                              const std::uint8_t* moved, const Real* old_min) {
  int movers = 0;
  Real worst_promise = Real(-2);
  for (int k = 0; k < 4; ++k)
    if (moved[tet[k]]) {
      ++movers;
      worst_promise = old_min[tet[k]] > worst_promise ? old_min[tet[k]] : worst_promise;
    }
  if (movers < 2) return false;
  const Real q_before = radius_ratio(before.get(tet[0]), before.get(tet[1]), before.get(tet[2]), before.get(tet[3]));
  const Real q_after = radius_ratio(after.get(tet[0]), after.get(tet[1]), after.get(tet[2]), after.get(tet[3]));
  return !tet_conflict_ok(q_before, q_after, worst_promise);
}

// The stopping rule shared by every variant and backend. `sweep` counts from 1.
enum class SweepVerdict { Continue, NoMoves, Tolerance, MaxIterations };

template <class Real>
TS_HD SweepVerdict sweep_verdict(int sweep, long long accepted, Real max_disp, Real tol_abs, int max_iterations) {
  if (accepted == 0) return SweepVerdict::NoMoves;
  if (max_disp < tol_abs) return SweepVerdict::Tolerance;
  if (sweep >= max_iterations) return SweepVerdict::MaxIterations;
  return SweepVerdict::Continue;
}

}  // namespace tetsmooth
