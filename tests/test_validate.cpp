// validate_mesh: shape and range errors are InputErrors that name the source
// and the offending tet or node; inverted, degenerate and unreferenced
// entities are counted, not rejected.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "mesh/errors.hpp"
#include "mesh/validate.hpp"
#include "support/test_meshes.hpp"
#include "input_error.hpp"

namespace tetsmooth {
namespace {

// The message of the InputError that validation throws, or a test failure.
std::string validation_error(const TetMesh& mesh) {
  return testing::input_error_message([&] { validate_mesh(mesh, "part.vtu"); }, "validate_mesh, the mesh");
}

TEST(Validate, ValidMeshesPassWithNothingCounted) {
  for (const TetMesh& mesh : {testing::regular_tet(), testing::cube_with_centre(), testing::cube_grid(3, 0.2)}) {
    const ValidationReport r = validate_mesh(mesh);
    EXPECT_EQ(r.nodes, mesh.num_nodes());
    EXPECT_EQ(r.tets, mesh.num_tets());
    EXPECT_EQ(r.inverted, 0u);
    EXPECT_EQ(r.degenerate, 0u);
    EXPECT_EQ(r.unreferenced, 0u);
  }
}

TEST(Validate, CountsInvertedTets) {
  TetMesh mesh = testing::cube_with_centre();
  std::swap(mesh.tets[4 * 3 + 1], mesh.tets[4 * 3 + 2]);  // an odd permutation flips the orientation
  std::swap(mesh.tets[4 * 7 + 0], mesh.tets[4 * 7 + 3]);
  const ValidationReport r = validate_mesh(mesh);
  EXPECT_EQ(r.inverted, 2u);
  EXPECT_EQ(r.degenerate, 0u);
}

TEST(Validate, CountsDegenerateTets) {
  TetMesh mesh = testing::regular_tet();
  mesh.xyz.insert(mesh.xyz.end(), {2, 0, 0});       // node 4, on the line through nodes 0 and 1
  mesh.tets.insert(mesh.tets.end(), {0, 1, 2, 2});  // repeated node
  mesh.tets.insert(mesh.tets.end(), {0, 1, 4, 2});  // zero volume: 0, 1, 4 collinear
  const ValidationReport r = validate_mesh(mesh);
  EXPECT_EQ(r.degenerate, 2u);
  EXPECT_EQ(r.inverted, 0u);
}

TEST(Validate, CountsUnreferencedNodes) {
  TetMesh mesh = testing::regular_tet();
  mesh.xyz.insert(mesh.xyz.end(), {5, 5, 5, 6, 6, 6});
  EXPECT_EQ(validate_mesh(mesh).unreferenced, 2u);
}

TEST(Validate, RejectsIndexOutOfRangeNamingTheTet) {
  TetMesh mesh = testing::cube_with_centre();
  mesh.tets[4 * 5 + 2] = 9;  // the mesh has nodes 0..8
  const std::string msg = validation_error(mesh);
  EXPECT_NE(msg.find("part.vtu"), std::string::npos) << msg;
  EXPECT_NE(msg.find("tet 5"), std::string::npos) << msg;
  EXPECT_NE(msg.find("node 9"), std::string::npos) << msg;
}

TEST(Validate, RejectsNegativeIndex) {
  TetMesh mesh = testing::regular_tet();
  mesh.tets[0] = -1;
  EXPECT_NE(validation_error(mesh).find("tet 0"), std::string::npos);
}

TEST(Validate, RejectsNonFiniteCoordinatesNamingTheNode) {
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    TetMesh mesh = testing::regular_tet();
    mesh.xyz[3 * 2 + 1] = bad;
    const std::string msg = validation_error(mesh);
    EXPECT_NE(msg.find("node 2"), std::string::npos) << msg;
    EXPECT_NE(msg.find("non-finite coordinate y"), std::string::npos) << msg;
  }
}

TEST(Validate, RejectsWrongArrayShapes) {
  TetMesh xyz = testing::regular_tet();
  xyz.xyz.push_back(1.0);
  EXPECT_NE(validation_error(xyz).find("multiple of 3"), std::string::npos);

  TetMesh tets = testing::regular_tet();
  tets.tets.push_back(0);
  EXPECT_NE(validation_error(tets).find("multiple of 4"), std::string::npos);

  TetMesh fixed = testing::regular_tet();
  fixed.fixed.assign(3, 0);
  EXPECT_NE(validation_error(fixed).find("fixed"), std::string::npos);

  TetMesh tags = testing::regular_tet();
  tags.extras.tet_tags = {1, 2};
  EXPECT_NE(validation_error(tags).find("tet tag"), std::string::npos);

  TetMesh attrs = testing::regular_tet();
  attrs.extras.tet_attribute_count = 2;
  attrs.extras.tet_attributes = {0.5, 1, 2};
  EXPECT_NE(validation_error(attrs).find("tet attribute array has 3 values, expected 2 per tet"), std::string::npos);
}

// Every per-node and per-tet array of the extras is checked against its own
// count: the writers index them by node or by tet, so one of another length
// would be read past its end (regular_tet: 4 nodes, 1 tet).
TEST(Validate, RejectsExtrasArraysOfTheWrongLength) {
  TetMesh node_tags = testing::regular_tet();
  node_tags.extras.node_tags = {1, 2, 3};
  EXPECT_NE(validation_error(node_tags).find("node tag array has 3 entries for 4 nodes"), std::string::npos);

  TetMesh markers = testing::regular_tet();
  markers.extras.node_markers = {1, 0, 0, 1, 1};
  EXPECT_NE(validation_error(markers).find("node marker array has 5 entries for 4 nodes"), std::string::npos);

  TetMesh entities = testing::regular_tet();
  entities.extras.tet_entity_tags = {1, 1};
  EXPECT_NE(validation_error(entities).find("tet entity tag array has 2 entries for 1 tets"), std::string::npos);

  TetMesh elements = testing::regular_tet();
  elements.extras.tet_element_tags = {7, 8};
  EXPECT_NE(validation_error(elements).find("tet element tag array has 2 entries for 1 tets"), std::string::npos);

  // Node attributes go by node, not by tet: 2 a node is 8 values here.
  TetMesh attrs = testing::regular_tet();
  attrs.extras.node_attribute_count = 2;
  attrs.extras.node_attributes = {0, 1};
  EXPECT_NE(validation_error(attrs).find("node attribute array has 2 values, expected 2 per node"), std::string::npos);
  attrs.extras.node_attributes.assign(8, 0.5);
  EXPECT_NO_THROW(validate_mesh(attrs));
}

// An attribute count with no values is a mesh whose attributes were not
// kept (the writers check the size before using them): valid, as the
// comment on the arrays says ("or empty").
TEST(Validate, AcceptsAnAttributeCountWithoutValues) {
  TetMesh mesh = testing::regular_tet();
  mesh.extras.node_attribute_count = 3;
  mesh.extras.tet_attribute_count = 2;
  EXPECT_NO_THROW(validate_mesh(mesh));
}

// A pass-through block must hold whole elements, of a positive size, with a
// tag array per element where it has one (a 0-node kind would divide by
// zero), and an error names the element by its index in the block.
TEST(Validate, RejectsMalformedPassThroughBlocks) {
  TetMesh no_nodes = testing::regular_tet();
  no_nodes.extras.blocks.push_back(PassThroughBlock{"vertex", 0, {0, 1}, {}, {}, {}});
  EXPECT_NE(validation_error(no_nodes).find("not a multiple of 0"), std::string::npos);

  TetMesh partial = testing::regular_tet();
  partial.extras.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 1, 2, 1}, {}, {}, {}});
  EXPECT_NE(validation_error(partial).find("holds 4 indices, not a multiple of 3"), std::string::npos);

  for (int which = 0; which < 3; ++which) {
    TetMesh tagged = testing::regular_tet();
    PassThroughBlock b{"line", 2, {0, 1, 1, 2}, {}, {}, {}};
    if (which == 0) b.tags = {5};
    if (which == 1) b.entity_tags = {5, 5, 5};
    if (which == 2) b.element_tags = {9};
    tagged.extras.blocks.push_back(b);
    EXPECT_NE(validation_error(tagged).find("tag array that does not match its 2 elements"), std::string::npos)
        << "tag array " << which;
  }

  // Lines of 2 nodes: index 5 is element 2 (not 5 / 4 = 1, the tets' count).
  TetMesh lines = testing::regular_tet();
  lines.extras.blocks.push_back(PassThroughBlock{"line", 2, {0, 1, 1, 2, 2, 9}, {}, {}, {}});
  const std::string msg = validation_error(lines);
  EXPECT_NE(msg.find("line element 2 refers to node 9"), std::string::npos) << msg;
}

// 4 node-to-tet entries a tet under 32-bit offsets: 2^29 - 1 tets at most
// (a mesh that size is too big for a test; lattice.cpp and the .tsm reader
// refuse by this bound before allocating, and their tests show it).
TEST(Validate, MaxTetsIsWhatTheNodeToTetOffsetsHold) {
  EXPECT_EQ(max_tets(), 536870911u);
  EXPECT_LE(4 * max_tets(), static_cast<std::size_t>(std::numeric_limits<index_t>::max()));
  EXPECT_GT(4 * (max_tets() + 1), static_cast<std::size_t>(std::numeric_limits<index_t>::max()));
}

TEST(Validate, RejectsMeshWithoutTets) {
  TetMesh mesh = testing::regular_tet();
  mesh.tets.clear();
  EXPECT_NE(validation_error(mesh).find("no tetrahedra"), std::string::npos);
}

TEST(Validate, RejectsPassThroughBlockOutOfRange) {
  TetMesh mesh = testing::regular_tet();
  mesh.extras.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 1, 2, 1, 2, 4}, {}, {}, {}});
  const std::string msg = validation_error(mesh);
  EXPECT_NE(msg.find("triangle element 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("node 4"), std::string::npos) << msg;
}

}  // namespace
}  // namespace tetsmooth
