#include "test_meshes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "generators/models.hpp"
#include "mesh/topology.hpp"

namespace tetsmooth::testing {

TetMesh regular_tet() {
  TetMesh m;
  const double h = 0.8164965809277260;  // sqrt(2/3): height of the unit-edge regular tet
  m.xyz = {0, 0, 0, 1, 0, 0, 0.5, 0.8660254037844386, 0, 0.5, 0.2886751345948129, h};
  m.tets = {0, 1, 2, 3};
  return m;
}

TetMesh cube_grid(int n, double jitter, std::uint64_t seed) { return generate_lattice(n, jitter, seed); }

TetMesh with_midsides(TetMesh mesh) {
  std::map<std::pair<index_t, index_t>, index_t> node_of_edge;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (const auto& edge : kTetEdges) {
      const index_t a = mesh.tets[4 * t + edge[0]], b = mesh.tets[4 * t + edge[1]];
      const auto [it, added] =
          node_of_edge.try_emplace({std::min(a, b), std::max(a, b)}, static_cast<index_t>(mesh.num_nodes()));
      if (added)
        for (int c = 0; c < 3; ++c)
          mesh.xyz.push_back(0.5 * (mesh.xyz[3 * static_cast<std::size_t>(a) + c] +
                                    mesh.xyz[3 * static_cast<std::size_t>(b) + c]));
      mesh.midsides.push_back(it->second);
    }
  if (!mesh.fixed.empty()) mesh.fixed.resize(mesh.num_nodes(), 0);
  return mesh;
}

double largest_midside_offset(const TetMesh& mesh) {
  double worst = 0;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t)
    for (int e = 0; e < 6; ++e) {
      const auto m = static_cast<std::size_t>(mesh.midsides[6 * t + static_cast<std::size_t>(e)]);
      const auto a = static_cast<std::size_t>(mesh.tets[4 * t + kTetEdges[e][0]]);
      const auto b = static_cast<std::size_t>(mesh.tets[4 * t + kTetEdges[e][1]]);
      for (std::size_t c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(mesh.xyz[3 * m + c] - 0.5 * (mesh.xyz[3 * a + c] + mesh.xyz[3 * b + c])));
    }
  return worst;
}

TetMesh pushed_cube_grid(int n, double jitter, std::uint64_t seed, int every, double push) {
  TetMesh m = cube_grid(n, jitter, seed);
  const Topology topo = build_topology(m);
  for (std::size_t i = 0; i < m.num_nodes(); i += static_cast<std::size_t>(every))
    if (topo.movable[i]) m.xyz[3 * i] += push;
  return m;
}

TetMesh cube_with_centre(double cx, double cy, double cz) {
  TetMesh m;
  for (int k = 0; k < 8; ++k) {
    m.xyz.push_back(k & 1);
    m.xyz.push_back((k >> 1) & 1);
    m.xyz.push_back((k >> 2) & 1);
  }
  m.xyz.insert(m.xyz.end(), {cx, cy, cz});
  const index_t centre = 8;
  // The 6 faces of the cube, each split into 2 triangles; with the centre
  // each gives one positively oriented tet.
  const index_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.tets.insert(m.tets.end(), {centre, q[0], q[1], q[2]});
    m.tets.insert(m.tets.end(), {centre, q[0], q[2], q[3]});
  }
  return m;
}

TetMesh random_delaunay(int points, std::uint64_t seed) { return generate_box_delaunay(0, points, seed); }

const char* data_path(const char* name) {
  static thread_local std::string path;
  path = std::string(TETSMOOTH_TEST_DATA_DIR) + "/" + name;
  return path.c_str();
}

}  // namespace tetsmooth::testing

namespace tetsmooth::testing {

TetMesh concave_star() {
  TetMesh m = cube_with_centre();
  // Found by a random search over distorted cube stars: every tet is valid,
  // but the neighbour centroid inverts one of them.
  m.xyz = {-0.84, -0.56, 0.31, 1.13, -0.61, 0.81, -0.62, 1.02, -0.64, 1.39, 0.6,  -0.66, -0.82, -0.59, 0.45,
           1.07,  -0.09, 1.82, 0.82, 1.53,  1.31, 1.62,  1.79, 0.14,  0.12, 0.36, 0.09};
  return m;
}

}  // namespace tetsmooth::testing
