// Material interfaces: the nodes of faces between tets of different regions
// or Gmsh volumes, and the nodes Gmsh classified on points, curves and
// surfaces inside the mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "mesh/region_interfaces.hpp"
#include "test_meshes.hpp"

namespace tetsmooth {
namespace {

// 4 x 4 x 4 unit cubes (no jitter) in two regions split at x = 2: the
// interface is the plane x = 2, 25 nodes, 9 of them off the boundary.
TetMesh two_layers() {
  TetMesh m = testing::cube_grid(4);
  for (std::size_t t = 0; t < m.num_tets(); ++t) {
    double cx = 0;
    for (int k = 0; k < 4; ++k) cx += m.xyz[3 * static_cast<std::size_t>(m.tets[4 * t + k])] / 4;
    m.extras.tet_tags.push_back(cx < 2 ? 1 : 2);
  }
  return m;
}

// The interface nodes of the plane x = 2 (kOnInterface): its 9 nodes off
// the boundary, which stays in place anyway.
std::vector<std::uint8_t> on_plane_x_2(const TetMesh& m) {
  std::vector<std::uint8_t> on(m.num_nodes(), 0);
  const auto inside = [](double c) { return c > 0 && c < 4; };
  for (std::size_t i = 0; i < m.num_nodes(); ++i)
    on[i] = m.xyz[3 * i] == 2.0 && inside(m.xyz[3 * i + 1]) && inside(m.xyz[3 * i + 2]);
  return on;
}

TEST(RegionInterfaces, ThePlaneBetweenTwoLayers) {
  const TetMesh m = two_layers();
  const std::vector<std::uint8_t> expected = on_plane_x_2(m);
  ASSERT_EQ(std::count(expected.begin(), expected.end(), kOnInterface), 9);
  EXPECT_EQ(region_interface_nodes(m), expected);
  // The face sort on several threads finds the same plane.
  for (int threads : {2, 3, 0}) EXPECT_EQ(region_interface_nodes(m, {}, threads), expected) << threads << " threads";
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

// Tets listed once per physical group whose sets of groups differ in any
// way: in the second tag only ({1,10} | {1,20}), by one set holding the
// other ({1} | {1,20}), in the first tag only ({5,30} | {7,30}). Each such
// pair of layers is two regions, the plane between them an interface; the
// same sets on both sides, in another listing order, are one region.
TEST(RegionInterfaces, TetsListedUnderTagSetsThatDifferAnywhere) {
  struct Sides {
    const char* name;
    std::vector<int> left, right;  // tags of the tets at x < 2, x > 2
    bool interface;
  };
  const Sides cases[] = {{"{1,10} | {1,20}", {1, 10}, {1, 20}, true},
                         {"{1} | {1,20}", {1}, {1, 20}, true},
                         {"{5,30} | {7,30}", {5, 30}, {7, 30}, true},
                         {"{1,20} | {20,1}", {1, 20}, {20, 1}, false}};
  const TetMesh layers = two_layers();
  const std::size_t nt = layers.num_tets();
  for (const Sides& c : cases) {
    TetMesh m = layers;
    m.tets.clear();
    m.extras.tet_tags.clear();
    for (std::size_t listing = 0; listing < std::max(c.left.size(), c.right.size()); ++listing)
      for (std::size_t t = 0; t < nt; ++t) {
        const std::vector<int>& tags = layers.extras.tet_tags[t] == 1 ? c.left : c.right;
        if (listing >= tags.size()) continue;
        m.tets.insert(m.tets.end(), layers.tets.begin() + static_cast<std::ptrdiff_t>(4 * t),
                      layers.tets.begin() + static_cast<std::ptrdiff_t>(4 * t + 4));
        m.extras.tet_tags.push_back(tags[listing]);
      }
    const std::vector<std::uint8_t> expected =
        c.interface ? on_plane_x_2(m) : std::vector<std::uint8_t>(m.num_nodes(), kNotPinned);
    EXPECT_EQ(region_interface_nodes(m), expected) << c.name;
  }
}

// Both layers in one physical group but on two Gmsh volume entities (two
// fragmented boxes in addPhysicalGroup(3, [1, 2], 7)): the plane between
// the volumes is an interface all the same, with or without region tags;
// not where the entity tags are not looked at, nor where they split no
// region.
TEST(RegionInterfaces, GmshVolumesOfOneRegion) {
  TetMesh m = two_layers();
  m.extras.tet_entity_tags.clear();
  for (int tag : m.extras.tet_tags) m.extras.tet_entity_tags.push_back(tag == 1 ? 1 : 2);
  m.extras.tet_tags.assign(m.num_tets(), 7);
  EXPECT_TRUE(tet_entities_split_regions(m));
  EXPECT_EQ(region_interface_nodes(m), on_plane_x_2(m));
  EXPECT_EQ(region_interface_nodes(m, {/*entity_tags=*/false, /*node_entities=*/true}),
            std::vector<std::uint8_t>(m.num_nodes(), kNotPinned));

  TetMesh untagged = m;
  untagged.extras.tet_tags.clear();  // MSH 4.1 without physical groups
  EXPECT_EQ(region_interface_nodes(untagged), on_plane_x_2(m));

  // One entity per region, as Gmsh files of one volume a group have: the
  // same interfaces as the region tags give.
  TetMesh layers = two_layers();
  layers.extras.tet_entity_tags = layers.extras.tet_tags;
  for (int& tag : layers.extras.tet_entity_tags) tag += 40;
  EXPECT_FALSE(tet_entities_split_regions(layers));
  EXPECT_EQ(region_interface_nodes(layers), on_plane_x_2(layers));
  m.extras.tet_entity_tags.assign(m.num_tets(), 1);
  EXPECT_FALSE(tet_entities_split_regions(m));
  EXPECT_EQ(region_interface_nodes(m), std::vector<std::uint8_t>(m.num_nodes(), kNotPinned));
}

// The tets of one volume listed once per physical group (MSH 2.2) keep
// their entity: no interface inside the volume, the plane between two
// volumes of one group still one.
TEST(RegionInterfaces, TetsListedUnderTwoTagsKeepTheirVolume) {
  TetMesh m = two_layers();
  const std::size_t nt = m.num_tets();
  std::vector<int> entity;
  for (int tag : m.extras.tet_tags) entity.push_back(tag);
  m.extras.tet_tags.assign(nt, 7);
  for (std::size_t t = 0; t < nt; ++t) {
    m.tets.insert(m.tets.end(), {m.tets[4 * t], m.tets[4 * t + 1], m.tets[4 * t + 2], m.tets[4 * t + 3]});
    m.extras.tet_tags.push_back(8);
    entity.push_back(entity[t]);
  }
  m.extras.tet_entity_tags = entity;
  EXPECT_EQ(region_interface_nodes(m), on_plane_x_2(m));
  for (int& e : m.extras.tet_entity_tags) e = 1;
  EXPECT_EQ(region_interface_nodes(m), std::vector<std::uint8_t>(m.num_nodes(), kNotPinned));
}

// A surface embedded in one volume (gmsh.model.mesh.embed), with no
// elements on it: Gmsh classifies its nodes on the surface, dimension 2.
// Those inside the mesh are features; those on the boundary (where Gmsh
// classifies every node on a surface, curve or point too) are not, nor
// are nodes the file pins, nodes in no tet, and nodes already on an
// interface.
TEST(RegionInterfaces, NodesGmshClassifiesOnSurfacesInsideTheMesh) {
  TetMesh m = testing::cube_grid(4);
  const std::size_t n = m.num_nodes();
  std::vector<std::uint8_t> expected(n, kNotPinned);
  m.extras.node_entity_dims.assign(n, 3);
  m.extras.node_entity_tags.assign(n, 1);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = m.xyz[3 * i], y = m.xyz[3 * i + 1], z = m.xyz[3 * i + 2];
    const bool boundary = x == 0 || x == 4 || y == 0 || y == 4 || z == 0 || z == 4;
    if (boundary || z == 2) m.extras.node_entity_dims[i] = 2;
    if (!boundary && z == 2) expected[i] = kOnGmshFeature;
  }
  ASSERT_EQ(std::count(expected.begin(), expected.end(), kOnGmshFeature), 9);
  EXPECT_EQ(region_interface_nodes(m), expected);
  EXPECT_EQ(region_interface_nodes(m, {/*entity_tags=*/true, /*node_entities=*/false}),
            std::vector<std::uint8_t>(n, kNotPinned));

  // A node classified on a curve but in no tet stays out; so does a node
  // the file pins.
  TetMesh more = m;
  more.xyz.insert(more.xyz.end(), {9, 9, 9});
  more.extras.node_entity_dims.push_back(1);
  more.extras.node_entity_tags.push_back(1);
  const auto pinned =
      static_cast<std::size_t>(std::find(expected.begin(), expected.end(), kOnGmshFeature) - expected.begin());
  more.fixed.assign(n + 1, 0);
  more.fixed[pinned] = 1;
  std::vector<std::uint8_t> more_expected = expected;
  more_expected[pinned] = kNotPinned;
  more_expected.push_back(kNotPinned);
  EXPECT_EQ(region_interface_nodes(more), more_expected);
  // Every such node pinned by the file: none is left.
  more.fixed.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) more.fixed[i] = m.extras.node_entity_dims[i] < 3;
  more.fixed[n] = 1;
  EXPECT_EQ(region_interface_nodes(more), std::vector<std::uint8_t>(n + 1, kNotPinned));

  // On the plane between two regions, the nodes are interface nodes.
  TetMesh layers = two_layers();
  layers.extras.node_entity_dims.assign(n, 3);
  layers.extras.node_entity_tags.assign(n, 1);
  const std::vector<std::uint8_t> plane = on_plane_x_2(layers);
  for (std::size_t i = 0; i < n; ++i)
    if (plane[i]) layers.extras.node_entity_dims[i] = 2;
  EXPECT_EQ(region_interface_nodes(layers), plane);
}

}  // namespace
}  // namespace tetsmooth
