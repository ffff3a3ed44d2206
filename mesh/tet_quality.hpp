#pragma once
// Per-tet quality metrics, built by the host compiler and by nvcc alike.
//
// All metrics are signed: positive for a positively oriented tet
// ((b-a)·((c-a)×(d-a)) > 0), negative for an inverted one, 0 for a
// degenerate one, and 1 for the regular tet. They are invariant under
// translation, rotation and uniform scaling (up to rounding).
#include <cmath>
#include <limits>

#include "mesh/hd.hpp"
#include "mesh/quality_roots.hpp"
#include "mesh/vec3.hpp"

namespace tetsmooth {

// Six times the signed volume.
template <class Real>
TS_HD Real signed_volume6(Vec3<Real> a, Vec3<Real> b, Vec3<Real> c, Vec3<Real> d) {
  return dot(b - a, cross(c - a, d - a));
}

// Radius ratio q = 3 r_in / R (the paper's "aspect ratio", scaled by 3).
// With u, v, w the edges from a, V6 = u·(v×w) is six times the volume,
// v×w, w×u, u×v are twice the area vectors of the three faces at a, and
// their sum is that of the face opposite a, so 2S is the sum of the four
// norms. The circumcentre sits at N / (2 V6) from a, with
// N = |u|² v×w + |v|² w×u + |w|² u×v, so R = |N| / (2|V6|); r_in = 3V/S
// = V6 / 2S. Hence q = 6 V6² / (2S |N|), carrying the sign of V6: five
// square roots and a division (two in float, below), the per-tet cost every
// smoother pays.
//
// Two guards keep it honest where the algebra alone would not:
//  * rounding leaves V6 an error of a few eps |u||v||w|. Below a margin of
//    that (corners on a line or nearly so) every cross product is rounding
//    noise, and the quotient of noises above is not small: such a tet is
//    degenerate, q = 0;
//  * in float, N is formed scaled by 1 / max(|u|², |v|², |w|²), so its
//    squared norm stays of the order of |edge|^4 like the areas', not
//    |edge|^8: float keeps tets down to ~1e-6 of the unit box in range.
//    Double holds |edge|^8 for edges from ~1e-35 to ~1e35 in any unit, and
//    goes without the scale's division, which waits on the edges and holds
//    up |N| (the 109k model's coloured GPU smoothing took 1.88 ms against
//    1.94 with it, on an H100).
template <class Real>
TS_HD Real radius_ratio(Vec3<Real> a, Vec3<Real> b, Vec3<Real> c, Vec3<Real> d) {
  constexpr Real kNoise = Real(32) * std::numeric_limits<Real>::epsilon();
  const Vec3<Real> u = b - a, v = c - a, w = d - a;
  const Vec3<Real> vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
  const Real v6 = dot(u, vw);
  const Real uu = norm2(u), vv = norm2(v), ww = norm2(w);
  if (!(v6 * v6 > kNoise * kNoise * (uu * vv * ww))) return Real(0);  // also NaN and Inf
  const Real s =
      sizeof(Real) >= 8 ? Real(1) : quality_div(Real(1), uu > vv ? (uu > ww ? uu : ww) : (vv > ww ? vv : ww));
  const Real area2 = quality_sqrt(norm2(vw)) + quality_sqrt(norm2(wu)) + quality_sqrt(norm2(uv)) +
                     quality_sqrt(norm2(vw + wu + uv));                                   // 2 S
  const Real n = quality_sqrt(norm2((uu * s) * vw + (vv * s) * wu + (ww * s) * uv));  // |N| s
  if (!(area2 > Real(0)) || !(n > Real(0))) return Real(0);
  return quality_div(Real(6) * v6 * (v6 < Real(0) ? -v6 : v6) * s, area2 * n);
}

// Mean ratio eta = 12 (3|V|)^(2/3) / sum(l^2), signed like the volume.
template <class Real>
TS_HD Real mean_ratio(Vec3<Real> a, Vec3<Real> b, Vec3<Real> c, Vec3<Real> d) {
  using std::cbrt;
  const Real v6 = signed_volume6(a, b, c, d);
  const Real l2 = norm2(b - a) + norm2(c - a) + norm2(d - a) + norm2(c - b) + norm2(d - b) + norm2(d - c);
  if (!(l2 > Real(0))) return Real(0);
  const Real v3 = (v6 < Real(0) ? -v6 : v6) / Real(2);  // 3|V|
  const Real cb = cbrt(v3);
  const Real eta = Real(12) * cb * cb / l2;
  return v6 < Real(0) ? -eta : eta;
}

// Smallest of the six dihedral angles, in degrees (0 for a degenerate tet).
// The angle at an edge is pi minus the angle between the outward normals of
// the two faces that meet there; orientation does not change it.
template <class Real>
TS_HD Real min_dihedral_deg(Vec3<Real> a, Vec3<Real> b, Vec3<Real> c, Vec3<Real> d) {
  using std::acos;
  using std::sqrt;
  // Normals of the faces opposite a, b, c, d (all outward, or all inward).
  const Vec3<Real> n[4] = {cross(c - b, d - b), cross(d - a, c - a), cross(b - a, d - a), cross(c - a, b - a)};
  Real len[4];
  for (int f = 0; f < 4; ++f) {
    len[f] = sqrt(norm2(n[f]));
    if (!(len[f] > Real(0))) return Real(0);
  }
  Real max_cos = Real(-1);
  for (int f = 0; f < 4; ++f)
    for (int g = f + 1; g < 4; ++g) {
      const Real cosang = -dot(n[f], n[g]) / (len[f] * len[g]);
      max_cos = cosang > max_cos ? cosang : max_cos;
    }
  if (max_cos > Real(1)) max_cos = Real(1);
  return acos(max_cos) * Real(57.29577951308232);
}

}  // namespace tetsmooth
