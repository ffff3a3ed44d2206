// Gmsh MSH 4.1 (ASCII, binary) and 2.2: sparse tags, entities and physical
// groups, pass-through elements, exact round trips of every flavour, files
// written by the real Gmsh, partitioned files, notes on skipped sections, and
// errors that name file:line or file, byte N.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <tuple>

#include "mesh/errors.hpp"
#include "mesh/io/gmsh_detail.hpp"
#include "mesh/io/gmsh_io.hpp"
#include "mesh/io/mesh_io.hpp"
#include "mesh/io/writable_check.hpp"
#include "mesh/region_interfaces.hpp"
#include "support/scratch_dir.hpp"
#include "support/test_meshes.hpp"
#include "input_error.hpp"

namespace tetsmooth {
namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TetMesh read_text(const std::string& text, const std::string& name = "t.msh") {
  std::istringstream in(text);
  return read_gmsh(in, name);
}

std::string write_text(const TetMesh& mesh, MshFlavour flavour, const MeshFields& fields = {}) {
  std::ostringstream out;
  write_gmsh(mesh, out, flavour, fields);
  return out.str();
}

// The InputError message from reading `text` as t.msh.
std::string read_error(const std::string& text) {
  return testing::input_error_message([&] { read_text(text); }, "read_gmsh:\n" + text);
}

const std::string* raw_section(const TetMesh& mesh, const std::string& name) {
  for (const auto& [key, body] : mesh.extras.raw_sections)
    if (key == name) return &body;
  return nullptr;
}

void expect_same_blocks(const TetMesh& a, const TetMesh& b) {
  ASSERT_EQ(a.extras.blocks.size(), b.extras.blocks.size());
  for (std::size_t i = 0; i < a.extras.blocks.size(); ++i) {
    const PassThroughBlock &x = a.extras.blocks[i], &y = b.extras.blocks[i];
    EXPECT_EQ(x.kind, y.kind);
    EXPECT_EQ(x.connectivity, y.connectivity) << x.kind;
    EXPECT_EQ(x.tags, y.tags) << x.kind;
    EXPECT_EQ(x.entity_tags, y.entity_tags) << x.kind;
    EXPECT_EQ(x.element_tags, y.element_tags) << x.kind;
  }
}

// 1 block of 4 nodes (lines 5-14), one tet (lines 17-19).
const char* kMinimal =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    "$Nodes\n1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n"
    "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 4\n$EndElements\n";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

TEST(GmshIo, ReadsSparseTagsEntitiesPhysicalsAndPassThroughElements) {
  const std::string path = testing::data_path("gmsh_sparse41.msh");
  const TetMesh mesh = read_gmsh_file(path);
  // File order of the nodes: D(42) B(20) C(30) A(10) E(57).
  ASSERT_EQ(mesh.num_nodes(), 5u);
  EXPECT_EQ(mesh.extras.node_tags, (std::vector<long long>{42, 20, 30, 10, 57}));
  EXPECT_EQ(mesh.xyz, (std::vector<double>{0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0, 0, 0.3, 0.3, -1}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{3, 1, 2, 0, 3, 2, 1, 4}));
  EXPECT_EQ(mesh.extras.tet_entity_tags, (std::vector<int>{1, 2}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{7, 8}));
  EXPECT_EQ(mesh.extras.tet_element_tags, (std::vector<long long>{110, 120}));
  EXPECT_EQ(mesh.extras.node_entity_dims, (std::vector<int>{0, 2, 2, 3, 3}));
  EXPECT_EQ(mesh.extras.node_entity_tags, (std::vector<int>{1, 5, 5, 1, 2}));

  ASSERT_EQ(mesh.extras.blocks.size(), 2u);
  const PassThroughBlock& point = mesh.extras.blocks[0];
  EXPECT_EQ(point.kind, "vertex");
  EXPECT_EQ(point.connectivity, (std::vector<index_t>{0}));
  EXPECT_EQ(point.tags, (std::vector<int>{9}));
  EXPECT_EQ(point.element_tags, (std::vector<long long>{100}));
  const PassThroughBlock& tris = mesh.extras.blocks[1];
  EXPECT_EQ(tris.kind, "triangle");
  EXPECT_EQ(tris.nodes_per_element, 3);
  EXPECT_EQ(tris.connectivity, (std::vector<index_t>{1, 2, 0, 2, 1, 4}));
  EXPECT_EQ(tris.tags, (std::vector<int>{3, 3}));
  EXPECT_EQ(tris.entity_tags, (std::vector<int>{5, 5}));
  EXPECT_EQ(tris.element_tags, (std::vector<long long>{101, 102}));
  // Only A, the node of no point or triangle, may move.
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{1, 1, 1, 0, 1}));

  // Both sections are kept word for word; $Comments is skipped.
  const std::string file = slurp(path);
  ASSERT_NE(raw_section(mesh, "$Entities"), nullptr);
  ASSERT_NE(raw_section(mesh, "$PhysicalNames"), nullptr);
  EXPECT_NE(file.find("$Entities\n" + *raw_section(mesh, "$Entities") + "$EndEntities"), std::string::npos);
  EXPECT_NE(file.find("$PhysicalNames\n" + *raw_section(mesh, "$PhysicalNames") + "$EndPhysicalNames"),
            std::string::npos);
}

TEST(GmshIo, ReadsMsh22WithPhysicalAndElementaryTags) {
  const TetMesh mesh = read_gmsh_file(testing::data_path("gmsh_bipyramid22.msh"));
  EXPECT_EQ(mesh.extras.node_tags, (std::vector<long long>{10, 20, 30, 42, 57}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3, 0, 2, 1, 4}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{7, 7}));
  EXPECT_EQ(mesh.extras.tet_entity_tags, (std::vector<int>{1, 2}));
  EXPECT_EQ(mesh.extras.tet_element_tags, (std::vector<long long>{4, 5}));
  ASSERT_EQ(mesh.extras.blocks.size(), 2u);
  EXPECT_EQ(mesh.extras.blocks[0].kind, "vertex");
  EXPECT_EQ(mesh.extras.blocks[0].element_tags, (std::vector<long long>{1}));
  EXPECT_EQ(mesh.extras.blocks[1].element_tags, (std::vector<long long>{2, 3}));
  EXPECT_EQ(mesh.extras.blocks[0].tags, (std::vector<int>{0}));
  EXPECT_EQ(mesh.extras.blocks[1].tags, (std::vector<int>{3, 3}));
  EXPECT_EQ(mesh.extras.blocks[1].entity_tags, (std::vector<int>{5, 5}));
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{0, 1, 1, 1, 1}));
  EXPECT_TRUE(mesh.extras.node_entity_dims.empty());
  EXPECT_NE(raw_section(mesh, "$PhysicalNames"), nullptr);
}

// Files written by Gmsh 4 itself (tests/data/gmsh_box_make.py): the binary
// and ASCII encodings of one mesh read the same, up to the 16 significant
// digits of Gmsh's ASCII output.
TEST(GmshIo, ReadsFilesWrittenByGmsh) {
  const TetMesh ascii = read_gmsh_file(testing::data_path("gmsh_box_ascii41.msh"));
  const TetMesh binary = read_gmsh_file(testing::data_path("gmsh_box_binary41.msh"));
  const TetMesh binary22 = read_gmsh_file(testing::data_path("gmsh_box_binary22.msh"));
  // Mesh.SaveParametric: MSH 2.2 gives the nodes in $ParametricNodes.
  const TetMesh param22 = read_gmsh_file(testing::data_path("gmsh_box_param22.msh"));
  const TetMesh param_binary22 = read_gmsh_file(testing::data_path("gmsh_box_param_binary22.msh"));
  ASSERT_GT(ascii.num_tets(), 0u);
  for (const TetMesh* other : {&binary, &binary22, &param22, &param_binary22}) {
    EXPECT_EQ(other->tets, ascii.tets);
    EXPECT_EQ(other->extras.node_tags, ascii.extras.node_tags);
    EXPECT_EQ(other->extras.tet_tags, ascii.extras.tet_tags);
    EXPECT_EQ(other->fixed, ascii.fixed);
    ASSERT_EQ(other->xyz.size(), ascii.xyz.size());
    for (std::size_t i = 0; i < ascii.xyz.size(); ++i) EXPECT_NEAR(other->xyz[i], ascii.xyz[i], 1e-15);
  }
  EXPECT_EQ(ascii.extras.tet_tags, std::vector<int>(ascii.num_tets(), 7));
  ASSERT_EQ(ascii.extras.blocks.size(), 1u);
  EXPECT_EQ(ascii.extras.blocks[0].kind, "triangle");
  EXPECT_EQ(ascii.extras.blocks[0].tags, std::vector<int>(ascii.extras.blocks[0].tags.size(), 3));
  EXPECT_EQ(binary.extras.node_entity_tags, ascii.extras.node_entity_tags);
  EXPECT_EQ(*raw_section(binary, "$PhysicalNames"), *raw_section(ascii, "$PhysicalNames"));
  // The parametric coordinates of the nodes on curves and surfaces are
  // dropped with the note MSH 4.1's get; so is their classification.
  const auto& dims = ascii.extras.node_entity_dims;
  const auto on_curves_and_surfaces = std::count_if(dims.begin(), dims.end(), [](int d) { return d == 1 || d == 2; });
  ASSERT_GT(on_curves_and_surfaces, 0);
  for (const TetMesh* param : {&param22, &param_binary22}) {
    EXPECT_EQ(param->extras.read_notes,
              (std::vector<std::string>{"the parametric coordinates of " + std::to_string(on_curves_and_surfaces) +
                                        " nodes on curves and surfaces are not kept: tetsmooth writes plain node "
                                        "coordinates"}));
    EXPECT_TRUE(param->extras.node_entity_dims.empty());
    EXPECT_EQ(param->extras.tet_entity_tags, binary22.extras.tet_entity_tags);
  }
  EXPECT_TRUE(binary22.extras.read_notes.empty());
}

// tests/data/gmsh_partitioned41.msh: the bipyramid as one volume in two
// partitions. File order of the nodes: D(42) B(20) C(30) A(10) E(57).
void expect_partitions_merged(const TetMesh& mesh) {
  EXPECT_EQ(mesh.extras.node_tags, (std::vector<long long>{42, 20, 30, 10, 57}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{3, 1, 2, 0, 3, 2, 1, 4}));
  // Both tets are on partitioned volumes of volume 1, physical 7.
  EXPECT_EQ(mesh.extras.tet_entity_tags, (std::vector<int>{1, 1}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{7, 7}));
  // Nodes go to the parents: A, between the partitions, into the volume.
  EXPECT_EQ(mesh.extras.node_entity_dims, (std::vector<int>{0, 2, 2, 3, 2}));
  EXPECT_EQ(mesh.extras.node_entity_tags, (std::vector<int>{1, 5, 5, 1, 5}));
  // The line and the triangle on the partition boundary are gone; the
  // point and the outer triangles keep their physical tags.
  ASSERT_EQ(mesh.extras.blocks.size(), 2u);
  const PassThroughBlock& point = mesh.extras.blocks[0];
  EXPECT_EQ(point.kind, "vertex");
  EXPECT_EQ(point.connectivity, (std::vector<index_t>{0}));
  EXPECT_EQ(point.entity_tags, (std::vector<int>{1}));
  EXPECT_EQ(point.tags, (std::vector<int>{9}));
  EXPECT_EQ(point.element_tags, (std::vector<long long>{100}));
  const PassThroughBlock& tris = mesh.extras.blocks[1];
  EXPECT_EQ(tris.kind, "triangle");
  EXPECT_EQ(tris.connectivity, (std::vector<index_t>{1, 2, 0, 2, 1, 4}));
  EXPECT_EQ(tris.entity_tags, (std::vector<int>{5, 5}));
  EXPECT_EQ(tris.tags, (std::vector<int>{3, 3}));
  // The dropped elements' tags (103, 105) go with them.
  EXPECT_EQ(tris.element_tags, (std::vector<long long>{101, 102}));
  EXPECT_EQ(mesh.extras.tet_element_tags, (std::vector<long long>{110, 120}));
  // A is pinned by no element of the model, so it may move.
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{1, 1, 1, 0, 1}));
  EXPECT_EQ(mesh.extras.read_notes,
            (std::vector<std::string>{"the partitions are merged and 2 elements on partition boundaries dropped; "
                                      "the written file is not partitioned"}));
}

TEST(GmshIo, ReadsPartitionedFileAsOneMeshOnTheModelEntities) {
  const TetMesh mesh = read_gmsh_file(testing::data_path("gmsh_partitioned41.msh"));
  expect_partitions_merged(mesh);
  // What is written is an ordinary file on the model's own entities.
  for (MshFlavour flavour : {MshFlavour::V41Ascii, MshFlavour::V41Binary, MshFlavour::V22Ascii}) {
    const std::string text = write_text(mesh, flavour);
    EXPECT_EQ(text.find("Partitioned"), std::string::npos);
    const TetMesh back = read_text(text);
    EXPECT_EQ(back.tets, mesh.tets);
    EXPECT_EQ(back.extras.tet_tags, mesh.extras.tet_tags);
    EXPECT_EQ(back.extras.tet_entity_tags, mesh.extras.tet_entity_tags);
    EXPECT_EQ(back.fixed, mesh.fixed);
    expect_same_blocks(back, mesh);
    EXPECT_TRUE(back.extras.read_notes.empty());
    if (flavour != MshFlavour::V22Ascii) {
      EXPECT_EQ(back.extras.node_entity_dims, mesh.extras.node_entity_dims);
      EXPECT_EQ(back.extras.node_entity_tags, mesh.extras.node_entity_tags);
      EXPECT_EQ(*raw_section(back, "$Entities"), *raw_section(mesh, "$Entities"));
    }
  }
}

// A partitioned entity that names no parent ("0 0") keeps its elements and
// its physical tags; the writer makes the entities up.
TEST(GmshIo, PartitionedEntityWithoutParentKeepsItsPhysicalTags) {
  const std::string file = slurp(testing::data_path("gmsh_partitioned41.msh"));
  const std::string text = replaced(file, "\n3 3 1 1 2 ", "\n3 0 0 1 2 ");  // volume 3
  const TetMesh mesh = read_text(text);
  EXPECT_EQ(mesh.extras.tet_entity_tags, (std::vector<int>{1, 3}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{7, 7}));
  const TetMesh back = read_text(write_text(mesh, MshFlavour::V41Ascii));
  EXPECT_EQ(back.extras.tet_entity_tags, mesh.extras.tet_entity_tags);
  EXPECT_EQ(back.extras.tet_tags, mesh.extras.tet_tags);
  expect_same_blocks(back, mesh);
}

// MSH 4.1 binary values in this machine's byte order, and text lines.
class BinaryMsh {
 public:
  BinaryMsh() {
    text("$MeshFormat\n4.1 1 8");
    ints({1});
    text("\n$EndMeshFormat");
  }
  void text(const std::string& line) { bytes_ += line + "\n"; }
  void sizes(std::initializer_list<std::uint64_t> values) {
    for (std::uint64_t v : values) raw(v);
  }
  void ints(std::initializer_list<std::int32_t> values) {
    for (std::int32_t v : values) raw(v);
  }
  void reals(std::initializer_list<double> values) {
    for (double v : values) raw(v);
  }
  const std::string& bytes() const { return bytes_; }

 private:
  template <class T>
  void raw(T v) {
    bytes_.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  std::string bytes_;
};

// gmsh_partitioned41.msh in binary: the same values, the same mesh.
TEST(GmshIo, ReadsBinaryPartitionedFile) {
  BinaryMsh f;
  f.text("$Entities");
  f.sizes({1, 0, 1, 1});
  f.ints({1}), f.reals({0, 0, 1}), f.sizes({1}), f.ints({9});
  f.ints({5}), f.reals({0, 0, -1, 1, 1, 1}), f.sizes({1}), f.ints({3}), f.sizes({0});
  f.ints({1}), f.reals({0, 0, -1, 1, 1, 1}), f.sizes({1}), f.ints({7}), f.sizes({1}), f.ints({5});
  f.text("\n$EndEntities\n$PartitionedEntities");
  f.sizes({2, 1}), f.ints({4, 1});
  f.sizes({1, 1, 3, 2});
  // tag, parent dim and tag, partitions, box, physicals, bounding entities
  f.ints({2, 0, 1}), f.sizes({1}), f.ints({1}), f.reals({0, 0, 1}), f.sizes({1}), f.ints({9});
  f.ints({9, 2, 5}), f.sizes({2}), f.ints({1, 2}), f.reals({0, 0, 0, 1, 1, 0}), f.sizes({1}), f.ints({3}), f.sizes({0});
  f.ints({6, 2, 5}), f.sizes({1}), f.ints({1}), f.reals({0, 0, 0, 1, 1, 1}), f.sizes({1}), f.ints({3}), f.sizes({1}),
      f.ints({9});
  f.ints({7, 2, 5}), f.sizes({1}), f.ints({2}), f.reals({0, 0, -1, 1, 1, 0}), f.sizes({1}), f.ints({3}), f.sizes({1}),
      f.ints({-9});
  f.ints({8, 3, 1}), f.sizes({2}), f.ints({1, 2}), f.reals({0, 0, 0, 1, 1, 0}), f.sizes({1}), f.ints({7}), f.sizes({1}),
      f.ints({9});
  f.ints({2, 3, 1}), f.sizes({1}), f.ints({1}), f.reals({0, 0, 0, 1, 1, 1}), f.sizes({1}), f.ints({7}), f.sizes({2}),
      f.ints({6, 8});
  f.ints({3, 3, 1}), f.sizes({1}), f.ints({2}), f.reals({0, 0, -1, 1, 1, 0}), f.sizes({1}), f.ints({7}), f.sizes({2}),
      f.ints({7, -8});
  f.text("\n$EndPartitionedEntities\n$Nodes");
  f.sizes({4, 5, 10, 57});
  f.ints({0, 2, 0}), f.sizes({1, 42}), f.reals({0, 0, 1});
  f.ints({1, 9, 0}), f.sizes({2, 20, 30}), f.reals({1, 0, 0, 0, 1, 0});
  f.ints({2, 8, 0}), f.sizes({1, 10}), f.reals({0, 0, 0});
  f.ints({2, 7, 0}), f.sizes({1, 57}), f.reals({0.3, 0.3, -1});
  f.text("\n$EndNodes\n$Elements");
  f.sizes({7, 7, 100, 120});
  f.ints({0, 2, 15}), f.sizes({1, 100, 42});
  f.ints({1, 9, 1}), f.sizes({1, 105, 20, 30});
  f.ints({2, 6, 2}), f.sizes({1, 101, 20, 30, 42});
  f.ints({2, 7, 2}), f.sizes({1, 102, 30, 20, 57});
  f.ints({2, 8, 2}), f.sizes({1, 103, 10, 20, 30});
  f.ints({3, 2, 4}), f.sizes({1, 110, 10, 20, 30, 42});
  f.ints({3, 3, 4}), f.sizes({1, 120, 10, 30, 20, 57});
  f.text("\n$EndElements");
  const TetMesh mesh = read_text(f.bytes());
  expect_partitions_merged(mesh);
  EXPECT_EQ(mesh.xyz, read_gmsh_file(testing::data_path("gmsh_partitioned41.msh")).xyz);
}

// Sections the reader skips are named once per kind, data sections once
// per view (their first string tag, when they have one); $Comments is not.
TEST(GmshIo, SkippedSectionsAreNoted) {
  const auto data = [](const std::string& tags) {
    return "$NodeData\n" + tags + "1\n0\n3\n0\n1\n1\n1 0.5\n$EndNodeData\n";
  };
  const std::string text = std::string(kMinimal) + "$Comments\nhello\n$EndComments\n" +
                           "$Periodic\n1\n0 1 2\n0\n0\n$EndPeriodic\n" + data("1\n\"p\"\n") + data("1\n\"p\"\n") +
                           data("1\n\"pore pressure\"\n") + data("0\n") + data("0\n");
  EXPECT_EQ(read_text(text).extras.read_notes,
            (std::vector<std::string>{"$Periodic section skipped; it will not be in the written file",
                                      "$NodeData 'p' section skipped; it will not be in the written file",
                                      "$NodeData 'pore pressure' section skipped; it will not be in the written file",
                                      "$NodeData section skipped; it will not be in the written file"}));
  EXPECT_TRUE(read_text(kMinimal).extras.read_notes.empty());
  EXPECT_TRUE(read_gmsh_file(testing::data_path("gmsh_sparse41.msh")).extras.read_notes.empty());
}

// A section name is file text: the note, and the error when its end marker
// never comes, quote it escaped and cut short, one line whatever it holds.
TEST(GmshIo, EchoedSectionNamesAreOneShortEscapedLine) {
  const std::string name = "$Y\x1dY\x7f" + std::string(1 << 20, 'Y');
  const std::string excerpt = "$Y\\x1dY\\x7f" + std::string(35, 'Y') + "...";
  const TetMesh mesh = read_text(std::string(kMinimal) + name + "\n1\n$End" + name.substr(1) + "\n");
  EXPECT_EQ(mesh.extras.read_notes,
            (std::vector<std::string>{excerpt + " section skipped; it will not be in the written file"}));
  const std::string unended = read_error(std::string(kMinimal) + name + "\n1\n");
  EXPECT_NE(unended.find("unexpected end of file, expected $EndY\\x1dY\\x7f"), std::string::npos)
      << unended.substr(0, 200);
  EXPECT_LT(unended.size(), 200u);
  const std::string bad = read_error(replaced(kMinimal, "$Elements\n", "gar\x1d" "bage\n$Elements\n"));
  EXPECT_NE(bad.find("expected a section such as $Nodes, found 'gar\\x1dbage'"), std::string::npos) << bad;
  const std::string after = read_error(replaced(kMinimal, "$Elements\n", "$Elements\x1d x\n"));
  EXPECT_NE(after.find("after $Elements\\x1d"), std::string::npos) << after;
}

// The quality and boundary fields tetsmooth writes are recomputed on every
// write, so a file it wrote reads back without notes; a user's own field of
// another name, or under the other section, is still noted.
TEST(GmshIo, OwnFieldsAreNotNoted) {
  const auto data = [](const char* section, const char* name) {
    return std::string("$") + section + "\n1\n\"" + name + "\"\n1\n0\n3\n0\n1\n1\n1 0.5\n$End" + section + "\n";
  };
  EXPECT_TRUE(read_text(std::string(kMinimal) + data("ElementData", "quality") + data("NodeData", "boundary"))
                  .extras.read_notes.empty());
  EXPECT_EQ(read_text(std::string(kMinimal) + data("NodeData", "quality")).extras.read_notes.size(), 1u);
  EXPECT_EQ(read_text(std::string(kMinimal) + data("ElementData", "stress")).extras.read_notes.size(), 1u);
  // tetsmooth's own output, in every MSH flavour, with its fields.
  const testing::ScratchDir dir("gmsh");
  for (const MeshFormat f : {MeshFormat::Msh41, MeshFormat::Msh41Binary, MeshFormat::Msh22}) {
    const std::string path = dir.file("own_fields.msh");
    MeshFields fields;
    const TetMesh mesh = testing::cube_with_centre();
    fields.tet_scalars.emplace_back("quality", std::vector<double>(mesh.num_tets(), 0.5));
    fields.node_scalars.emplace_back("boundary", std::vector<double>(mesh.num_nodes(), 1.0));
    write_mesh(mesh, path, f, fields);
    EXPECT_TRUE(read_mesh(path).extras.read_notes.empty()) << format_name(f);
  }
}

class GmshRoundTrip : public ::testing::TestWithParam<MshFlavour> {};

TEST_P(GmshRoundTrip, KeepsTagsEntitiesPhysicalsAndBlocks) {
  const TetMesh mesh = read_gmsh_file(testing::data_path("gmsh_sparse41.msh"));
  const TetMesh back = read_text(write_text(mesh, GetParam()));
  EXPECT_EQ(back.xyz, mesh.xyz);
  EXPECT_EQ(back.tets, mesh.tets);
  EXPECT_EQ(back.extras.node_tags, mesh.extras.node_tags);
  EXPECT_EQ(back.extras.tet_tags, mesh.extras.tet_tags);
  EXPECT_EQ(back.extras.tet_entity_tags, mesh.extras.tet_entity_tags);
  EXPECT_EQ(back.extras.tet_element_tags, mesh.extras.tet_element_tags);
  EXPECT_EQ(back.fixed, mesh.fixed);
  expect_same_blocks(back, mesh);
  ASSERT_NE(raw_section(back, "$PhysicalNames"), nullptr);
  EXPECT_EQ(*raw_section(back, "$PhysicalNames"), *raw_section(mesh, "$PhysicalNames"));
  if (GetParam() != MshFlavour::V22Ascii) {
    EXPECT_EQ(back.extras.node_entity_dims, mesh.extras.node_entity_dims);
    EXPECT_EQ(back.extras.node_entity_tags, mesh.extras.node_entity_tags);
    ASSERT_NE(raw_section(back, "$Entities"), nullptr);
    // The fixture's numbers are written the shortest way, so even the
    // re-encoded binary entities read back as the same text.
    EXPECT_EQ(*raw_section(back, "$Entities"), *raw_section(mesh, "$Entities"));
  }
}

TEST_P(GmshRoundTrip, CoordinatesAreExact) {
  const TetMesh mesh = testing::cube_grid(3, 0.3);  // jittered: full mantissas
  const TetMesh back = read_text(write_text(mesh, GetParam()));
  EXPECT_EQ(back.xyz, mesh.xyz);
  EXPECT_EQ(back.tets, mesh.tets);
  std::vector<long long> one_to_n(mesh.num_nodes());
  for (std::size_t i = 0; i < one_to_n.size(); ++i) one_to_n[i] = static_cast<long long>(i) + 1;
  EXPECT_EQ(back.extras.node_tags, one_to_n);
  // A mesh without element tags gets 1..T.
  one_to_n.resize(mesh.num_tets());
  for (std::size_t i = 0; i < one_to_n.size(); ++i) one_to_n[i] = static_cast<long long>(i) + 1;
  EXPECT_EQ(back.extras.tet_element_tags, one_to_n);
  EXPECT_EQ(back.extras.tet_entity_tags, std::vector<int>(mesh.num_tets(), 1));
  EXPECT_TRUE(back.extras.blocks.empty());
}

// A mesh from elsewhere: region attributes become physical groups (one
// volume entity each), and a triangle block gets a surface entity.
TEST_P(GmshRoundTrip, RegionTagsAndForeignBlocksBecomeEntities) {
  TetMesh mesh = testing::cube_with_centre();
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) mesh.extras.tet_tags.push_back(t < 6 ? 4 : 9);
  PassThroughBlock tris;
  tris.kind = "triangle";
  tris.nodes_per_element = 3;
  tris.connectivity = {0, 2, 3, 0, 3, 1};
  tris.tags = {2, 2};
  mesh.extras.blocks.push_back(tris);
  const TetMesh back = read_text(write_text(mesh, GetParam()));
  EXPECT_EQ(back.xyz, mesh.xyz);
  EXPECT_EQ(back.tets, mesh.tets);
  EXPECT_EQ(back.extras.tet_tags, mesh.extras.tet_tags);
  EXPECT_EQ(back.extras.tet_entity_tags, mesh.extras.tet_tags);
  ASSERT_EQ(back.extras.blocks.size(), 1u);
  EXPECT_EQ(back.extras.blocks[0].connectivity, tris.connectivity);
  EXPECT_EQ(back.extras.blocks[0].tags, tris.tags);
  EXPECT_EQ(back.fixed, (std::vector<std::uint8_t>{1, 1, 1, 1, 0, 0, 0, 0, 0}));
}

TEST_P(GmshRoundTrip, FieldsAreWrittenAndSkippedOnReading) {
  const TetMesh mesh = read_gmsh_file(testing::data_path("gmsh_sparse41.msh"));
  MeshFields fields;
  fields.node_scalars.push_back({"displacement", {0.5, 1.5, 2.5, 3.5, 4.5}});
  fields.tet_scalars.push_back({"quality \"q\"", {0.25, 0.75}});
  const std::string text = write_text(mesh, GetParam(), fields);
  EXPECT_NE(text.find("$NodeData\n1\n\"displacement\"\n1\n0\n3\n0\n1\n5\n"), std::string::npos);
  // All 5 elements get a value, by their own tags and in their order (the
  // point 100, the triangles 101 and 102, the tets 110 and 120): NaN for
  // the point and the triangles.
  EXPECT_NE(text.find("$ElementData\n1\n\"quality 'q'\"\n1\n0\n3\n0\n1\n5\n"), std::string::npos);
  if (GetParam() != MshFlavour::V41Binary) {
    EXPECT_NE(text.find("\n42 0.5\n20 1.5\n"), std::string::npos);
    EXPECT_NE(text.find("\n100 nan\n101 nan\n102 nan\n110 0.25\n120 0.75\n"), std::string::npos);
  }
  if (GetParam() == MshFlavour::V41Ascii) {  // blocks, elements, smallest and largest tag
    EXPECT_NE(text.find("$Elements\n4 5 100 120\n"), std::string::npos);
  }
  EXPECT_EQ(read_text(text).xyz, mesh.xyz);
}

INSTANTIATE_TEST_SUITE_P(Flavours, GmshRoundTrip,
                         ::testing::Values(MshFlavour::V41Ascii, MshFlavour::V41Binary, MshFlavour::V22Ascii),
                         [](const ::testing::TestParamInfo<MshFlavour>& p) {
                           switch (p.param) {
                             case MshFlavour::V41Ascii:
                               return std::string("V41Ascii");
                             case MshFlavour::V41Binary:
                               return std::string("V41Binary");
                             case MshFlavour::V22Ascii:
                               return std::string("V22Ascii");
                           }
                           return std::string("unknown");
                         });

// Parametric coordinates (Mesh.SaveParametric) are read past, with a note:
// the output has plain nodes (a node on an embedded surface of an MSH 2.2
// file, which has no other classification, may move, and would leave its
// parameters stale).
TEST(GmshIo, ParametricCoordinatesAreNotedAndDropped) {
  const std::string text = replaced(kMinimal, "1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n",
                                    "2 4 1 4\n2 1 1 3\n1\n2\n3\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n"
                                    "3 1 0 1\n4\n0 0 1\n");
  const TetMesh mesh = read_text(text);
  EXPECT_EQ(mesh.xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}));
  ASSERT_EQ(mesh.extras.read_notes.size(), 1u);
  EXPECT_EQ(mesh.extras.read_notes[0],
            "the parametric coordinates of 3 nodes on curves and surfaces are not kept: tetsmooth writes plain node "
            "coordinates");
  EXPECT_TRUE(read_text(kMinimal).extras.read_notes.empty());
}

// MSH 2.2 with Mesh.SaveParametric (Gmsh's MVertex::writeMSH2): the nodes
// come in $ParametricNodes, each with the dimension and tag of its entity
// and then u on a curve, u v on a surface, nothing on a point or in a
// volume. They are the nodes; the rest is dropped with 4.1's note, and the
// written file has a plain $Nodes.
const char* kParametric22 =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
    "$ParametricNodes\n5\n"
    "10 0 0 0 0 3\n"
    "20 1 0 0 1 2 0.5\n"
    "30 0 1 0 2 1 0.25 0.75\n"
    "40 0 0 1 3 1\n"
    "50 0 0 -1 3 1\n"
    "$EndParametricNodes\n"
    "$Elements\n2\n1 4 2 7 1 10 20 30 40\n2 4 2 7 1 10 30 20 50\n$EndElements\n";

void expect_parametric22_read(const TetMesh& mesh) {
  EXPECT_EQ(mesh.extras.node_tags, (std::vector<long long>{10, 20, 30, 40, 50}));
  EXPECT_EQ(mesh.xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3, 0, 2, 1, 4}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{7, 7}));
  EXPECT_EQ(mesh.extras.tet_entity_tags, (std::vector<int>{1, 1}));
  EXPECT_TRUE(mesh.extras.node_entity_dims.empty());
  EXPECT_EQ(mesh.extras.read_notes,
            (std::vector<std::string>{"the parametric coordinates of 2 nodes on curves and surfaces are not kept: "
                                      "tetsmooth writes plain node coordinates"}));
}

TEST(GmshIo, Msh22ParametricNodesAreTheNodes) {
  const TetMesh mesh = read_text(kParametric22);
  expect_parametric22_read(mesh);
  for (MshFlavour flavour : {MshFlavour::V22Ascii, MshFlavour::V41Ascii, MshFlavour::V41Binary}) {
    const std::string text = write_text(mesh, flavour);
    EXPECT_EQ(text.find("Parametric"), std::string::npos);
    EXPECT_NE(text.find("$Nodes\n"), std::string::npos);
    const TetMesh back = read_text(text);
    EXPECT_EQ(back.xyz, mesh.xyz);
    EXPECT_EQ(back.tets, mesh.tets);
    EXPECT_EQ(back.extras.node_tags, mesh.extras.node_tags);
    EXPECT_TRUE(back.extras.read_notes.empty());
  }

  // Binary: the tag as an int, three doubles, the dimension and tag as
  // ints, then the parametric doubles.
  std::string binary = "$MeshFormat\n2.2 1 8\n";
  const auto put = [&](auto value) { binary.append(reinterpret_cast<const char*>(&value), sizeof value); };
  put(std::int32_t{1});
  binary += "\n$EndMeshFormat\n$ParametricNodes\n5\n";
  const double corners[5][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}};
  const std::int32_t entity[5][2] = {{0, 3}, {1, 2}, {2, 1}, {3, 1}, {3, 1}};
  for (std::int32_t n = 0; n < 5; ++n) {
    put(10 * (n + 1));
    for (double c : corners[n]) put(c);
    put(entity[n][0]);
    put(entity[n][1]);
    for (std::int32_t k = 0; k < (entity[n][0] == 3 ? 0 : entity[n][0]); ++k) put(0.125 * (k + 1));
  }
  binary += "\n$EndParametricNodes\n$Elements\n2\n";
  for (std::int32_t v : {4, 2, 2, 1, 7, 1, 10, 20, 30, 40, 2, 7, 1, 10, 30, 20, 50}) put(v);
  binary += "\n$EndElements\n";
  expect_parametric22_read(read_text(binary));

  // MSH 4.1 has no such section (its node blocks say whether they are
  // parametric): one there is skipped like any unknown section.
  const std::string in41 =
      replaced(kMinimal, "$Elements\n", "$ParametricNodes\n1\n1 0 0 0 0 1\n$EndParametricNodes\n$Elements\n");
  EXPECT_EQ(read_text(in41).extras.read_notes,
            (std::vector<std::string>{"$ParametricNodes section skipped; it will not be in the written file"}));
}

TEST(GmshIo, HugeSparseNodeTagsAreKept) {
  std::string text = kMinimal;
  text = replaced(text, "1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n", "1 4 7 1000000000000\n3 1 0 4\n1000000000000\n7\n3\n4\n");
  text = replaced(text, "1 1 2 3 4\n", "1 1000000000000 7 3 4\n");
  const TetMesh mesh = read_text(text);
  EXPECT_EQ(mesh.extras.node_tags, (std::vector<long long>{1000000000000, 7, 3, 4}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3}));
  EXPECT_EQ(read_text(write_text(mesh, MshFlavour::V41Binary)).extras.node_tags, mesh.extras.node_tags);
}

// The $Nodes header's smallest and largest node tags are not relied on:
// the tag lookup is built from the tags the blocks hold, so a header range
// that is wrong (hand-edited, or from a writer that leaves it 0 0) neither
// loses nodes nor sizes anything. Tag 900 of 4 nodes takes the lookup's
// table by tag, tag 5000 its sorted list; the binary reader is checked
// with the range zeroed in a file the writer made.
TEST(GmshIo, NodeTagRangeInTheNodesHeaderIsNotReliedOn) {
  for (const std::string last : {"900", "5000"}) {
    for (const std::string range : {"1 4", "0 0", "3 2"}) {
      std::string text = replaced(kMinimal, "1 4 1 4\n3 1 0 4\n1\n2\n3\n4\n",
                                  "1 4 " + range + "\n3 1 0 4\n1\n" + last + "\n3\n2\n");
      text = replaced(text, "1 1 2 3 4\n", "1 1 " + last + " 3 2\n");
      const TetMesh mesh = read_text(text);
      EXPECT_EQ(mesh.extras.node_tags, (std::vector<long long>{1, std::stoll(last), 3, 2})) << last << ", " << range;
      EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3})) << last << ", " << range;

      std::string binary = write_text(mesh, MshFlavour::V41Binary);
      const std::size_t nodes = binary.find("$Nodes\n");
      ASSERT_NE(nodes, std::string::npos);
      // After the keyword: blocks, nodes, smallest and largest tag, 8 bytes each.
      binary.replace(nodes + 7 + 16, 16, 16, '\0');
      const TetMesh back = read_text(binary);
      EXPECT_EQ(back.extras.node_tags, mesh.extras.node_tags) << last << ", " << range;
      EXPECT_EQ(back.tets, mesh.tets) << last << ", " << range;
    }
  }
}

// Element tags that Gmsh would refuse, or that field data cannot name, are
// replaced by 1, 2, ... on writing, with a note; the elements themselves
// are read as they are.
TEST(GmshIo, UnusableElementTagsAreNotedAndRenumbered) {
  const std::string two_tets =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0 0 -1\n$EndNodes\n"
      "$Elements\n2\nA 4 2 1 1 1 2 3 4\nB 4 2 1 1 1 3 2 5\n$EndElements\n";
  const auto with_tags = [&](const std::string& a, const std::string& b) {
    return read_text(replaced(replaced(two_tets, "A 4", a + " 4"), "B 4", b + " 4"));
  };
  for (const auto& [a, b, why] : {std::tuple{"7", "7", "element tag 7 is used twice"},
                                  std::tuple{"0", "9", "element tag 0 is not positive"},
                                  std::tuple{"3", "2147483600", "element tag 2147483600 exceeds"}}) {
    const TetMesh mesh = with_tags(a, b);
    EXPECT_EQ(mesh.num_tets(), 2u);
    EXPECT_TRUE(mesh.extras.tet_element_tags.empty()) << why;
    ASSERT_EQ(mesh.extras.read_notes.size(), 1u) << why;
    EXPECT_NE(mesh.extras.read_notes[0].find(why), std::string::npos) << mesh.extras.read_notes[0];
    EXPECT_EQ(read_text(write_text(mesh, MshFlavour::V41Ascii)).extras.tet_element_tags,
              (std::vector<long long>{1, 2}));
  }
  const TetMesh kept = with_tags("2147482623", "5");  // kLargestIntTag
  EXPECT_TRUE(kept.extras.read_notes.empty());
  EXPECT_EQ(read_text(write_text(kept, MshFlavour::V41Binary)).extras.tet_element_tags,
            (std::vector<long long>{2147482623, 5}));
  // Binary MSH 2.2 numbers its elements with signed ints: a negative one
  // is read, and noted like 0.
  std::string binary = "$MeshFormat\n2.2 1 8\n";
  const auto put = [&](auto value) { binary.append(reinterpret_cast<const char*>(&value), sizeof value); };
  put(std::int32_t{1});
  binary += "\n$EndMeshFormat\n$Nodes\n4\n";
  const double corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (std::int32_t n = 0; n < 4; ++n) {
    put(n + 1);
    for (double c : corners[n]) put(c);
  }
  binary += "\n$EndNodes\n$Elements\n1\n";
  for (std::int32_t v : {4, 1, 2, -6, 1, 1, 1, 2, 3, 4}) put(v);  // type, count, tags; number, tags, nodes
  binary += "\n$EndElements\n";
  const TetMesh negative = read_text(binary);
  EXPECT_EQ(negative.num_tets(), 1u);
  ASSERT_EQ(negative.extras.read_notes.size(), 1u);
  EXPECT_NE(negative.extras.read_notes[0].find("element tag -6 is not positive"), std::string::npos);

  // Tags given in memory are checked on writing too: one repeated between
  // a tet and a triangle falls back to 1..N.
  TetMesh clash = kept;
  clash.extras.tet_element_tags = {5, 6};
  PassThroughBlock tri;
  tri.kind = "triangle";
  tri.nodes_per_element = 3;
  tri.connectivity = {0, 1, 2};
  tri.element_tags = {6};
  clash.extras.blocks.push_back(tri);
  const TetMesh back = read_text(write_text(clash, MshFlavour::V22Ascii));
  EXPECT_EQ(back.extras.tet_element_tags, (std::vector<long long>{1, 2}));
  ASSERT_EQ(back.extras.blocks.size(), 1u);
  EXPECT_EQ(back.extras.blocks[0].element_tags, (std::vector<long long>{3}));
}

// A file written on a machine of the other byte order.
TEST(GmshIo, ReadsBinaryOfTheOtherByteOrder) {
  std::string s = "$MeshFormat\n4.1 1 8\n";
  const auto swapped = [&](const void* p, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) s += static_cast<const char*>(p)[n - 1 - i];
  };
  const auto u64 = [&](std::uint64_t v) { swapped(&v, 8); };
  const auto i32 = [&](std::int32_t v) { swapped(&v, 4); };
  const auto f64 = [&](double v) { swapped(&v, 8); };
  i32(1);
  s += "\n$EndMeshFormat\n$Nodes\n";
  for (std::uint64_t v : {1, 4, 1, 4}) u64(v);
  i32(3), i32(1), i32(0), u64(4);
  for (std::uint64_t tag = 1; tag <= 4; ++tag) u64(tag);
  for (double v : {0.0, 0.0, 0.0, 1.5, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0}) f64(v);
  s += "\n$EndNodes\n$Elements\n";
  for (std::uint64_t v : {1, 1, 1, 1}) u64(v);
  i32(3), i32(1), i32(4), u64(1);
  for (std::uint64_t v : {1, 1, 2, 3, 4}) u64(v);
  s += "\n$EndElements\n";
  const TetMesh mesh = read_text(s);
  EXPECT_EQ(mesh.xyz, (std::vector<double>{0, 0, 0, 1.5, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3}));
}

struct BadText {
  const char* from;
  const char* to;
  const char* where;
  const char* what;
};

// Each case edits `base` (its first `from` becomes `to`); reading the result
// must fail with a message that names the place (`where`) and the reason.
template <class Cases>
void expect_edits_refused(const std::string& base, const Cases& cases) {
  for (const auto& c : cases) {
    const std::string message = read_error(replaced(base, c.from, c.to));
    EXPECT_NE(message.find(c.where), std::string::npos) << message;
    EXPECT_NE(message.find(c.what), std::string::npos) << message;
  }
}

TEST(GmshIo, BadAsciiInputNamesFileAndLine) {
  const BadText cases[] = {
      {"3 1 4 1\n1 1 2 3 4\n", "3 1 29 1\n1 1 2 3 4 1 2 3 4 1 2\n",
       "t.msh:18:", "unsupported element type 29 (20-node tetrahedron)"},
      {"1 1 2 3 4\n", "1 1 2 3 9\n", "t.msh:19:", "node tag 9, which is not in $Nodes"},
      {"1 0 0\n", "nan 0 0\n", "t.msh:12:", "non-finite node coordinate"},
      {"1 4 1 4\n", "1 5 1 5\n", "t.msh:14:", "hold 4 nodes, not the 5 announced"},
      {"1 1 2 3 4\n", "1 1 2 3 4 4\n", "t.msh:19:", "expected $EndElements, found '4'"},
      {"\n2\n3\n", "\n2\n2\n", "t.msh:", "node tag 2 occurs twice"},
      {"3 1 4 1\n1 1 2 3 4\n", "2 1 2 1\n1 1 2 3\n", "t.msh:20:", "no tetrahedra"},
      {"$Elements\n", "garbage\n$Elements\n", "t.msh:16:", "expected a section such as $Nodes, found 'garbage'"},
      {"4.1 0 8", "4.0 0 8", "t.msh:2:", "unsupported MSH version '4.0'"},
      {"$EndElements\n", "", "t.msh:19:", "unexpected end of file, expected $EndElements"},
      {"3 1 0 4\n", "3 1 0 5\n", "t.msh:", "more nodes than the 4 announced"},
      {"$MeshFormat\n", "$MeshFormatt\n", "t.msh:1:", "not a Gmsh MSH file"},
  };
  expect_edits_refused(kMinimal, cases);
  const std::string truncated = read_error(std::string(kMinimal).substr(0, std::string(kMinimal).find("1 0 0\n")));
  EXPECT_NE(truncated.find("t.msh:11: unexpected end of file, expected node coordinate"), std::string::npos)
      << truncated;
  const std::string swapped = read_error(std::string(kMinimal).substr(std::string(kMinimal).find("$Elements")) +
                                         std::string(kMinimal).substr(0, std::string(kMinimal).find("$Elements")));
  EXPECT_NE(swapped.find("not a Gmsh MSH file"), std::string::npos) << swapped;

  const std::string nodes =
      "$ParametricNodes\n5\n10 0 0 0 0 3\n20 1 0 0 1 2 0.5\n30 0 1 0 2 1 0.25 0.75\n"
      "40 0 0 1 3 1\n50 0 0 -1 3 1\n$EndParametricNodes\n";
  const BadText parametric[] = {
      {"30 0 1 0 2 1", "30 0 1 0 4 1", "t.msh:8:", "entity dimension 4 is not 0, 1, 2 or 3"},
      // A value too many or too few shifts the values after it: a real
      // number or a section end turns up where an integer belongs.
      {"0.25 0.75\n", "0.25 0.75 0.5\n", "t.msh:8:", "expected an integer node tag, found '0.5'"},
      {"20 1 0 0 1 2 0.5\n", "20 1 0 0 1 2\n", "t.msh:8:", "expected an integer entity tag, found '0.25'"},
      {"50 0 0 -1 3 1\n", "50 0 0 -1\n", "t.msh:11:",
       "expected an integer entity dimension, found '$EndParametricNodes'"},
      {"$Elements\n", "$Nodes\n0\n$EndNodes\n$Elements\n", "t.msh:12:",
       "a second node section: $Nodes after $Nodes or $ParametricNodes"},
      {nodes.c_str(), "", "t.msh:4:", "$Elements before $Nodes or $ParametricNodes"},
  };
  expect_edits_refused(kParametric22, parametric);
}

TEST(GmshIo, BadPartitionedEntitiesNameFileAndLine) {
  const std::string good = slurp(testing::data_path("gmsh_partitioned41.msh"));
  const BadText cases[] = {
      {"6 2 5 1 1 ", "6 1 5 1 1 ", "t.msh:31:",
       "partitioned entity of dimension 2 with tag 6 has a parent of dimension 1 (expected 2 to 3)"},
      {"2 3 1 1 1 ", "1 3 1 1 1 ", "t.msh:",
       "entity of dimension 3 with tag 1 is declared in both $Entities and $PartitionedEntities"},
      {"7 2 5 1 2 ", "6 2 5 1 2 ", "t.msh:32:", "partitioned entity of dimension 2 with tag 6 is declared twice"},
  };
  for (const BadText& c : cases) {
    const std::string text = replaced(good, c.from, c.to);
    const std::string message = testing::input_error_message([&] { read_text(text); }, text);
    EXPECT_NE(message.find(c.where), std::string::npos) << message;
    EXPECT_NE(message.find(c.what), std::string::npos) << message;
  }
}

// The byte offset in "t.msh, byte N: ...", or npos.
std::size_t offset_in(const std::string& message) {
  const std::size_t at = message.find("t.msh, byte ");
  return at == std::string::npos ? at : std::stoul(message.substr(at + 12));
}

TEST(GmshIo, BadBinaryInputNamesFileAndByteOffset) {
  TetMesh mesh = testing::regular_tet();
  mesh.xyz[4] = 12345.678;  // a value to find in the bytes
  const std::string good = write_text(mesh, MshFlavour::V41Binary);
  // (After $Nodes: the entity bounding box holds the value too.)
  const std::size_t coordinate =
      good.find(std::string(reinterpret_cast<const char*>(&mesh.xyz[4]), 8), good.find("$Nodes\n"));
  ASSERT_NE(coordinate, std::string::npos);

  // Cut inside the coordinates: the block header already announces more
  // nodes than the bytes left can hold.
  const std::string truncated = read_error(good.substr(0, coordinate + 3));
  EXPECT_NE(truncated.find("(truncated or corrupt count)"), std::string::npos) << truncated;
  EXPECT_LT(offset_in(truncated), coordinate);
  const std::string unfinished = read_error(good.substr(0, good.rfind("$EndElements")));
  EXPECT_NE(unfinished.find("unexpected end of file, expected $EndElements"), std::string::npos) << unfinished;
  EXPECT_EQ(offset_in(unfinished), good.rfind("$EndElements"));

  std::string nan = good;
  const double q = std::numeric_limits<double>::quiet_NaN();
  nan.replace(coordinate, 8, reinterpret_cast<const char*>(&q), 8);
  const std::string not_finite = read_error(nan);
  EXPECT_NE(not_finite.find("non-finite node coordinate"), std::string::npos) << not_finite;
  EXPECT_EQ(offset_in(not_finite), coordinate);

  // A corrupt count of node blocks must be refused, not allocated.
  std::string huge = good;
  const std::size_t count = huge.find("$Nodes\n") + 7;
  const std::uint64_t lots = std::uint64_t{1} << 60;
  huge.replace(count, 8, reinterpret_cast<const char*>(&lots), 8);
  const std::string refused = read_error(huge);
  EXPECT_NE(refused.find("cannot fit in the"), std::string::npos) << refused;
  EXPECT_NE(offset_in(refused), std::string::npos) << refused;

  std::string order = good;
  order[good.find("8\n") + 2] = 7;
  EXPECT_NE(read_error(order).find("byte-order integer"), std::string::npos);
}

TEST(GmshIo, WriterRefusesWhatMshCannotHold) {
  TetMesh mesh = testing::regular_tet();
  MeshFields fields;
  fields.tet_scalars.push_back({"short", {}});
  EXPECT_THROW(write_text(mesh, MshFlavour::V41Ascii, fields), std::invalid_argument);
  PassThroughBlock polygon;
  polygon.kind = "polygon";
  polygon.nodes_per_element = 5;
  polygon.connectivity = {0, 1, 2, 3, 0};
  mesh.extras.blocks.push_back(polygon);
  EXPECT_THROW(write_text(mesh, MshFlavour::V22Ascii), OutputError);
}

// Field data name nodes by 32-bit int. A node tag past that stays in MSH
// 4.1's $Nodes (size_t), which then carries no $NodeData; MSH 2.2, which
// numbers nodes by int, numbers them 1, 2, ... and keeps its node fields.
TEST(GmshIo, NodeTagsPastTheIntRangeCostFieldsOrTags) {
  TetMesh sparse = testing::regular_tet();
  sparse.extras.node_tags = {1, 2, 3, gmsh::kLargestIntTag + 1};
  MeshFields fields;
  fields.node_scalars.push_back({"p", {0, 1, 2, 3}});
  fields.tet_scalars.push_back({"q", {0.5}});
  for (MshFlavour flavour : {MshFlavour::V41Ascii, MshFlavour::V41Binary}) {
    const std::string text = write_text(sparse, flavour, fields);
    EXPECT_EQ(text.find("$NodeData"), std::string::npos);
    EXPECT_NE(text.find("$ElementData"), std::string::npos);
    EXPECT_EQ(read_text(text).extras.node_tags, sparse.extras.node_tags);
  }
  const std::string v22 = write_text(sparse, MshFlavour::V22Ascii, fields);
  EXPECT_NE(v22.find("$NodeData"), std::string::npos);
  EXPECT_EQ(read_text(v22).extras.node_tags, (std::vector<long long>{1, 2, 3, 4}));
  // At the limit, both flavours keep the tags and the fields.
  sparse.extras.node_tags.back() = gmsh::kLargestIntTag;
  for (MshFlavour flavour : {MshFlavour::V41Binary, MshFlavour::V22Ascii}) {
    const std::string text = write_text(sparse, flavour, fields);
    EXPECT_NE(text.find("$NodeData"), std::string::npos);
    EXPECT_EQ(read_text(text).extras.node_tags, sparse.extras.node_tags);
  }
}

// MSH physical tags are positive: negative region tags (TetGen, VTU) get the
// next free positive ones, -1 first, so that regions stay apart in every
// flavour; a boundary block's tags share the numbering.
TEST(GmshIo, NegativeRegionTagsBecomeNewPositiveOnes) {
  TetMesh mesh = testing::cube_with_centre();
  mesh.extras.tet_tags = {-1, -1, 3, 3, -7, -7, 0, 0, 3, 3, -1, -1};
  mesh.extras.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 2, 3}, {-7}, {}, {}});
  EXPECT_EQ(gmsh::negative_tag_renumbering(mesh.extras), (std::map<int, int>{{-7, 5}, {-1, 4}}));
  for (MshFlavour flavour : {MshFlavour::V41Ascii, MshFlavour::V41Binary, MshFlavour::V22Ascii}) {
    const TetMesh back = read_text(write_text(mesh, flavour));
    EXPECT_EQ(back.extras.tet_tags, (std::vector<int>{4, 4, 3, 3, 5, 5, 0, 0, 3, 3, 4, 4}));
    ASSERT_EQ(back.extras.blocks.size(), 1u);
    EXPECT_EQ(back.extras.blocks[0].tags, (std::vector<int>{5}));
  }
}

TEST(GmshIo, FileWriterReplacesTargetOrThrows) {
  const testing::ScratchDir dir("gmsh");
  const std::string path = dir.file("out.msh");
  const TetMesh mesh = testing::cube_grid(2);
  write_gmsh_file(mesh, path, MshFlavour::V41Binary, {});
  EXPECT_EQ(read_gmsh_file(path).xyz, mesh.xyz);
  EXPECT_THROW(write_gmsh_file(mesh, dir.file("missing/out.msh"), MshFlavour::V41Ascii, {}), OutputError);
}

// Two tets on volumes 1 and 2, both volumes in physical group 13 as well
// as in 11 and 12 (as Gmsh saves two fragmented boxes with groups
// (3,11)=[1], (3,12)=[2], (3,13)=[1,2]).
const char* kTwoGroups41 =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    "$Entities\n0 0 0 2\n1 0 0 0 1 1 1 2 11 13 0\n2 0 0 -1 1 1 0 2 12 13 0\n$EndEntities\n"
    "$Nodes\n1 5 1 5\n3 1 0 5\n1\n2\n3\n4\n5\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 0 -1\n$EndNodes\n"
    "$Elements\n2 2 1 2\n3 1 4 1\n1 1 2 3 4\n3 2 4 1\n2 1 3 2 5\n$EndElements\n";

TEST(GmshIo, Msh22WritesAnElementOncePerPhysicalGroupUnderOneNumber) {
  const TetMesh mesh = read_text(kTwoGroups41);
  MeshFields fields;
  fields.tet_scalars.emplace_back("quality", std::vector<double>{0.5, 0.25});  // not noted on reading
  const std::string v22 = write_text(mesh, MshFlavour::V22Ascii, fields);
  EXPECT_NE(v22.find("$Elements\n4\n1 4 2 11 1 1 2 3 4\n1 4 2 13 1 1 2 3 4\n2 4 2 12 2 1 3 2 5\n"
                     "2 4 2 13 2 1 3 2 5\n$EndElements\n"),
            std::string::npos)
      << v22;
  // A value a line, for readers that take them in the order of the lines.
  EXPECT_NE(v22.find("\n4\n1 0.5\n1 0.5\n2 0.25\n2 0.25\n$EndElementData\n"), std::string::npos) << v22;

  // Read back: each tet once, the first group its region tag, and every
  // group kept for the next MSH output.
  const TetMesh back = read_text(v22);
  EXPECT_EQ(back.tets, mesh.tets);
  EXPECT_EQ(back.extras.tet_tags, (std::vector<int>{11, 12}));
  EXPECT_EQ(back.extras.tet_element_tags, (std::vector<long long>{1, 2}));
  EXPECT_TRUE(back.extras.read_notes.empty());
  EXPECT_EQ(write_text(back, MshFlavour::V22Ascii, fields), v22);
  const TetMesh v41 = read_text(write_text(back, MshFlavour::V41Ascii));
  const gmsh::Entities entities = gmsh::parse_entities_text(*raw_section(v41, "$Entities"), "v41");
  ASSERT_NE(entities.find(3, 1), nullptr);
  ASSERT_NE(entities.find(3, 2), nullptr);
  EXPECT_EQ(entities.find(3, 1)->physicals, (std::vector<int>{11, 13}));
  EXPECT_EQ(entities.find(3, 2)->physicals, (std::vector<int>{12, 13}));
  EXPECT_EQ(v41.tets, mesh.tets);
}

TEST(GmshIo, Msh22ElementsOfOneEntityInDifferentGroupsKeepTheirFirst) {
  // Tet 1 in groups 11 and 13, tet 2 of the same volume only in 11.
  const std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0 0 -1\n$EndNodes\n"
      "$Elements\n3\n1 4 2 11 1 1 2 3 4\n1 4 2 13 1 1 2 3 4\n2 4 2 11 1 1 3 2 5\n$EndElements\n";
  const TetMesh mesh = read_text(text);
  EXPECT_EQ(mesh.num_tets(), 2u);
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{11, 11}));
  EXPECT_EQ(raw_section(mesh, "$Entities"), nullptr);
  EXPECT_EQ(mesh.extras.read_notes,
            (std::vector<std::string>{"1 element is listed once per physical group, but not every element of "
                                      "its elementary entity is in the same groups: it keeps only its first "
                                      "group"}));
  // Lines under different numbers are different elements, as Gmsh reads them.
  const TetMesh twice = read_text(replaced(text, "1 4 2 13", "3 4 2 13"));
  EXPECT_EQ(twice.num_tets(), 3u);
}

// A line repeating an element for a further group names the same entity, so
// lines that differ only in their elementary tag are two elements, each on
// its own entity; only their shared number is lost (as a tag used twice).
TEST(GmshIo, Msh22LinesDifferingOnlyInTheirElementaryTagAreTwoElements) {
  const std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0 0 -1\n$EndNodes\n"
      "$Elements\n3\n1 4 2 11 1 1 2 3 4\n1 4 2 11 2 1 2 3 4\n2 4 2 11 1 1 3 2 5\n$EndElements\n";
  const TetMesh mesh = read_text(text);
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3, 0, 1, 2, 3, 0, 2, 1, 4}));
  EXPECT_EQ(mesh.extras.tet_entity_tags, (std::vector<int>{1, 2, 1}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{11, 11, 11}));
  EXPECT_EQ(raw_section(mesh, "$Entities"), nullptr);
  EXPECT_EQ(mesh.extras.read_notes,
            (std::vector<std::string>{"element tag 1 is used twice; MSH output numbers the elements 1, 2, ... "
                                      "instead of keeping their tags"}));
}

TEST(GmshIo, Msh22PartitionTagsAreNoted) {
  const std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0 0 -1\n$EndNodes\n"
      "$Elements\n2\n1 4 4 7 1 1 1 1 2 3 4\n2 4 4 7 1 1 2 1 3 2 5\n$EndElements\n";
  const TetMesh mesh = read_text(text);
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{7, 7}));
  EXPECT_EQ(mesh.extras.read_notes,
            (std::vector<std::string>{"the partition tags of 2 elements are dropped: the partitions are merged; "
                                      "the written file is not partitioned"}));
  // Three tags where the third counts no partitions: nothing dropped.
  EXPECT_TRUE(read_text(replaced(replaced(text, "1 4 4 7 1 1 1 1", "1 4 3 7 1 0 1"), "2 4 4 7 1 1 2 1", "2 4 2 7 1 1"))
                  .extras.read_notes.empty());
}

TEST(GmshIo, EmptyElementBlockMakesNoPassThroughBlock) {
  const TetMesh mesh = read_text(replaced(kMinimal, "$Elements\n1 1 1 1\n", "$Elements\n2 1 1 1\n3 1 5 0\n"));
  EXPECT_TRUE(mesh.extras.blocks.empty());
  EXPECT_TRUE(mesh.fixed.empty());
}

// VTU, VTK, Medit and TetGen give a cell one region tag, the first group.
TEST(GmshIo, OneTagFormatsNoteTheGroupsTheyDrop) {
  const TetMesh mesh = read_text(kTwoGroups41);
  for (const char* name : {"out.vtu", "out.vtk", "out.mesh"})
    EXPECT_EQ(output_losses(mesh, name),
              (std::vector<std::string>{"2 elements in several Gmsh physical groups will keep only the first: " +
                                        std::string(format_name(format_from_path(name))) +
                                        " holds one region tag per element"}))
        << name;
  EXPECT_EQ(output_losses(mesh, "out.node"),
            (std::vector<std::string>{
                "2 elements in several Gmsh physical groups will keep only the first: tetgen holds one region tag "
                "per tet"}));
  for (const char* name : {"out.msh", "out.tsm"})
    for (const std::string& loss : output_losses(mesh, name))
      EXPECT_EQ(loss.find("physical groups"), std::string::npos) << name << ": " << loss;
}

// cube_grid(2) in MSH 4.1 on volume 1 (physical 7), the centre node (1, 1, 1)
// classified on point 1, as Gmsh classifies a point embedded in a volume
// (gmsh.model.mesh.embed); with `declared`, $Entities declares the point.
std::string embedded_point41(bool declared) {
  const TetMesh grid = testing::cube_grid(2);
  std::ostringstream s;
  s << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n" << (declared ? 1 : 0) << " 0 0 1\n"
    << (declared ? "1 1 1 1 0\n" : "") << "1 0 0 0 2 2 2 1 7 0\n$EndEntities\n";
  std::string volume_tags, volume_xyz, centre;
  for (std::size_t i = 0; i < grid.num_nodes(); ++i) {
    std::ostringstream xyz;
    xyz << grid.xyz[3 * i] << ' ' << grid.xyz[3 * i + 1] << ' ' << grid.xyz[3 * i + 2] << '\n';
    if (xyz.str() == "1 1 1\n") {
      centre = std::to_string(i + 1) + '\n' + xyz.str();
    } else {
      volume_tags += std::to_string(i + 1) + '\n';
      volume_xyz += xyz.str();
    }
  }
  s << "$Nodes\n2 27 1 27\n3 1 0 26\n" << volume_tags << volume_xyz << "0 1 0 1\n" << centre << "$EndNodes\n";
  s << "$Elements\n1 " << grid.num_tets() << " 1 " << grid.num_tets() << "\n3 1 4 " << grid.num_tets() << '\n';
  for (std::size_t t = 0; t < grid.num_tets(); ++t) {
    s << t + 1;
    for (int k = 0; k < 4; ++k) s << ' ' << grid.tets[4 * t + k] + 1;
    s << '\n';
  }
  s << "$EndElements\n";
  return s.str();
}

// Nodes that Gmsh's entities keep in place are a loss where the output
// drops what tells of them: the classification of an embedded point (all
// but MSH 4.1, and MSH 4.1 too when it cannot declare the point), the
// entity tags of two volumes in one physical group (all but MSH).
TEST(GmshIo, OutputLossesCountNodesThatGmshEntitiesPin) {
  const std::string feature =
      " that Gmsh's entities keep in place (between volumes of one physical group, or on points, curves or surfaces "
      "inside the mesh) will not be pinned in the ";
  const auto losses_of = [&](const TetMesh& mesh, const char* name, MeshFormat format) {
    std::vector<std::string> found;
    for (const std::string& loss : output_losses(mesh, name, format))
      if (loss.find(feature) != std::string::npos) found.push_back(loss);
    return found;
  };
  const TetMesh point = read_text(embedded_point41(true));
  ASSERT_EQ(point.extras.node_entity_dims.size(), 27u);
  EXPECT_TRUE(losses_of(point, "out.msh", MeshFormat::Auto).empty());
  EXPECT_EQ(losses_of(point, "out.msh", MeshFormat::Msh22),
            (std::vector<std::string>{"1 node" + feature + "msh22 output, which does not keep the nodes' entities, "
                                      "so a later run may move it"}));
  // VTU and VTK keep the nodes' classification (gmsh:dim_tags), and read
  // it back.
  for (const char* name : {"out.vtu", "out.vtk"}) {
    EXPECT_TRUE(losses_of(point, name, MeshFormat::Auto).empty()) << name;
    const testing::ScratchDir dir("vtk_dim_tags");
    const std::string file = (dir.path() / name).string();
    write_mesh(point, file);
    const TetMesh read = read_mesh(file);
    EXPECT_EQ(read.extras.node_entity_dims, point.extras.node_entity_dims) << name;
    EXPECT_EQ(read.extras.node_entity_tags, point.extras.node_entity_tags) << name;
  }
  for (const char* name : {"out.mesh", "out.node", "out.tsm"})
    EXPECT_EQ(losses_of(point, name, MeshFormat::Auto),
              (std::vector<std::string>{"1 node" + feature + format_name(format_from_path(name)) +
                                        " output, which has no place for Gmsh entities, so a later run may move "
                                        "it"}))
        << name;
  // MSH 4.1 output keeps the classification where it can declare the point.
  const TetMesh back = read_text(write_text(point, MshFlavour::V41Ascii));
  EXPECT_EQ(back.extras.node_entity_dims, point.extras.node_entity_dims);
  const TetMesh undeclared = read_text(embedded_point41(false));
  EXPECT_EQ(losses_of(undeclared, "out.msh", MeshFormat::Auto).size(), 1u);

  // cube_grid(4) on volumes 1 (x < 2) and 2, both in physical group 7: the
  // 9 nodes inside the plane x = 2 between them.
  TetMesh boxes = testing::cube_grid(4);
  for (std::size_t t = 0; t < boxes.num_tets(); ++t) {
    double cx = 0;
    for (int k = 0; k < 4; ++k) cx += boxes.xyz[3 * static_cast<std::size_t>(boxes.tets[4 * t + k])] / 4;
    boxes.extras.tet_entity_tags.push_back(cx < 2 ? 1 : 2);
  }
  boxes.extras.tet_tags.assign(boxes.num_tets(), 7);
  for (MshFlavour flavour : {MshFlavour::V41Ascii, MshFlavour::V22Ascii}) {
    const TetMesh read = read_text(write_text(boxes, flavour));
    EXPECT_EQ(read.extras.tet_entity_tags, boxes.extras.tet_entity_tags);
    EXPECT_TRUE(losses_of(read, "out.msh", MeshFormat::Auto).empty());
    EXPECT_TRUE(losses_of(read, "out.msh", MeshFormat::Msh22).empty());
    EXPECT_TRUE(losses_of(read, "out.vtu", MeshFormat::Auto).empty());
    EXPECT_EQ(losses_of(read, "out.mesh", MeshFormat::Auto),
              (std::vector<std::string>{"9 nodes" + feature +
                                        "medit output, which has no place for Gmsh entities, so a later run may move "
                                        "them"}));
  }
}

// cube_grid(4) of one volume, its nodes classified as Gmsh classifies those
// of a surface inside it with a curve and a point on that surface, and of
// the boundary surface, with no element on any of these (meshio's VTU or
// VTK of a Gmsh mesh whose physical group is the volume names them in
// gmsh:dim_tags alone): MSH 4.1 output declares them, so the nodes come
// back on them and stay in place. Two classifications fall back to the
// volume of the node's tets: a volume no tet is on, which pins nothing, and
// a surface of tag 0, which no Gmsh entity has; only the latter's node is a
// loss.
TEST(GmshIo, Msh41OutputDeclaresTheEntitiesThatOnlyTheNodesNameFromOtherFormats) {
  TetMesh mesh = testing::cube_grid(4);
  mesh.extras.tet_entity_tags.assign(mesh.num_tets(), 1);
  std::vector<int> dims, tags, want_dims, want_tags;
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) {
    const double* p = &mesh.xyz[3 * i];
    const bool boundary = std::any_of(p, p + 3, [](double c) { return c == 0 || c == 4; });
    std::pair<int, int> entity{3, 1};
    if (boundary)
      entity = {2, 20};
    else if (p[2] == 2)
      entity = p[0] == 2 && p[1] == 2 ? std::pair{0, 4} : (p[1] == 2 ? std::pair{1, 3} : std::pair{2, 5});
    else if (p[0] == 1 && p[1] == 1 && p[2] == 1)
      entity = {3, 9};
    else if (p[0] == 3 && p[1] == 3 && p[2] == 3)
      entity = {2, 0};
    dims.push_back(entity.first);
    tags.push_back(entity.second);
    const bool kept = entity != std::pair{3, 9} && entity != std::pair{2, 0};
    want_dims.push_back(kept ? entity.first : 3);
    want_tags.push_back(kept ? entity.second : 1);
  }
  mesh.extras.node_entity_dims = dims;
  mesh.extras.node_entity_tags = tags;
  for (MshFlavour flavour : {MshFlavour::V41Ascii, MshFlavour::V41Binary}) {
    const TetMesh back = read_text(write_text(mesh, flavour));
    EXPECT_EQ(back.extras.node_entity_dims, want_dims);
    EXPECT_EQ(back.extras.node_entity_tags, want_tags);
    EXPECT_EQ(back.extras.tet_entity_tags, mesh.extras.tet_entity_tags);
    // The 9 nodes of the inner surface stay in place, as they do in the
    // mesh, less the one of surface 0.
    const std::vector<std::uint8_t> pinned = region_interface_nodes(mesh);
    const std::vector<std::uint8_t> back_pinned = region_interface_nodes(back);
    EXPECT_EQ(std::count(pinned.begin(), pinned.end(), kOnGmshFeature), 10);
    EXPECT_EQ(std::count(back_pinned.begin(), back_pinned.end(), kOnGmshFeature), 9);
  }
  // The entities made for them have no physical group and no boundary; a
  // point is where its node is, the others span their nodes.
  const std::string text = write_text(mesh, MshFlavour::V41Ascii);
  const std::string entities =
      text.substr(text.find("$Entities\n") + 10, text.find("$EndEntities") - text.find("$Entities\n") - 10);
  EXPECT_EQ(entities.substr(0, entities.find('\n')), "1 1 2 1");
  EXPECT_NE(entities.find("\n4 2 2 2 0\n"), std::string::npos) << entities;
  EXPECT_NE(entities.find("\n3 1 2 2 3 2 2 0 0\n"), std::string::npos) << entities;
  EXPECT_NE(entities.find("\n5 1 1 2 3 3 2 0 0\n"), std::string::npos) << entities;
  EXPECT_NE(entities.find("\n20 0 0 0 4 4 4 0 0\n"), std::string::npos) << entities;
  const std::string feature =
      " that Gmsh's entities keep in place (between volumes of one physical group, or on points, curves or surfaces "
      "inside the mesh) will not be pinned in the ";
  std::vector<std::string> losses;
  for (const std::string& loss : output_losses(mesh, "out.msh"))
    if (loss.find(feature) != std::string::npos) losses.push_back(loss);
  EXPECT_EQ(losses,
            (std::vector<std::string>{"1 node" + feature +
                                      "msh41 output, which has no entity of a tag below 1 to put them on, so a later "
                                      "run may move it"}));
  mesh.extras.node_entity_tags[static_cast<std::size_t>(std::find(tags.begin(), tags.end(), 0) - tags.begin())] = 5;
  for (const std::string& loss : output_losses(mesh, "out.msh"))
    EXPECT_EQ(loss.find(feature), std::string::npos) << loss;
}

// Entity tags from another program need not nest in the physical groups
// (meshio's gmsh:geometrical of a file whose writer gave every element
// entity 1, say). An MSH 4.1 entity puts all its elements in the same
// groups, so the writer gives each (entity, group) an entity of its own,
// with a tag clear of those given: the groups, and the interface between
// them, come back as they were.
TEST(GmshIo, EntityTagsThatDoNotNestInTheGroupsAreSplit) {
  TetMesh layers = testing::cube_grid(4);
  for (std::size_t t = 0; t < layers.num_tets(); ++t) {
    double cx = 0;
    for (int k = 0; k < 4; ++k) cx += layers.xyz[3 * static_cast<std::size_t>(layers.tets[4 * t + k])] / 4;
    layers.extras.tet_tags.push_back(cx < 2 ? 5 : 6);
  }
  const std::vector<std::uint8_t> interface = region_interface_nodes(layers);
  ASSERT_EQ(std::count(interface.begin(), interface.end(), kOnInterface), 9);
  struct Case {
    const char* name;
    int left, right;  // the entity tags of the tets in groups 5 and 6
  };
  for (const Case& c : {Case{"one entity for both groups", 1, 1},
                        Case{"no entity tag where a given one is the other group's tag", 6, 0}}) {
    TetMesh m = layers;
    for (int tag : m.extras.tet_tags) m.extras.tet_entity_tags.push_back(tag == 5 ? c.left : c.right);
    for (MshFlavour flavour : {MshFlavour::V41Ascii, MshFlavour::V22Ascii}) {
      SCOPED_TRACE(std::string(c.name) + (flavour == MshFlavour::V22Ascii ? ", MSH 2.2" : ", MSH 4.1"));
      const TetMesh back = read_text(write_text(m, flavour));
      EXPECT_EQ(back.extras.tet_tags, layers.extras.tet_tags);
      EXPECT_EQ(region_interface_nodes(back), interface);
      // Group 5 keeps its given entity; group 6 is on another.
      const auto left = static_cast<std::size_t>(
          std::find(layers.extras.tet_tags.begin(), layers.extras.tet_tags.end(), 5) - layers.extras.tet_tags.begin());
      const auto right = static_cast<std::size_t>(
          std::find(layers.extras.tet_tags.begin(), layers.extras.tet_tags.end(), 6) - layers.extras.tet_tags.begin());
      EXPECT_EQ(back.extras.tet_entity_tags[left], c.left);
      EXPECT_NE(back.extras.tet_entity_tags[right], c.left);
    }
  }
}

// Groupings that MSH 2.2 lines give where an element's lines do not make it
// a member of every group of its elementary entity: each keeps its first
// group, with a note counting the elements listed more than once, and no
// $Entities is made up (it would put elements in groups they were not in).
TEST(GmshIo, Msh22GroupsNotSharedByTheWholeEntityKeepTheFirst) {
  const std::string head =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n5\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 0 0 -1\n$EndNodes\n";
  struct Case {
    const char* lines;  // element lines: tet 1 = nodes 1 2 3 4, tet 2 = nodes 1 3 2 5
    const char* repeated;
    std::vector<int> tags;
  };
  const Case cases[] = {
      // Elementary tag 0 is no entity that groups could be declared on.
      {"1 4 2 11 0 1 2 3 4\n1 4 2 13 0 1 2 3 4\n2 4 2 11 0 1 3 2 5\n2 4 2 13 0 1 3 2 5\n", "2", {11, 11}},
      // Tet 2 is in no group, though lines == elements * groups.
      {"1 4 2 11 1 1 2 3 4\n1 4 2 13 1 1 2 3 4\n1 4 2 11 1 1 2 3 4\n2 4 2 0 1 1 3 2 5\n", "1", {11, 0}},
      // Both tets in both groups, but tet 2 lists 13 first: its tag is 13.
      {"1 4 2 11 1 1 2 3 4\n1 4 2 13 1 1 2 3 4\n2 4 2 13 1 1 3 2 5\n2 4 2 11 1 1 3 2 5\n", "2", {11, 13}},
      // An element listed twice in no group at all.
      {"1 4 2 0 1 1 2 3 4\n1 4 2 0 1 1 2 3 4\n2 4 2 0 1 1 3 2 5\n", "1", {0, 0}},
      // Three lines are still one element listed more than once.
      {"1 4 2 11 1 1 2 3 4\n1 4 2 13 1 1 2 3 4\n1 4 2 17 1 1 2 3 4\n2 4 2 11 1 1 3 2 5\n", "1", {11, 11}},
  };
  for (const Case& c : cases) {
    const std::string lines = c.lines;
    const std::size_t count = static_cast<std::size_t>(std::count(lines.begin(), lines.end(), '\n'));
    const TetMesh mesh = read_text(head + "$Elements\n" + std::to_string(count) + "\n" + lines + "$EndElements\n");
    EXPECT_EQ(mesh.num_tets(), 2u) << lines;
    EXPECT_EQ(mesh.extras.tet_tags, c.tags) << lines;
    EXPECT_EQ(raw_section(mesh, "$Entities"), nullptr) << lines;
    const std::string note = std::string(c.repeated) == "1"
                                 ? "1 element is listed once per physical group, but not every element of its "
                                   "elementary entity is in the same groups: it keeps only its first group"
                                 : std::string(c.repeated) +
                                       " elements are listed once per physical group, but not every element of "
                                       "their elementary entity is in the same groups: they keep only their first "
                                       "group";
    EXPECT_EQ(mesh.extras.read_notes, std::vector<std::string>{note})
        << lines;
  }
}

// Tag 0 is a valid node tag, so a second 0 is a repeated tag like any other.
TEST(GmshIo, RepeatedNodeTagZeroIsRefused) {
  const std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n0 0 0 0\n0 1 0 0\n2 0 1 0\n3 0 0 1\n$EndNodes\n"
      "$Elements\n1\n1 4 2 1 1 0 1 2 3\n$EndElements\n";
  const std::string message = read_error(text);
  EXPECT_NE(message.find("node tag 0 occurs twice in $Nodes"), std::string::npos) << message;
}

// An MSH 2.2 binary file: counts as text lines, nodes as an int tag and
// three doubles, elements in runs headed by type, count and number of tags.
class Binary22 {
 public:
  Binary22() {
    s_ = "$MeshFormat\n2.2 1 8\n";
    i32(1);
    s_ += "\n$EndMeshFormat\n";
  }
  Binary22& text(const std::string& t) {
    s_ += t;
    return *this;
  }
  Binary22& i32(std::int32_t v) {
    s_.append(reinterpret_cast<const char*>(&v), 4);
    return *this;
  }
  Binary22& f64(double v) {
    s_.append(reinterpret_cast<const char*>(&v), 8);
    return *this;
  }
  // $Nodes of the unit tet's four nodes tagged `tags`.
  Binary22& nodes(const std::int32_t (&tags)[4]) {
    const double xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    text("$Nodes\n4\n");
    for (int i = 0; i < 4; ++i) {
      i32(tags[i]);
      for (double v : xyz[i]) f64(v);
    }
    return text("\n$EndNodes\n");
  }
  // One tet element with two tags (physical 7, elementary 1).
  Binary22& tet(std::int32_t id, const std::int32_t (&nodes)[4]) {
    i32(id).i32(7).i32(1);
    for (std::int32_t n : nodes) i32(n);
    return *this;
  }
  const std::string& str() const { return s_; }

 private:
  std::string s_;
};

TEST(GmshIo, ReadsBinaryMsh22AndRefusesBadRuns) {
  const auto file = [](std::int32_t node_tag, std::int32_t element_node, std::int32_t tags, std::int32_t second_run) {
    Binary22 b;
    b.nodes({1, 2, 3, node_tag}).text("$Elements\n2\n");
    b.i32(4).i32(1).i32(tags).i32(1).i32(7).i32(1);  // one tet: number, tags (as many as `tags` says), nodes
    for (std::int32_t n : {1, 2, 3, element_node}) b.i32(n);
    b.i32(4).i32(second_run).i32(2);
    for (std::int32_t k = 0; k < second_run; ++k) b.tet(2 + k, {1, 3, 2, node_tag});
    return b.text("\n$EndElements\n").str();
  };
  // The well-formed file reads: two tets of group 7 on entity 1.
  const TetMesh mesh = read_text(file(4, 4, 2, 1));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3, 0, 2, 1, 3}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{7, 7}));
  EXPECT_EQ(mesh.extras.tet_element_tags, (std::vector<long long>{1, 2}));

  struct Bad {
    std::string text;
    const char* what;
  };
  // A negative tag count would read the run with a wrong layout; a run of 0
  // or one past the announced total is a corrupt header.
  const Bad cases[] = {
      {file(-1, 4, 2, 1), "negative node tag -1"},
      {file(4, -1, 2, 1), "negative node tag -1"},
      {file(4, 4, -1, 1), "negative number of element tags -1"},
      {file(4, 4, 2, 0), "a run of 0 elements does not fit the 1 still to come"},
      {file(4, 4, 2, 2), "a run of 2 elements does not fit the 1 still to come"},
  };
  for (const Bad& c : cases) {
    const std::string message = testing::input_error_message([&] { read_text(c.text); }, c.what);
    EXPECT_NE(message.find(c.what), std::string::npos) << message;
    EXPECT_NE(offset_in(message), std::string::npos) << message;
  }
}

// MSH 4.1 block headers and node tags that do not add up: each is refused
// naming what is wrong, not read into a mesh of misplaced values.
TEST(GmshIo, BadMsh41BlocksAndNodeTagsAreRefused) {
  const BadText cases[] = {
      {"3 1 0 4\n", "4 1 0 4\n", "t.msh:6:", "entity dimension 4 is not 0, 1, 2 or 3"},
      {"3 1 0 4\n", "3 1 2 4\n", "t.msh:6:", "parametric flag 2 is not 0 or 1"},
      {"3 1 4 1\n", "2 1 4 1\n", "t.msh:18:", "element type 4 (tetra) in a block of dimension 2"},
      {"3 1 4 1\n1 1 2 3 4\n", "3 1 4 2\n1 1 2 3 4\n2 1 3 2 4\n", "t.msh:18:",
       "the element blocks hold more elements than the 1 announced"},
      {"$Elements\n1 1 1 1\n", "$Elements\n1 2 1 2\n", "t.msh:", "the element blocks hold 1 elements, not the 2 announced"},
      // One past the largest tag: the end of a table indexed by tag.
      {"1 1 2 3 4\n", "1 1 2 3 5\n", "t.msh:19:", "node tag 5, which is not in $Nodes"},
      // A repeat of the first node's tag, with tags few enough for a table
      // and spread enough for a sorted list.
      {"0 4\n1\n2\n3\n", "0 4\n1\n2\n1\n", "t.msh:", "node tag 1 occurs twice"},
      {"0 4\n1\n2\n3\n4\n", "0 4\n1\n5000\n5000\n4\n", "t.msh:", "node tag 5000 occurs twice"},
      // A tag missing from a sorted list is not the next larger one.
      {"0 4\n1\n2\n3\n4\n", "0 4\n1\n2\n3\n5000\n", "t.msh:19:", "node tag 4, which is not in $Nodes"},
  };
  expect_edits_refused(kMinimal, cases);
}

// $PhysicalNames is kept verbatim and written back, so a body that is not
// `dim tag "name"` lines in the announced number must be refused, as must a
// second copy of a section that comes once and a stray end line.
TEST(GmshIo, BadSectionFramingAndPhysicalNamesAreRefused) {
  const std::string names = "$PhysicalNames\n1\n3 1 \"volume\"\n$EndPhysicalNames\n";
  const std::string with_names = replaced(kMinimal, "$EndMeshFormat\n", "$EndMeshFormat\n" + names);
  EXPECT_NE(raw_section(read_text(with_names), "$PhysicalNames"), nullptr);
  struct Bad {
    std::string from, to;
    const char* where;
    const char* what;
  };
  const Bad cases[] = {
      {"\n1\n3 1", "\n-1\n3 1", "t.msh:5:", "expected the number of physical names, found '-1'"},
      {"3 1 \"volume\"", "3 1 \"volume", "t.msh:6:", "expected a physical name as 'dimension tag \"name\"'"},
      {"3 1 \"volume\"", "4 1 \"volume\"", "t.msh:6:", "expected a physical name"},
      {"3 1 \"volume\"", "volume", "t.msh:6:", "expected a physical name"},
      {"$EndPhysicalNames\n", "$EndPhysicalNames\n" + names, "t.msh:8:", "a second $PhysicalNames section"},
      {"$Elements\n", "$EndFoo\n$Elements\n", "t.msh:20:", "expected a section such as $Nodes, found '$EndFoo'"},
      {"$EndElements\n", "$EndElements\n$Elements\n1 1 1 1\n3 1 4 1\n2 1 2 3 4\n$EndElements\n", "t.msh:25:",
       "a second $Elements section"},
      {"4.1 0 8", "4.1 2 8", "t.msh:2:", "file type 2 is not 0 or 1"},
      {"4.1 0 8", "4.1 1 4", "t.msh:2:", "binary data size 4 is not 8"},
  };
  expect_edits_refused(with_names, cases);
}

// A binary file cut right after its version line, or with bytes left over
// before an end line: both are refused at their byte, not read past.
TEST(GmshIo, BinaryCutShortOrRunningOverIsRefused) {
  const std::string cut = read_error("$MeshFormat\n4.1 1 8\n");
  EXPECT_NE(cut.find("unexpected end of file, expected the byte-order integer"), std::string::npos) << cut;
  Binary22 b;
  b.nodes({1, 2, 3, 4}).text("$Elements\n1\n").i32(4).i32(1).i32(2).tet(1, {1, 2, 3, 4});
  const std::string over = read_error(b.i32(0).text("\n$EndElements\n").str());
  EXPECT_NE(over.find("expected $EndElements"), std::string::npos) << over;
  EXPECT_NE(offset_in(over), std::string::npos) << over;
}

// A partitioned entity's parent is a model entity, of dimension at most 3.
TEST(GmshIo, PartitionedEntityParentPastDimension3IsRefused) {
  const std::string text = replaced(slurp(testing::data_path("gmsh_partitioned41.msh")), "6 2 5 1 1 ", "6 4 5 1 1 ");
  const std::string message = testing::input_error_message([&] { read_text(text); }, text);
  EXPECT_NE(message.find("t.msh:31: partitioned entity of dimension 2 with tag 6 has a parent of dimension 4"),
            std::string::npos)
      << message;
}

// Dropping the partition-boundary triangle that comes first must shift the
// kept triangles' physical tags along with their nodes and numbers.
TEST(GmshIo, DroppedBoundaryElementsLeaveTheOthersTagsInPlace) {
  const std::string text =
      replaced(slurp(testing::data_path("gmsh_partitioned41.msh")),
               "2 6 2 1\n101 20 30 42\n2 7 2 1\n102 30 20 57\n2 8 2 1\n103 10 20 30\n",
               "2 8 2 1\n103 10 20 30\n2 6 2 1\n101 20 30 42\n2 7 2 1\n102 30 20 57\n");
  const TetMesh mesh = read_text(text);
  const PassThroughBlock* triangles = nullptr;
  for (const PassThroughBlock& block : mesh.extras.blocks)
    if (block.kind == "triangle") triangles = &block;
  ASSERT_NE(triangles, nullptr);
  EXPECT_EQ(triangles->element_tags, (std::vector<long long>{101, 102}));
  EXPECT_EQ(triangles->entity_tags, (std::vector<int>{5, 5}));
  EXPECT_EQ(triangles->tags, (std::vector<int>{3, 3}));  // surface 5's group, not volume 1's 7
}

// An $Entities body is whole records and nothing after them.
TEST(GmshIo, EntitiesTextWithTrailingValuesIsRefused) {
  const std::string body = "1 0 0 0\n1 0 0 0 0\n";
  EXPECT_EQ(gmsh::parse_entities_text(body, "e").count(0), 1u);
  EXPECT_THROW(gmsh::parse_entities_text(body + "2\n", "e"), InputError);
}

// A block added after reading has no entity tags: the file's $Entities
// cannot classify it, so entities are made up for every element instead.
TEST(GmshIo, BlockWithoutEntityTagsIsWrittenOnMadeUpEntities) {
  TetMesh mesh = read_text(replaced(kMinimal, "$EndMeshFormat\n",
                                    "$EndMeshFormat\n$Entities\n0 0 0 1\n1 0 0 0 1 1 1 1 7 0\n$EndEntities\n"));
  ASSERT_EQ(mesh.extras.tet_tags, (std::vector<int>{7}));
  mesh.extras.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 1, 2}, {}, {}, {}});
  for (MshFlavour flavour : {MshFlavour::V41Ascii, MshFlavour::V22Ascii}) {
    const TetMesh back = read_text(write_text(mesh, flavour));
    ASSERT_EQ(back.extras.blocks.size(), 1u);
    EXPECT_EQ(back.extras.blocks[0].connectivity, (std::vector<index_t>{0, 1, 2}));
    EXPECT_EQ(back.extras.blocks[0].entity_tags, (std::vector<int>{1}));
    EXPECT_EQ(back.extras.tet_entity_tags, (std::vector<int>{1}));
    EXPECT_EQ(back.extras.tet_tags, (std::vector<int>{7}));
  }
}

// Without the file's classification, MSH 4.1 output puts each node on the
// entity of an element that uses it: a node used only by tets of volume 2
// is in volume 2, whatever the volume of the first tet.
TEST(GmshIo, NodesAreClassifiedOnTheirOwnElementsEntity) {
  TetMesh mesh = testing::cube_grid(2);
  std::vector<std::vector<int>> volumes_of(mesh.num_nodes());
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    double cx = 0;
    for (int k = 0; k < 4; ++k) cx += mesh.xyz[3 * static_cast<std::size_t>(mesh.tets[4 * t + k])] / 4;
    const int volume = cx < 1 ? 1 : 2;
    mesh.extras.tet_entity_tags.push_back(volume);
    for (int k = 0; k < 4; ++k) volumes_of[static_cast<std::size_t>(mesh.tets[4 * t + k])].push_back(volume);
  }
  const TetMesh back = read_text(write_text(mesh, MshFlavour::V41Ascii));
  ASSERT_EQ(back.extras.node_entity_tags.size(), mesh.num_nodes());
  std::size_t only_in_2 = 0;
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) {
    const std::vector<int>& v = volumes_of[i];
    if (v.empty()) continue;
    EXPECT_EQ(back.extras.node_entity_dims[i], 3) << i;
    if (std::all_of(v.begin(), v.end(), [&](int x) { return x == v.front(); })) {
      EXPECT_EQ(back.extras.node_entity_tags[i], v.front()) << "node " << i;
      only_in_2 += v.front() == 2;
    }
  }
  EXPECT_GT(only_in_2, 0u);
}

// The other byte order with values whose every byte matters (a tag past
// 32 bits, an entity tag of four non-zero bytes, 1/3): each value is reversed
// whole, not only its outer bytes.
TEST(GmshIo, OtherByteOrderReversesEveryByte) {
  std::string s = "$MeshFormat\n4.1 1 8\n";
  const auto swapped = [&](const void* p, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) s += static_cast<const char*>(p)[n - 1 - i];
  };
  const auto u64 = [&](std::uint64_t v) { swapped(&v, 8); };
  const auto i32 = [&](std::int32_t v) { swapped(&v, 4); };
  const auto f64 = [&](double v) { swapped(&v, 8); };
  const std::uint64_t big = 0x0102030405060708ULL;
  const std::int32_t entity = 0x01020304;
  i32(1);
  s += "\n$EndMeshFormat\n$Nodes\n";
  for (std::uint64_t v : {std::uint64_t{1}, std::uint64_t{4}, std::uint64_t{1}, big}) u64(v);
  i32(3), i32(entity), i32(0), u64(4);
  for (std::uint64_t tag : {std::uint64_t{1}, std::uint64_t{2}, std::uint64_t{3}, big}) u64(tag);
  for (double v : {0.0, 0.0, 0.0, 1.0 / 3.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0}) f64(v);
  s += "\n$EndNodes\n$Elements\n";
  for (std::uint64_t v : {1, 1, 1, 1}) u64(v);
  i32(3), i32(entity), i32(4), u64(1);
  for (std::uint64_t v : {std::uint64_t{1}, std::uint64_t{1}, std::uint64_t{2}, std::uint64_t{3}, big}) u64(v);
  s += "\n$EndElements\n";
  const TetMesh mesh = read_text(s);
  EXPECT_EQ(mesh.xyz, (std::vector<double>{0, 0, 0, 1.0 / 3.0, 0, 0, 0, 1, 0, 0, 0, 1}));
  EXPECT_EQ(mesh.extras.node_tags, (std::vector<long long>{1, 2, 3, static_cast<long long>(big)}));
  EXPECT_EQ(mesh.extras.tet_entity_tags, (std::vector<int>{entity}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3}));
}

// ASCII values stored as 32-bit ints (entity tags, types, flags) that do
// not fit are refused, not wrapped onto another entity.
TEST(GmshIo, IntValuesPast32BitsAreRefused) {
  const std::string message = read_error(replaced(kMinimal, "3 1 4 1\n", "3 4294967297 4 1\n"));
  EXPECT_NE(message.find("t.msh:18: entity tag 4294967297 is out of the 32-bit range"), std::string::npos)
      << message;
}

// A binary unknown section is skipped up to its end line standing alone,
// not up to a longer name that starts with it.
TEST(GmshIo, BinarySkipStopsOnlyAtTheWholeEndLine) {
  Binary22 b;
  b.text("$Foo\n$EndFoo2\n$EndFoo\n").nodes({1, 2, 3, 4}).text("$Elements\n1\n").i32(4).i32(1).i32(2);
  const TetMesh mesh = read_text(b.tet(1, {1, 2, 3, 4}).text("\n$EndElements\n").str());
  EXPECT_EQ(mesh.num_tets(), 1u);
  EXPECT_EQ(mesh.extras.read_notes,
            (std::vector<std::string>{"$Foo section skipped; it will not be in the written file"}));
}

// Tets go in the mesh's tets; a pass-through "tetra" block would be read
// back as more tets, and a negative node index is no node: both refused.
TEST(GmshIo, WriterRefusesTetraBlocksAndNegativeNodeIndices) {
  TetMesh tetra = testing::regular_tet();
  tetra.extras.blocks.push_back(PassThroughBlock{"tetra", 4, {0, 1, 2, 3}, {}, {}, {}});
  EXPECT_THROW(write_text(tetra, MshFlavour::V41Ascii), OutputError);
  TetMesh past = testing::regular_tet();
  past.tets[3] = static_cast<index_t>(past.num_nodes());  // one past the last node
  EXPECT_THROW(write_text(past, MshFlavour::V41Ascii), OutputError);
  TetMesh negative = testing::regular_tet();
  negative.tets[0] = -1;
  EXPECT_THROW(write_text(negative, MshFlavour::V41Ascii), OutputError);
  TetMesh block = testing::regular_tet();
  block.extras.blocks.push_back(PassThroughBlock{"line", 2, {0, -1}, {}, {}, {}});
  EXPECT_THROW(write_text(block, MshFlavour::V22Ascii), OutputError);
}

// A partitioned surface whose file names no parent ("0 0") is an ordinary
// entity: its triangle stays, on its own tag.
TEST(GmshIo, PartitionedSurfaceWithoutParentKeepsItsElements) {
  const std::string text = replaced(slurp(testing::data_path("gmsh_partitioned41.msh")), "6 2 5 1 1 ", "6 0 0 1 1 ");
  const TetMesh mesh = read_text(text);
  const PassThroughBlock* triangles = nullptr;
  for (const PassThroughBlock& block : mesh.extras.blocks)
    if (block.kind == "triangle") triangles = &block;
  ASSERT_NE(triangles, nullptr);
  EXPECT_EQ(triangles->element_tags, (std::vector<long long>{101, 102}));
  EXPECT_EQ(triangles->entity_tags, (std::vector<int>{6, 5}));
}

// Quads lie on surfaces and wedges have six nodes: blocks of both read
// from MSH 4.1, and a curve's line comes back through the curve entity
// written for it (whose record ends in its bounding points).
TEST(GmshIo, QuadWedgeAndLineBlocksRoundTrip) {
  const TetMesh mesh = read_text(replaced(replaced(kMinimal, "$Elements\n1 1 1 1\n", "$Elements\n3 3 1 3\n"),
                                          "$EndElements\n", "2 1 3 1\n2 1 2 3 4\n3 1 6 1\n3 1 2 3 4 1 2\n$EndElements\n"));
  ASSERT_EQ(mesh.extras.blocks.size(), 2u);
  EXPECT_EQ(mesh.extras.blocks[0].kind, "quad");
  EXPECT_EQ(mesh.extras.blocks[1].kind, "wedge");
  EXPECT_EQ(mesh.extras.blocks[1].connectivity, (std::vector<index_t>{0, 1, 2, 3, 0, 1}));
  TetMesh lined = testing::regular_tet();
  lined.extras.blocks.push_back(PassThroughBlock{"line", 2, {0, 1}, {}, {}, {}});
  const TetMesh back = read_text(write_text(lined, MshFlavour::V41Ascii));
  ASSERT_EQ(back.extras.blocks.size(), 1u);
  EXPECT_EQ(back.extras.blocks[0].connectivity, (std::vector<index_t>{0, 1}));
}

// The $Nodes header gives the smallest then the largest node tag.
TEST(GmshIo, NodesHeaderGivesTheTagRange) {
  TetMesh mesh = testing::regular_tet();
  mesh.extras.node_tags = {7, 3, 9, 5};
  EXPECT_NE(write_text(mesh, MshFlavour::V41Ascii).find("$Nodes\n1 4 3 9\n"), std::string::npos);
}

}  // namespace
}  // namespace tetsmooth
