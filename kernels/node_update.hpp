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

template <class Real>
struct NodeMove {
  Vec3<Real> target;  // the centroid
  Real old_min;       // min q over incident tets at the old position
  Real new_min;       // min q with the node at the target
  Real displacement2; // squared move length
  bool accept;
};

// The pieces below take a lane and a stride so that a group of GPU threads
// can share one node (lane l handles entries l, l + stride, ...) and combine
// the parts; the CPU calls them with lane 0 and stride 1.

// Does nothing with a neighbour (see neighbour_sum).
struct IgnoreNeighbour {
  TS_HD void operator()(index_t) const {}
};

// Sum of the neighbours' positions over this lane's share of the row.
// `visit(j)` is called for each neighbour j on the way, so a caller that
// needs more of the row reads it in the same pass.
#ifdef __CUDACC__
#pragma nv_exec_check_disable
#endif
template <class Real, class Coords, class Visit = IgnoreNeighbour>
TS_HD Vec3<Real> neighbour_sum(const MeshView& m, const Coords& xyz, index_t i, int lane, int stride,
                               Visit&& visit = {}) {
  Vec3<Real> s{0, 0, 0};
  for (index_t k = m.nbr_off[i] + lane; k < m.nbr_off[i + 1]; k += stride) {
    const index_t j = m.nbr[k];
    visit(j);
    s = s + xyz.get(j);
  }
  return s;
}

// The four corners of tet t, with node i replaced by `at`.
template <class Real, class Coords>
TS_HD void tet_corners(const MeshView& m, const Coords& xyz, index_t t, index_t i, Vec3<Real> at, Vec3<Real> (&v)[4]) {
  for (int k = 0; k < 4; ++k) {
    const index_t n = m.tets[4 * t + k];
    v[k] = n == i ? at : xyz.get(n);
  }
}

// The tet-level part of the accept rule, shared with the Form A conflict check.
template <class Real>
TS_HD bool keeps_validity(Real q_old, Real q_new) {
  return q_old > Real(0) ? q_new > Real(0) : q_new >= q_old;
}

// Quality of a node's incident tets (this lane's share) at the old position
// p and at the target.
template <class Real>
struct StarQuality {
  Real old_min, new_min;
  bool valid;  // every tet keeps its validity (keeps_validity)
};

template <class Real>
TS_HD StarQuality<Real> merge(StarQuality<Real> a, StarQuality<Real> b) {
  return {a.old_min < b.old_min ? a.old_min : b.old_min, a.new_min < b.new_min ? a.new_min : b.new_min,
          a.valid && b.valid};
}

// A tet's radius ratio with node i at `at` (the tet's own corner order).
template <class Real, class Coords>
TS_HD Real tet_quality_with(const MeshView& m, const Coords& xyz, index_t t, index_t i, Vec3<Real> at) {
  Vec3<Real> v[4];
  tet_corners(m, xyz, t, i, at, v);
  return radius_ratio(v[0], v[1], v[2], v[3]);
}

// Where star_quality gets a tet's quality with the node where it stands now:
// recomputed from the coordinates (the reference, every backend), or read
// from a per-tet cache that the caller keeps current (the GPU coloured loop;
// see kernels/cuda/coloured_loop_kernel.cuh).
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

// Does nothing with a tet's quality at the target (see star_quality).
struct IgnoreNewQuality {
  template <class Real>
  TS_HD void operator()(index_t, Real) const {}
};

// `keep_new(k, q)` receives the quality q at the target of the tet at
// incidence entry k, for a caller that stores what it may need again.
#ifdef __CUDACC__
#pragma nv_exec_check_disable
#endif
template <class Real, class Coords, class OldQuality = FreshOldQuality, class KeepNew = IgnoreNewQuality>
TS_HD StarQuality<Real> star_quality(const MeshView& m, const Coords& xyz, index_t i, Vec3<Real> p, Vec3<Real> target,
                                     int lane, int stride, const OldQuality& old_quality = {},
                                     KeepNew&& keep_new = {}) {
  StarQuality<Real> sq{Real(2), Real(2), true};
  for (index_t k = m.inc_off[i] + lane; k < m.inc_off[i + 1]; k += stride) {
    const index_t t = m.inc[k];
    const Real q_old = old_quality(m, xyz, t, i, p);
    const Real q_new = tet_quality_with(m, xyz, t, i, target);
    keep_new(k, q_new);
    sq = merge(sq, StarQuality<Real>{q_old, q_new, keeps_validity(q_old, q_new)});
  }
  return sq;
}

// The decision, once the centroid and the star's quality are known.
template <class Real, bool kAdaptive>
TS_HD NodeMove<Real> decide_move(Vec3<Real> p, Vec3<Real> target, StarQuality<Real> sq) {
  NodeMove<Real> mv;
  mv.target = target;
  mv.displacement2 = norm2(target - p);
  mv.old_min = kAdaptive ? sq.old_min : Real(1);
  mv.new_min = kAdaptive ? sq.new_min : Real(1);
  mv.accept = !kAdaptive || (sq.valid && sq.new_min > sq.old_min);
  return mv;
}

// One node, start to finish, on one thread (the CPU and SingleBlock).
template <class Real, bool kAdaptive, class Coords>
TS_HD NodeMove<Real> evaluate_node(const MeshView& m, const Coords& xyz, index_t i) {
  const Vec3<Real> p = xyz.get(i);
  const Real inv_degree = Real(1) / Real(m.nbr_off[i + 1] - m.nbr_off[i]);
  const Vec3<Real> target = inv_degree * neighbour_sum<Real>(m, xyz, i, 0, 1);
  const StarQuality<Real> sq =
      kAdaptive ? star_quality(m, xyz, i, p, target, 0, 1) : StarQuality<Real>{Real(1), Real(1), true};
  return decide_move<Real, kAdaptive>(p, target, sq);
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
