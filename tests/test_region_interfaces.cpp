// Material interfaces: the nodes of faces between tets of different regions.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "mesh/region_interfaces.hpp"
#include "test_meshes.hpp"

namespace tetsmooth {
namespace {

// 4 x 4 x 4 unit cubes (no jitter) in two regions split at x = 2: the
// interface is the plane x = 2, 25 nodes.
TetMesh two_layers() {
  TetMesh m = testing::cube_grid(4);
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    double cx = 0;
    for (int k = 0; k < 4; ++k) cx += m.xyz[3 * static_cast<std::size_t>(m.tets[4 * t + k])] / 4;
    m.extras.tet_tags.push_back(cx < 2 ? 1 : 2);
  }
  return m;
}

std::vector<std::uint8_t> on_plane_x_2(const TetMesh& m) {
  std::vector<std::uint8_t> on(m.num_nodes(), 0);
  for (std::size_t i = 0; i < m.num_nodes(); ++i) on[i] = m.xyz[3 * i] == 2.0;
  return on;
}

TEST(RegionInterfaces, ThePlaneBetweenTwoLayers) {
  const TetMesh m = two_layers();
  const std::vector<std::uint8_t> expected = on_plane_x_2(m);
  ASSERT_EQ(std::count(expected.begin(), expected.end(), 1), 25);
  EXPECT_EQ(region_interface_nodes(m), expected);
}

TEST(RegionInterfaces, NoneWithoutTagsOrWithOneRegion) {
  TetMesh m = testing::cube_grid(4);
  const std::vector<std::uint8_t> none(m.num_nodes(), 0);
  EXPECT_EQ(region_interface_nodes(m), none);
  m.extras.tet_tags.assign(m.num_tets(), 7);
  EXPECT_EQ(region_interface_nodes(m), none);
}

// Gmsh's MSH 2.2 writer lists the tets of a volume in two physical groups
// twice, once under each tag: one region, no interface. The same with two
// layers keeps just the plane between them.
TEST(RegionInterfaces, TetsListedUnderTwoTagsAreOneRegion) {
  TetMesh m = testing::cube_grid(4);
  const std::size_t nt = m.num_tets();
  m.extras.tet_tags.assign(nt, 1);
  for (std::size_t t = 0; t < nt; ++t) {
    m.tets.insert(m.tets.end(), {m.tets[4 * t], m.tets[4 * t + 1], m.tets[4 * t + 2], m.tets[4 * t + 3]});
    m.extras.tet_tags.push_back(2);
  }
  EXPECT_EQ(region_interface_nodes(m), std::vector<std::uint8_t>(m.num_nodes(), 0));

  TetMesh layers = two_layers();
  const std::vector<int> tags = layers.extras.tet_tags;
  for (std::size_t t = 0; t < nt; ++t) {
    layers.tets.insert(layers.tets.end(), {layers.tets[4 * t], layers.tets[4 * t + 1], layers.tets[4 * t + 2],
                                           layers.tets[4 * t + 3]});
    layers.extras.tet_tags.push_back(tags[t] + 10);  // a second group per layer
  }
  EXPECT_EQ(region_interface_nodes(layers), on_plane_x_2(layers));
}

}  // namespace
}  // namespace tetsmooth
