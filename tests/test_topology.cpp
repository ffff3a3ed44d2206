// CPU topology against brute force: neighbours, incidence, boundary, movable.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "mesh/topology.hpp"
#include "test_meshes.hpp"

namespace tetsmooth {
namespace {

// Neighbours as sets, straight from the definition: nodes sharing a tet.
std::vector<std::set<index_t>> brute_neighbours(const TetMesh& m) {
  std::vector<std::set<index_t>> nb(m.num_nodes());
  for (std::size_t t = 0; t < m.num_tets(); ++t)
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        if (m.tets[4 * t + a] != m.tets[4 * t + b]) nb[m.tets[4 * t + a]].insert(m.tets[4 * t + b]);
  return nb;
}

// A face is on the boundary when one tet uses it; tets with the same node
// set are one tet, however often they are listed.
std::vector<std::uint8_t> brute_boundary(const TetMesh& m) {
  std::map<std::set<index_t>, std::set<std::set<index_t>>> users;
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    const std::set<index_t> tet(m.tets.begin() + 4 * t, m.tets.begin() + 4 * t + 4);
    for (int skip = 0; skip < 4; ++skip) {
      std::set<index_t> f;
      for (int k = 0; k < 4; ++k)
        if (k != skip) f.insert(m.tets[4 * t + k]);
      users[f].insert(tet);
    }
  }
  std::vector<std::uint8_t> b(m.num_nodes(), 0);
  for (const auto& [face, tets] : users)
    if (tets.size() == 1)
      for (index_t n : face) b[n] = 1;
  return b;
}

void expect_matches_brute_force(const TetMesh& m, const Topology& topo) {
  const auto nb = brute_neighbours(m);
  ASSERT_EQ(topo.neighbours.rows(), m.num_nodes());
  for (std::size_t i = 0; i < m.num_nodes(); ++i) {
    std::vector<index_t> row(topo.neighbours.row_begin(i), topo.neighbours.row_end(i));
    EXPECT_EQ(row, std::vector<index_t>(nb[i].begin(), nb[i].end())) << "node " << i;
    // Symmetry: j in row(i) <=> i in row(j).
    for (index_t j : row) EXPECT_TRUE(std::binary_search(topo.neighbours.row_begin(j), topo.neighbours.row_end(j), index_t(i)));
  }
  std::vector<std::vector<index_t>> inc(m.num_nodes());
  for (std::size_t t = 0; t < m.num_tets(); ++t)
    for (int k = 0; k < 4; ++k) {
      std::vector<index_t>& row = inc[m.tets[4 * t + k]];
      if (row.empty() || row.back() != static_cast<index_t>(t)) row.push_back(static_cast<index_t>(t));  // once a tet
    }
  for (std::size_t i = 0; i < m.num_nodes(); ++i)
    EXPECT_EQ(std::vector<index_t>(topo.node_tets.row_begin(i), topo.node_tets.row_end(i)), inc[i]) << "node " << i;
  EXPECT_EQ(topo.boundary, brute_boundary(m));
}

// On one thread, the serial reference, and on several, whose tables must be
// the same: 2 and 3 split the tets and rows unevenly, 64 leaves runs empty
// on the smaller meshes, and 0 takes every core.
void expect_matches_brute_force(const TetMesh& m) {
  for (int threads : {1, 2, 3, 64, 0}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    expect_matches_brute_force(m, build_topology(m, threads));
  }
}

TEST(Topology, SingleTet) {
  const TetMesh m = testing::regular_tet();
  expect_matches_brute_force(m);
  const Topology topo = build_topology(m);
  EXPECT_EQ(topo.boundary, std::vector<std::uint8_t>(4, 1));
  EXPECT_EQ(topo.movable, std::vector<std::uint8_t>(4, 0));
}

TEST(Topology, CubeWithCentreHasOneInteriorNode) {
  const TetMesh m = testing::cube_with_centre();
  expect_matches_brute_force(m);
  const Topology topo = build_topology(m);
  EXPECT_EQ(topo.neighbours.row_size(8), 8);
  EXPECT_EQ(topo.node_tets.row_size(8), 12);
  EXPECT_EQ(topo.movable[8], 1);
  EXPECT_EQ(std::count(topo.movable.begin(), topo.movable.end(), 1), 1);
  // The centre's rows alone: the corners' are read by no sweep.
  const MovableRows rows = movable_rows(topo);
  EXPECT_EQ(rows.nodes, 1u);
  EXPECT_EQ(rows.neighbour_entries, 8u);
  EXPECT_EQ(rows.incidence_entries, 12u);
}

TEST(Topology, LatticeInteriorCounts) {
  const TetMesh m = testing::cube_grid(4, 0.2);
  expect_matches_brute_force(m);
  const Topology topo = build_topology(m);
  // (n+1)^3 nodes of which (n-1)^3 are interior, each with 14 neighbours
  // and 24 tets in the Kuhn lattice.
  EXPECT_EQ(std::count(topo.boundary.begin(), topo.boundary.end(), 0), 27);
  const MovableRows rows = movable_rows(topo);
  EXPECT_EQ(rows.nodes, 27u);
  EXPECT_EQ(rows.neighbour_entries, 27u * 14);
  EXPECT_EQ(rows.incidence_entries, 27u * 24);
}

TEST(Topology, RandomDelaunayMeshes) {
  for (std::uint64_t seed : {1u, 2u, 3u}) expect_matches_brute_force(testing::random_delaunay(400, seed));
}

TEST(Topology, UnreferencedAndPinnedNodesNeverMove) {
  TetMesh m = testing::cube_with_centre();
  m.xyz.insert(m.xyz.end(), {5, 5, 5});  // node 9: in no tet
  Topology topo = build_topology(m);
  EXPECT_EQ(topo.neighbours.row_size(9), 0);
  EXPECT_EQ(topo.boundary[9], 0);
  EXPECT_EQ(topo.movable[9], 0);
  m.fixed.assign(10, 0);
  m.fixed[8] = 1;
  topo = build_topology(m);
  EXPECT_EQ(topo.movable[8], 0);
}

// A tet listed again, its nodes in another order or not (Gmsh's MSH 2.2
// writer repeats the tets of a volume in two physical groups), is one tet:
// the boundary stays that of the mesh listed once.
TEST(Topology, RepeatedTetsKeepTheBoundary) {
  const TetMesh once = testing::cube_with_centre();
  TetMesh twice = once;
  for (std::size_t t = 0; t < once.num_tets(); ++t) {
    const index_t* v = &once.tets[4 * t];
    if (t % 2)
      twice.tets.insert(twice.tets.end(), v, v + 4);
    else
      twice.tets.insert(twice.tets.end(), {v[2], v[0], v[1], v[3]});
  }
  expect_matches_brute_force(twice);
  const Topology a = build_topology(once), b = build_topology(twice);
  EXPECT_EQ(b.boundary, a.boundary);
  EXPECT_EQ(b.movable, a.movable);
  EXPECT_EQ(b.movable[8], 1);
  EXPECT_EQ(b.node_tets.row_size(8), 24);
}

// A face used by a tet, its repeat and a neighbour is interior: the repeat
// must not hide the neighbour.
TEST(Topology, RepeatedTetBesideANeighbour) {
  const TetMesh once = testing::random_delaunay(300, 5);
  TetMesh some_twice = once;
  for (std::size_t t = 0; t < once.num_tets(); t += 7)
    some_twice.tets.insert(some_twice.tets.end(), once.tets.begin() + 4 * t, once.tets.begin() + 4 * t + 4);
  expect_matches_brute_force(some_twice);
  EXPECT_EQ(build_topology(some_twice).boundary, build_topology(once).boundary);
}

TEST(Topology, CountsRepeatedTets) {
  const TetMesh m = testing::cube_with_centre();
  EXPECT_EQ(count_repeated_tets(m.tets), 0u);
  std::vector<index_t> tets = m.tets;
  const index_t* v = &m.tets[0];
  tets.insert(tets.end(), {v[3], v[1], v[2], v[0]});      // tet 0 reordered
  tets.insert(tets.end(), v, v + 4);                      // and as it was
  tets.insert(tets.end(), m.tets.begin() + 4, m.tets.begin() + 8);  // tet 1 again
  EXPECT_EQ(count_repeated_tets(tets), 3u);
}

// A tet that names a node twice (a collapsed tet in a broken file) is in
// that node's row once, and gives the node no edge to itself.
TEST(Topology, TetWithARepeatedNode) {
  TetMesh m = testing::cube_with_centre();
  m.tets.insert(m.tets.end(), {8, 0, 8, 1});
  expect_matches_brute_force(m);
  const Topology topo = build_topology(m);
  EXPECT_FALSE(std::binary_search(topo.neighbours.row_begin(8), topo.neighbours.row_end(8), index_t(8)));
  EXPECT_EQ(topo.node_tets.row_size(8), 13);  // the cube's 12 tets and this one
}

// The face uses come out in the order of one sort of them all, whatever the
// node numbering (here shuffled, so that faces' lowest nodes are scattered).
TEST(Topology, FaceUsesInFullSortOrder) {
  TetMesh m = testing::random_delaunay(300, 9);
  std::vector<index_t> relabel(m.num_nodes());
  for (std::size_t i = 0; i < relabel.size(); ++i) relabel[i] = static_cast<index_t>((i * 7919) % relabel.size());
  for (index_t& v : m.tets) v = relabel[static_cast<std::size_t>(v)];
  m.tets.insert(m.tets.end(), m.tets.begin(), m.tets.begin() + 40);  // ten tets again
  std::vector<FaceUse> expected;
  for (std::size_t t = 0; t < m.num_tets(); ++t)
    for (int f = 0; f < 4; ++f) {
      FaceUse u;
      u.face = {m.tets[4 * t + kTetFaces[f][0]], m.tets[4 * t + kTetFaces[f][1]], m.tets[4 * t + kTetFaces[f][2]]};
      std::sort(u.face.begin(), u.face.end());
      u.opposite = m.tets[4 * t + f];
      u.tet = static_cast<index_t>(t);
      expected.push_back(u);
    }
  const auto key = [](const FaceUse& u) { return std::tie(u.face, u.opposite, u.tet); };
  std::sort(expected.begin(), expected.end(), [&](const FaceUse& a, const FaceUse& b) { return key(a) < key(b); });
  for (int threads : {1, 2, 5}) {
    const auto uses = sorted_face_uses(m.tets, threads);
    ASSERT_EQ(uses.size(), expected.size()) << threads << " threads";
    for (std::size_t k = 0; k < uses.size(); ++k)
      EXPECT_EQ(key(uses[k]), key(expected[k])) << "use " << k << ", " << threads << " threads";
  }
  EXPECT_EQ(count_repeated_tets(m.tets), 10u);
  expect_matches_brute_force(m);
}

// Rows finished side by side share the neighbour marks (`seen` in
// build_neighbours); with node labels scattered, rows on different threads
// meet the same neighbours, and a mark overwritten in between keeps one
// twice unless it is made unique. A lattice big enough for many chunks of
// rows a thread, built again and again, must give the serial tables.
TEST(Topology, ScatteredLabelsGiveTheSerialTablesOnManyThreads) {
  TetMesh m = testing::cube_grid(30, 0.2);
  const std::size_t n = m.num_nodes();  // 31^3, which 7919 does not divide
  for (index_t& v : m.tets) v = static_cast<index_t>((static_cast<std::size_t>(v) * 7919) % n);
  const Topology serial = build_topology(m, 1);
  for (int round = 0; round < 4; ++round)
    for (int threads : {2, 4, 0}) {
      const Topology t = build_topology(m, threads);
      ASSERT_TRUE(t.neighbours == serial.neighbours) << threads << " threads, round " << round;
      ASSERT_TRUE(t.node_tets == serial.node_tets) << threads << " threads, round " << round;
      ASSERT_EQ(t.boundary, serial.boundary) << threads << " threads, round " << round;
    }
}

// The face convention of tet_mesh.hpp: face f, opposite local vertex f, is
// listed so that its normal (b-a)x(c-a) points away from that vertex for a
// positively oriented tet. Checked on the corner tet (0,0,0), x, y, z.
TEST(Topology, TetFacesFaceOutwardOfAPositiveTet) {
  const double p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const auto sub = [](const double* a, const double* b) {
    return std::array<double, 3>{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
  };
  for (int f = 0; f < 4; ++f) {
    const double* a = p[kTetFaces[f][0]];
    const std::array<double, 3> u = sub(p[kTetFaces[f][1]], a), v = sub(p[kTetFaces[f][2]], a), w = sub(p[f], a);
    const std::array<double, 3> n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    EXPECT_LT(n[0] * w[0] + n[1] * w[1] + n[2] * w[2], 0.0) << "face " << f << " faces its own vertex";
    for (int k = 0; k < 3; ++k) EXPECT_NE(kTetFaces[f][k], f) << "face " << f << " holds its opposite vertex";
  }
}

// Csr's == is what the GPU tests compare the device tables with: two tables
// with the same items but rows cut in other places (here one row [0 1 2]
// against [0] [1 2]) are different tables and must not compare equal.
TEST(Topology, CsrEqualityComparesTheRowsNotOnlyTheItems) {
  Csr one_row, two_rows;
  one_row.offsets = {0, 3};
  one_row.items = {0, 1, 2};
  two_rows.offsets = {0, 1, 3};
  two_rows.items = {0, 1, 2};
  EXPECT_FALSE(one_row == two_rows);
  EXPECT_TRUE(one_row == one_row);
  Csr other_items = one_row;
  other_items.items = {0, 1, 3};
  EXPECT_FALSE(one_row == other_items);
}

TEST(Topology, MeanEdgeLengthOfRegularTet) {
  const TetMesh m = testing::regular_tet();
  EXPECT_NEAR(mean_edge_length(m.xyz, build_neighbours(m.tets, 4)), 1.0, 1e-12);
}

}  // namespace
}  // namespace tetsmooth
