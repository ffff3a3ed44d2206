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
    EXPECT_TRUE(is_valid_colouring(topo.neighbours, topo.movable, c));
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
  // The threads of a round decide and colour its nodes in any order: the
  // colouring must not depend on their number.
  for (int threads : {2, 3, 0}) {
    const Colouring c = colour_nodes(topo.neighbours, topo.movable, threads);
    EXPECT_EQ(c.colour, a.colour) << threads << " threads";
    EXPECT_EQ(c.num_colours, a.num_colours) << threads << " threads";
    EXPECT_EQ(c.rounds, a.rounds) << threads << " threads";
    EXPECT_TRUE(c.classes == a.classes) << threads << " threads";
  }
  // First fit: a node of colour c > 0 has a coloured neighbour of every smaller colour.
  for (std::size_t i = 0; i < m.num_nodes(); ++i) {
    for (int lower = 0; lower < a.colour[i]; ++lower) {
      bool seen = false;
      for (const index_t* j = topo.neighbours.row_begin(i); j != topo.neighbours.row_end(i); ++j) seen |= a.colour[*j] == lower;
      EXPECT_TRUE(seen) << "node " << i << " skipped colour " << lower;
    }
  }
}

// Jones-Plassmann's first round: a movable node that goes before all its
// movable neighbours (colours_before, the priority the CUDA colouring uses
// too) wins at once and takes colour 0. With the priority read backwards the
// colouring stays valid, but is no longer the one the GPU produces.
TEST(Colouring, LocalPriorityMaximaTakeColourZero) {
  const TetMesh m = testing::random_delaunay(800, 9);
  const Topology topo = build_topology(m);
  const Colouring c = colour_nodes(topo.neighbours, topo.movable);
  std::size_t maxima = 0;
  for (std::size_t i = 0; i < m.num_nodes(); ++i) {
    if (!topo.movable[i]) continue;
    bool first = true;
    for (const index_t* j = topo.neighbours.row_begin(i); j != topo.neighbours.row_end(i); ++j)
      if (topo.movable[*j] && !colours_before(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(*j)))
        first = false;
    if (!first) continue;
    ++maxima;
    EXPECT_EQ(c.colour[i], 0) << "node " << i << " goes before all its neighbours";
  }
  EXPECT_GT(maxima, 10u) << "too few local maxima to tell";
}

TEST(Colouring, DetectsInvalidColouring) {
  const TetMesh m = testing::cube_grid(3);
  const Topology topo = build_topology(m);
  const Colouring good = colour_nodes(topo.neighbours, topo.movable);
  ASSERT_EQ(colouring_flaw(topo.neighbours, topo.movable, good), "");
  const auto flaw = [&](const Colouring& c) { return colouring_flaw(topo.neighbours, topo.movable, c); };
  const auto first = [&](bool movable) {
    return static_cast<std::size_t>(std::find(topo.movable.begin(), topo.movable.end(), movable ? 1 : 0) -
                                    topo.movable.begin());
  };
  {  // two interior neighbours with one colour, the classes rebuilt to match
    Colouring c = good;
    const std::size_t i = first(true);
    const index_t* j = std::find_if(topo.neighbours.row_begin(i), topo.neighbours.row_end(i),
                                    [&](index_t k) { return topo.movable[k] != 0; });
    ASSERT_NE(j, topo.neighbours.row_end(i)) << "no two movable neighbours in a 3x3x3 grid";
    c.colour[*j] = c.colour[i];
    c.classes = colour_classes(c.colour, c.num_colours);
    EXPECT_NE(flaw(c).find("share colour"), std::string::npos) << flaw(c);
  }
  {  // a boundary node with a colour would be moved by the coloured sweeps
    Colouring c = good;
    c.colour[first(false)] = 0;
    c.classes = colour_classes(c.colour, c.num_colours);
    EXPECT_NE(flaw(c).find("never moves"), std::string::npos) << flaw(c);
  }
  {  // a movable node without one, or with one past num_colours
    Colouring c = good;
    c.colour[first(true)] = -1;
    EXPECT_NE(flaw(c).find("outside"), std::string::npos) << flaw(c);
    c.colour[first(true)] = good.num_colours;
    EXPECT_NE(flaw(c).find("outside"), std::string::npos) << flaw(c);
  }
  {  // classes that disagree with the colours, or a count the classes lack
    Colouring c = good;
    c.classes = Csr{};
    EXPECT_NE(flaw(c).find("classes"), std::string::npos) << flaw(c);
    c = good;
    c.num_colours += 3;
    EXPECT_NE(flaw(c).find("classes"), std::string::npos) << flaw(c);
    c = good;
    std::swap(c.classes.items.front(), c.classes.items.back());
    EXPECT_NE(flaw(c).find("classes"), std::string::npos) << flaw(c);
  }
  {  // -1 is the one mark of a node that never moves: any other negative
     // value is a colour array of some other convention
    Colouring c = good;
    c.colour[first(false)] = -2;
    EXPECT_NE(flaw(c).find("never moves"), std::string::npos) << flaw(c);
  }
  {  // a colour array of another mesh
    Colouring c = good;
    c.colour.pop_back();
    EXPECT_NE(flaw(c).find("nodes"), std::string::npos) << flaw(c);
  }
}

}  // namespace
}  // namespace tetsmooth
