// Jones-Plassmann colouring: valid, deterministic, only movable nodes.
#include <gtest/gtest.h>

#include <algorithm>

#include "mesh/colouring.hpp"
#include "mesh/topology.hpp"
#include "test_meshes.hpp"

namespace tetsmooth {
namespace {

TEST(Colouring, ValidOnMeshes) {
  for (const TetMesh& m : {testing::cube_grid(6, 0.2), testing::random_delaunay(1500, 5)}) {
    const Topology topo = build_topology(m);
    const Colouring c = colour_nodes(topo.neighbours, topo.movable);
    EXPECT_TRUE(is_valid_colouring(topo.neighbours, topo.movable, c.colour));
    EXPECT_GT(c.num_colours, 1);
    EXPECT_LT(c.num_colours, 40) << "first fit should need few colours on a tet mesh";
    EXPECT_GE(c.rounds, c.num_colours > 0 ? 1 : 0);
    for (std::size_t i = 0; i < m.num_nodes(); ++i) EXPECT_EQ(c.colour[i] >= 0, topo.movable[i] != 0) << i;
    // Classes list each coloured node once, ascending within a class.
    ASSERT_EQ(c.classes.rows(), static_cast<std::size_t>(c.num_colours));
    EXPECT_EQ(c.classes.items.size(), static_cast<std::size_t>(std::count(topo.movable.begin(), topo.movable.end(), 1)));
    for (int k = 0; k < c.num_colours; ++k) {
      EXPECT_TRUE(std::is_sorted(c.classes.row_begin(k), c.classes.row_end(k)));
      for (const index_t* n = c.classes.row_begin(k); n != c.classes.row_end(k); ++n) EXPECT_EQ(c.colour[*n], k);
    }
  }
}

TEST(Colouring, DeterministicAndFirstFit) {
  const TetMesh m = testing::random_delaunay(800, 9);
  const Topology topo = build_topology(m);
  const Colouring a = colour_nodes(topo.neighbours, topo.movable);
  const Colouring b = colour_nodes(topo.neighbours, topo.movable);
  EXPECT_EQ(a.colour, b.colour);
  // First fit: a node of colour c > 0 has a coloured neighbour of every smaller colour.
  for (std::size_t i = 0; i < m.num_nodes(); ++i) {
    for (int lower = 0; lower < a.colour[i]; ++lower) {
      bool seen = false;
      for (const index_t* j = topo.neighbours.row_begin(i); j != topo.neighbours.row_end(i); ++j) seen |= a.colour[*j] == lower;
      EXPECT_TRUE(seen) << "node " << i << " skipped colour " << lower;
    }
  }
}

TEST(Colouring, DetectsInvalidColouring) {
  const TetMesh m = testing::cube_grid(3);
  const Topology topo = build_topology(m);
  Colouring c = colour_nodes(topo.neighbours, topo.movable);
  ASSERT_TRUE(is_valid_colouring(topo.neighbours, topo.movable, c.colour));
  // Give two interior neighbours the same colour.
  for (std::size_t i = 0; i < m.num_nodes(); ++i) {
    if (!topo.movable[i]) continue;
    for (const index_t* j = topo.neighbours.row_begin(i); j != topo.neighbours.row_end(i); ++j)
      if (topo.movable[*j]) {
        c.colour[*j] = c.colour[i];
        EXPECT_FALSE(is_valid_colouring(topo.neighbours, topo.movable, c.colour));
        return;
      }
  }
  FAIL() << "no two movable neighbours in a 3x3x3 grid";
}

}  // namespace
}  // namespace tetsmooth
