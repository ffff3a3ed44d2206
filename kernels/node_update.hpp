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

template <class Real, class Coords>
TS_HD Vec3<Real> neighbour_centroid(const MeshView& m, const Coords& xyz, index_t i) {
  Vec3<Real> s{0, 0, 0};
  const index_t b = m.nbr_off[i], e = m.nbr_off[i + 1];
  for (index_t k = b; k < e; ++k) s = s + xyz.get(m.nbr[k]);
  return (Real(1) / Real(e - b)) * s;
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

template <class Real, bool kAdaptive, class Coords>
TS_HD NodeMove<Real> evaluate_node(const MeshView& m, const Coords& xyz, index_t i) {
  NodeMove<Real> mv;
  const Vec3<Real> p = xyz.get(i);
  mv.target = neighbour_centroid<Real>(m, xyz, i);
  const Vec3<Real> d = mv.target - p;
  mv.displacement2 = norm2(d);
  mv.old_min = mv.new_min = Real(1);
  mv.accept = true;
  if (!kAdaptive) return mv;
  Real old_min = Real(2), new_min = Real(2);
  bool valid = true;
  const index_t b = m.inc_off[i], e = m.inc_off[i + 1];
  for (index_t k = b; k < e; ++k) {
    Vec3<Real> v[4];
    tet_corners(m, xyz, m.inc[k], i, p, v);
    const Real q_old = radius_ratio(v[0], v[1], v[2], v[3]);
    tet_corners(m, xyz, m.inc[k], i, mv.target, v);
    const Real q_new = radius_ratio(v[0], v[1], v[2], v[3]);
    old_min = q_old < old_min ? q_old : old_min;
    new_min = q_new < new_min ? q_new : new_min;
    valid = valid && keeps_validity(q_old, q_new);
  }
  mv.old_min = old_min;
  mv.new_min = new_min;
  mv.accept = valid && new_min > old_min;
  return mv;
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
