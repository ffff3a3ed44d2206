#include "mesh/second_order.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/errors.hpp"
#include "mesh/tet_quality.hpp"
#include "mesh/vec3.hpp"

namespace tetsmooth {
namespace {

constexpr double kLargestRounding = 1e-2;  // of an edge's length, see straight()

Vec3<double> point(const std::vector<double>& xyz, index_t n) {
  const double* p = &xyz[3 * static_cast<std::size_t>(n)];
  return {p[0], p[1], p[2]};
}

double largest_magnitude(Vec3<double> p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}); }

// Each coordinate is off by at most half a step or `relative` of itself,
// so a midside node's offset from the midpoint by at most twice that in
// each component; the bound is doubled again for margin. At most a hundredth of
// the edge is put down to rounding, so that a coarse mesh of exact values
// (a unit lattice's midside nodes are multiples of 0.1) still shows its
// curved edges.
bool straight(const TetMesh& mesh, CoordinateResolution res, index_t a, index_t b, index_t m) {
  const Vec3<double> pa = point(mesh.xyz, a), pb = point(mesh.xyz, b), pm = point(mesh.xyz, m);
  const double offset = std::sqrt(norm2(pm - 0.5 * (pa + pb))), length = std::sqrt(norm2(pb - pa));
  const double size = std::max({largest_magnitude(pa), largest_magnitude(pb), largest_magnitude(pm)});
  const double rounding = 2 * std::sqrt(3.0) * (res.step + 2 * res.relative * size);
  return offset <= kStraightEdgeTolerance * length + std::min(rounding, kLargestRounding * length);
}

// Whether every value is a whole multiple of `step` (to a thousandth of a
// step, past double's own rounding of the product).
bool multiples_of(const std::vector<double>& values, double step) {
  for (double v : values) {
    const double q = v / step;
    if (std::abs(q - std::nearbyint(q)) > 1e-3) return false;
  }
  return true;
}

// Whether every value has at most `digits` significant decimal digits.
bool significant_digits(const std::vector<double>& values, int digits) {
  for (double v : values) {
    if (v == 0) continue;
    const double q = v / std::pow(10.0, std::floor(std::log10(std::abs(v))) - digits + 1);
    if (std::abs(q - std::nearbyint(q)) > 1e-3) return false;
  }
  return true;
}

}  // namespace

CoordinateResolution coordinate_resolution(const std::vector<double>& xyz) {
  CoordinateResolution res;
  const auto in_float = [](double v) {
    return std::abs(v) <= std::numeric_limits<float>::max() && static_cast<double>(static_cast<float>(v)) == v;
  };
  if (std::all_of(xyz.begin(), xyz.end(), in_float)) res.relative = 0x1p-24;
  // Fewest digits first; a file of full double precision fails each count
  // within its first few values. Past 12 digits the rounding is too small
  // to matter.
  for (int digits = 1; digits <= 12; ++digits)
    if (significant_digits(xyz, digits)) {
      res.relative = std::max(res.relative, 0.5 * std::pow(10.0, 1 - digits));
      break;
    }
  // Coarsest first, so that the step found is the largest that fits; a
  // file of full double precision fails each within its first few values.
  for (double step = 1; step >= 0.99e-9; step /= 10)
    if (multiples_of(xyz, step)) {
      res.step = step;
      break;
    }
  return res;
}

CurvedTetPins curved_tet_pins(const TetMesh& mesh) {
  CurvedTetPins pins;
  if (mesh.midsides.empty()) return pins;
  pins.corners.assign(mesh.num_nodes(), 0);
  const CoordinateResolution res = coordinate_resolution(mesh.xyz);
  const auto pinned = [&](index_t n) { return !mesh.fixed.empty() && mesh.fixed[static_cast<std::size_t>(n)]; };
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    const index_t* v = &mesh.tets[4 * t];
    const index_t* m = &mesh.midsides[6 * t];
    bool curved = false;
    for (int e = 0; e < 6; ++e) {
      const index_t a = v[kTetEdges[e][0]], b = v[kTetEdges[e][1]];
      curved = curved || !straight(mesh, res, a, b, m[e]);
      if (pinned(m[e])) pins.corners[static_cast<std::size_t>(a)] = pins.corners[static_cast<std::size_t>(b)] = 1;
    }
    if (!curved) continue;
    ++pins.tets;
    for (int k = 0; k < 4; ++k) pins.corners[static_cast<std::size_t>(v[k])] = 1;
  }
  return pins;
}

namespace {

// A tet's corners and its midside nodes' offsets from their edges'
// midpoints: x(λ) = Σ λ_i x_i + Σ_e 4 λ_a λ_b offset_e, the quadratic map
// in barycentric coordinates λ.
struct QuadraticTet {
  Vec3<double> corner[4];
  Vec3<double> offset[6];
  bool straight = true;  // every offset exactly zero
};

QuadraticTet quadratic_tet(const TetMesh& mesh, const std::vector<double>& xyz, std::size_t t) {
  QuadraticTet q;
  for (int k = 0; k < 4; ++k) q.corner[k] = point(xyz, mesh.tets[4 * t + static_cast<std::size_t>(k)]);
  for (int e = 0; e < 6; ++e) {
    const Vec3<double> m = point(xyz, mesh.midsides[6 * t + static_cast<std::size_t>(e)]);
    q.offset[e] = m - 0.5 * (q.corner[kTetEdges[e][0]] + q.corner[kTetEdges[e][1]]);
    q.straight = q.straight && q.offset[e].x == 0 && q.offset[e].y == 0 && q.offset[e].z == 0;
  }
  return q;
}

// det(dx/d(r,s,t)) at barycentric coordinates l, with λ1..λ3 = r, s, t and
// λ0 = 1 - r - s - t.
double jacobian_at(const QuadraticTet& q, const double (&l)[4]) {
  static constexpr double kGrad[4][3] = {{-1, -1, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Vec3<double> column[3];
  for (int j = 0; j < 3; ++j) {
    column[j] = q.corner[j + 1] - q.corner[0];
    for (int e = 0; e < 6; ++e) {
      const int a = kTetEdges[e][0], b = kTetEdges[e][1];
      column[j] = column[j] + 4 * (kGrad[a][j] * l[b] + l[a] * kGrad[b][j]) * q.offset[e];
    }
  }
  return dot(column[0], cross(column[1], column[2]));
}

}  // namespace

double smallest_jacobian(const TetMesh& mesh, const std::vector<double>& xyz, std::size_t t) {
  const QuadraticTet q = quadratic_tet(mesh, xyz, t);
  constexpr double kA = 0.5854101966249685, kB = 0.1381966011250105;  // the 4-point Gauss rule
  static constexpr double kPoints[15][4] = {
      {1, 0, 0, 0},     {0, 1, 0, 0},     {0, 0, 1, 0},     {0, 0, 0, 1},     {.5, .5, 0, 0},
      {0, .5, .5, 0},   {.5, 0, .5, 0},   {.5, 0, 0, .5},   {0, .5, 0, .5},   {0, 0, .5, .5},
      {.25, .25, .25, .25}, {kA, kB, kB, kB}, {kB, kA, kB, kB}, {kB, kB, kA, kB}, {kB, kB, kB, kA}};
  double smallest = jacobian_at(q, kPoints[0]);
  for (const auto& l : kPoints) smallest = std::min(smallest, jacobian_at(q, l));
  return smallest;
}

bool exactly_straight(const TetMesh& mesh, const std::vector<double>& xyz, std::size_t t) {
  return quadratic_tet(mesh, xyz, t).straight;
}

std::vector<std::size_t> folded_tets(const TetMesh& mesh, const std::vector<double>& before) {
  std::vector<std::size_t> folded;
  for (std::size_t t = 0; t < mesh.num_tets() && !mesh.midsides.empty(); ++t) {
    if (exactly_straight(mesh, before, t)) continue;
    if (smallest_jacobian(mesh, before, t) > 0 && !(smallest_jacobian(mesh, mesh.xyz, t) > 0)) folded.push_back(t);
  }
  return folded;
}

void carry_midside_nodes(TetMesh& mesh, const std::vector<double>& before) {
  std::vector<std::uint8_t> done(mesh.num_nodes(), 0);
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    const index_t* v = &mesh.tets[4 * t];
    for (int e = 0; e < 6; ++e) {
      const auto m = static_cast<std::size_t>(mesh.midsides[6 * t + static_cast<std::size_t>(e)]);
      if (done[m]) continue;  // an edge shared by several tets moves its node once
      done[m] = 1;
      const Vec3<double> a = point(mesh.xyz, v[kTetEdges[e][0]]) - point(before, v[kTetEdges[e][0]]);
      const Vec3<double> b = point(mesh.xyz, v[kTetEdges[e][1]]) - point(before, v[kTetEdges[e][1]]);
      if (a.x == 0 && a.y == 0 && a.z == 0 && b.x == 0 && b.y == 0 && b.z == 0) continue;
      const Vec3<double> moved = point(before, static_cast<index_t>(m)) + 0.5 * (a + b);
      mesh.xyz[3 * m] = moved.x;
      mesh.xyz[3 * m + 1] = moved.y;
      mesh.xyz[3 * m + 2] = moved.z;
    }
  }
}

void append_file_tet(TetMesh& mesh, const index_t* nodes, bool ten, const MidsidePlaces& places) {
  mesh.tets.insert(mesh.tets.end(), nodes, nodes + 4);
  if (ten)
    for (int place : places) mesh.midsides.push_back(nodes[place]);
}

void file_tet10(const TetMesh& mesh, std::size_t t, const MidsidePlaces& places, index_t* out) {
  std::copy(&mesh.tets[4 * t], &mesh.tets[4 * t] + 4, out);
  for (int e = 0; e < 6; ++e) out[places[e]] = mesh.midsides[6 * t + static_cast<std::size_t>(e)];
}

std::size_t turn_left_handed_tets(TetMesh& mesh) {
  // Swapping corners 1 and 2 swaps the tet's edges 0 and 2, and 4 and 5
  // (kTetEdges).
  constexpr int kTurnedEdges[6] = {2, 1, 0, 3, 5, 4};
  std::size_t turned = 0;
  const auto at = [&](index_t n) {
    const double* p = &mesh.xyz[3 * static_cast<std::size_t>(n)];
    return Vec3<double>{p[0], p[1], p[2]};
  };
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    index_t* c = &mesh.tets[4 * t];
    if (signed_volume6(at(c[0]), at(c[1]), at(c[2]), at(c[3])) >= 0) continue;
    std::swap(c[1], c[2]);
    if (!mesh.midsides.empty()) {
      index_t m[6];
      std::copy_n(&mesh.midsides[6 * t], 6, m);
      for (std::size_t e = 0; e < 6; ++e) mesh.midsides[6 * t + e] = m[kTurnedEdges[e]];
    }
    ++turned;
  }
  return turned;
}

std::string mixed_tet_kinds(int nodes) {
  return std::string(nodes == 4 ? "a 4-node tet after 10-node ones" : "a 10-node tet after 4-node ones") +
         ": tetsmooth reads meshes of 4-node or of 10-node tets, not both";
}

void mark_midsides_of_marked_edges(const TetMesh& mesh, std::vector<std::uint8_t>& flags) {
  for (std::size_t t = 0; t < mesh.num_tets() && !mesh.midsides.empty(); ++t)
    for (int e = 0; e < 6; ++e)
      if (flags[static_cast<std::size_t>(mesh.tets[4 * t + kTetEdges[e][0]])] &&
          flags[static_cast<std::size_t>(mesh.tets[4 * t + kTetEdges[e][1]])])
        flags[static_cast<std::size_t>(mesh.midsides[6 * t + static_cast<std::size_t>(e)])] = 1;
}

void check_first_order_output(const TetMesh& mesh, const std::string& format) {
  if (!mesh.midsides.empty())
    throw OutputError(format +
                      " output holds 4-node tets only; write MSH, VTU, VTK, TetGen, Abaqus, Nastran, Exodus, ANSYS or LS-DYNA to keep the 10-node tets");
}

}  // namespace tetsmooth
