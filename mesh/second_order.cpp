#include "mesh/second_order.hpp"

#include "mesh/errors.hpp"
#include "mesh/vec3.hpp"

namespace tetsmooth {
namespace {

Vec3<double> point(const std::vector<double>& xyz, index_t n) {
  const double* p = &xyz[3 * static_cast<std::size_t>(n)];
  return {p[0], p[1], p[2]};
}

bool straight(const TetMesh& mesh, index_t a, index_t b, index_t m) {
  const Vec3<double> pa = point(mesh.xyz, a), pb = point(mesh.xyz, b);
  const Vec3<double> off = point(mesh.xyz, m) - 0.5 * (pa + pb);
  return norm2(off) <= kStraightEdgeTolerance * kStraightEdgeTolerance * norm2(pb - pa);
}

}  // namespace

CurvedTetPins curved_tet_pins(const TetMesh& mesh) {
  CurvedTetPins pins;
  if (mesh.midsides.empty()) return pins;
  pins.corners.assign(mesh.num_nodes(), 0);
  const auto pinned = [&](index_t n) { return !mesh.fixed.empty() && mesh.fixed[static_cast<std::size_t>(n)]; };
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    const index_t* v = &mesh.tets[4 * t];
    const index_t* m = &mesh.midsides[6 * t];
    bool curved = false;
    for (int e = 0; e < 6; ++e) {
      const index_t a = v[kTetEdges[e][0]], b = v[kTetEdges[e][1]];
      curved = curved || !straight(mesh, a, b, m[e]);
      if (pinned(m[e])) pins.corners[static_cast<std::size_t>(a)] = pins.corners[static_cast<std::size_t>(b)] = 1;
    }
    if (!curved) continue;
    ++pins.tets;
    for (int k = 0; k < 4; ++k) pins.corners[static_cast<std::size_t>(v[k])] = 1;
  }
  return pins;
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

void check_first_order_output(const TetMesh& mesh, const std::string& format) {
  if (!mesh.midsides.empty())
    throw OutputError(format + " output holds 4-node tets only; write MSH, VTU or VTK to keep the 10-node tets");
}

}  // namespace tetsmooth
