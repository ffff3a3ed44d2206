// TetGen .node/.ele: 0- and 1-based numbering, comments, attributes, markers
// and region attributes, exact round trips, and errors that name file:line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "mesh/errors.hpp"
#include "mesh/io/tetgen_io.hpp"
#include "support/scratch_dir.hpp"
#include "support/test_meshes.hpp"

namespace tetsmooth {
namespace {

namespace fs = std::filesystem;

class TetGenIo : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return scratch_.file(name); }

  testing::ScratchDir scratch_{"tetgen"};
  const fs::path dir_ = scratch_.path();
};

// The InputError message from reading the two texts as box.node / box.ele.
std::string read_error(const std::string& node, const std::string& ele) {
  std::istringstream n(node), e(ele);
  try {
    read_tetgen(n, "box.node", e, "box.ele");
  } catch (const InputError& err) {
    return err.what();
  }
  ADD_FAILURE() << "read_tetgen accepted\n" << node << "---\n" << ele;
  return "";
}

const char* kNode = "5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 1 1 1\n";
const char* kEle = "2 4 0\n0 0 1 2 3\n1 1 2 3 4\n";

TEST_F(TetGenIo, ReadsZeroBasedFileWithCommentsAttributesAndMarkers) {
  const TetMesh mesh = read_tetgen(testing::data_path("tetgen_commented.node"));
  ASSERT_EQ(mesh.num_nodes(), 5u);
  ASSERT_EQ(mesh.num_tets(), 2u);
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3, 1, 2, 3, 4}));
  EXPECT_EQ(mesh.xyz[3 * 4 + 2], 1.0);
  EXPECT_EQ(mesh.extras.node_markers, (std::vector<int>{1, 1, 0, 2, -1}));
  EXPECT_EQ(mesh.extras.node_attribute_count, 1);
  EXPECT_EQ(mesh.extras.node_attributes, (std::vector<double>{10.5, 11.5, 12.5, 13.5, 14.5}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{7, -3}));
  EXPECT_TRUE(mesh.fixed.empty()) << "markers must not pin nodes";
}

TEST_F(TetGenIo, OneBasedFileReadsAsZeroBased) {
  const TetMesh one = read_tetgen(testing::data_path("tetgen_one_based.ele"));
  const TetMesh zero = read_tetgen(testing::data_path("tetgen_commented"));
  EXPECT_EQ(one.tets, zero.tets);
  EXPECT_EQ(one.xyz, zero.xyz);
  EXPECT_TRUE(one.extras.node_markers.empty());
  EXPECT_TRUE(one.extras.tet_tags.empty());
}

TEST_F(TetGenIo, AcceptsNodeEleOrBaseName) {
  EXPECT_EQ(tetgen_base("a/b.node"), "a/b");
  EXPECT_EQ(tetgen_base("a/b.ele"), "a/b");
  EXPECT_EQ(tetgen_base("a/b"), "a/b");
  EXPECT_EQ(tetgen_base("a.node/b"), "a.node/b");
}

TEST_F(TetGenIo, RoundTripIsExact) {
  TetMesh mesh = testing::cube_grid(3, 0.3);  // jittered: coordinates with full mantissas
  const std::size_t n = mesh.num_nodes();
  mesh.extras.node_markers.resize(n);
  mesh.extras.node_attribute_count = 2;
  for (std::size_t i = 0; i < n; ++i) {
    mesh.extras.node_markers[i] = static_cast<int>(i % 3) - 1;
    mesh.extras.node_attributes.push_back(0.1 * static_cast<double>(i));
    mesh.extras.node_attributes.push_back(-1e-300 * static_cast<double>(i));
  }
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) mesh.extras.tet_tags.push_back(static_cast<int>(t % 4));

  write_tetgen(mesh, path("out.node"));
  ASSERT_TRUE(fs::exists(path("out.node")));
  ASSERT_TRUE(fs::exists(path("out.ele")));
  const TetMesh back = read_tetgen(path("out"));
  EXPECT_EQ(back.xyz, mesh.xyz);  // bit-exact: shortest round-trip decimal form
  EXPECT_EQ(back.tets, mesh.tets);
  EXPECT_EQ(back.extras.node_markers, mesh.extras.node_markers);
  EXPECT_EQ(back.extras.node_attribute_count, 2);
  EXPECT_EQ(back.extras.node_attributes, mesh.extras.node_attributes);
  EXPECT_EQ(back.extras.tet_tags, mesh.extras.tet_tags);
}

TEST_F(TetGenIo, WritesOneBasedNumberingAndPlainHeaders) {
  write_tetgen(testing::regular_tet(), path("t"));
  std::ifstream node(path("t.node")), ele(path("t.ele"));
  std::string line;
  std::getline(node, line);
  EXPECT_EQ(line, "4 3 0 0");
  std::getline(node, line);
  EXPECT_EQ(line.substr(0, 2), "1 ");
  std::getline(ele, line);
  EXPECT_EQ(line, "1 4 0");
  std::getline(ele, line);
  EXPECT_EQ(line, "1 1 2 3 4");
}

TEST_F(TetGenIo, WriteIntoMissingDirectoryFailsWithoutLeavingFiles) {
  try {
    write_tetgen(testing::regular_tet(), path("missing/x"));
    FAIL() << "no OutputError";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("missing/x.node"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(TetGenIo, MissingFileNamesThePath) {
  try {
    read_tetgen(path("nothing"));
    FAIL() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nothing.node"), std::string::npos) << e.what();
  }
}

TEST(TetGenErrors, TruncatedNodeFile) {
  const std::string msg = read_error("5 3 0 0\n0 0 0 0\n1 1 0 0\n", kEle);
  EXPECT_NE(msg.find("box.node:3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("end of file"), std::string::npos) << msg;
}

TEST(TetGenErrors, TruncatedEleFile) {
  const std::string msg = read_error(kNode, "3 4 0\n0 0 1 2 3\n1 1 2 3 4\n");
  EXPECT_NE(msg.find("box.ele:3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("tet 3 of 3"), std::string::npos) << msg;
}

TEST(TetGenErrors, MoreEntriesThanDeclared) {
  std::string msg = read_error("4 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 1\n4 1 1 1\n", kEle);
  EXPECT_NE(msg.find("box.node:6: more data than the 4 nodes"), std::string::npos) << msg;
  msg = read_error(kNode, "1 4 0\n0 0 1 2 3\n1 1 2 3 4\n# comment\n");
  EXPECT_NE(msg.find("box.ele:3: more data than the 1 tets"), std::string::npos) << msg;
}

TEST(TetGenErrors, NonNumericToken) {
  const std::string msg = read_error("5 3 0 0\n0 0 0 0\n1 1 zero 0\n2 0 1 0\n3 0 0 1\n4 1 1 1\n", kEle);
  EXPECT_NE(msg.find("box.node:3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'zero'"), std::string::npos) << msg;
}

TEST(TetGenErrors, MissingCoordinate) {
  const std::string msg = read_error("5 3 0 0\n0 0 0 0\n1 1 0\n2 0 1 0\n3 0 0 1\n4 1 1 1\n", kEle);
  EXPECT_NE(msg.find("box.node:3"), std::string::npos) << msg;
}

TEST(TetGenErrors, NonFiniteCoordinate) {
  for (const char* bad : {"nan", "inf", "-inf", "1e999"}) {
    const std::string node = std::string("5 3 0 0\n0 0 0 0\n1 1 0 0\n2 0 1 0\n3 0 0 ") + bad + "\n4 1 1 1\n";
    const std::string msg = read_error(node, kEle);
    EXPECT_NE(msg.find("box.node:5"), std::string::npos) << msg;
  }
}

TEST(TetGenErrors, IndexOutOfRange) {
  const std::string msg = read_error(kNode, "2 4 0\n0 0 1 2 3\n1 1 2 3 5\n");
  EXPECT_NE(msg.find("box.ele:3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("node number 5 out of range [0, 5)"), std::string::npos) << msg;
}

TEST(TetGenErrors, OneBasedIndexZeroIsOutOfRange) {
  const std::string msg =
      read_error("5 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n5 1 1 1\n", "2 4 0\n1 1 2 3 4\n2 0 2 3 4\n");
  EXPECT_NE(msg.find("box.ele:3"), std::string::npos) << msg;
}

TEST(TetGenErrors, BadHeaders) {
  EXPECT_NE(read_error("", kEle).find("box.node:1: unexpected end of file"), std::string::npos);
  EXPECT_NE(read_error("5 2 0 0\n", kEle).find("box.node:1: dimension 2"), std::string::npos);
  EXPECT_NE(read_error("-5 3 0 0\n", kEle).find("box.node:1"), std::string::npos);
  // A 10-node header over 4-node rows runs out of nodes on the first row.
  EXPECT_NE(read_error(kNode, "2 10 0\n0 0 1 2 3\n1 1 2 3 4\n").find("box.ele:2:"), std::string::npos);
  EXPECT_NE(read_error(kNode, "2 4 -1\n").find("box.ele:1"), std::string::npos);
  EXPECT_NE(read_error(kNode, "0 4 0\n").find("box.ele:1"), std::string::npos);
}

// Each header field is refused by its own check, with its value: without
// them a bad count would still fail, but later and as something else (a
// truncation, a missing tet), and a marker flag of 2 would be read as 1.
TEST(TetGenErrors, BadHeaderFieldsAreNamedWithTheirValue) {
  EXPECT_NE(read_error("-5 3 0 0\n", kEle).find("box.node:1: invalid node count -5"), std::string::npos);
  EXPECT_NE(read_error("3000000000 3 0 0\n", kEle).find("box.node:1: invalid node count 3000000000"),
            std::string::npos);
  EXPECT_NE(read_error("0 3 0 0\n", kEle).find("box.node:1: the .node file declares no nodes"), std::string::npos);
  EXPECT_NE(read_error("5 3 0 2\n", kEle).find("box.node:1: boundary marker flag must be 0 or 1, found 2"),
            std::string::npos);
  EXPECT_NE(read_error(kNode, "2 8 0\n").find("box.ele:1: nodes per tet must be 4 or 10, found 8"), std::string::npos);
  // A whole marker past int would wrap if it were cast unchecked.
  EXPECT_NE(read_error("5 3 0 1\n0 0 0 0 3000000000\n", kEle)
                .find("box.node:2: boundary marker 3000000000 out of range"),
            std::string::npos);
}

// A header that claims two billion nodes over a file of one: the reader
// must end in "unexpected end of file" after line 2, not try to reserve room
// for the claim first (48 GB of coordinates, a bad_alloc on most hosts).
TEST(TetGenErrors, LyingNodeCountEndsInATruncationError) {
  const std::string msg = read_error("2000000000 3 0 0\n0 0 0 0\n", kEle);
  EXPECT_NE(msg.find("box.node:2: unexpected end of file, expected node 2 of 2000000000"), std::string::npos) << msg;
}

TEST(TetGenErrors, NodeNumbering) {
  EXPECT_NE(read_error("2 3 0 0\n2 0 0 0\n3 1 0 0\n", kEle).find("box.node:2: the first node number"),
            std::string::npos);
  EXPECT_NE(read_error("5 3 0 0\n0 0 0 0\n1 1 0 0\n3 0 1 0\n", kEle).find("box.node:4: node number 3 out of sequence"),
            std::string::npos);
}

// TetGen's region attributes are reals. Where one is not a whole number in
// int range, the regions are tagged by rank of value, and the attributes
// themselves are kept for TetGen output.
TEST_F(TetGenIo, RegionAttributesThatAreNotWholeAreRankedAndWrittenBack) {
  for (const auto& [first, why] : {std::pair{"1.5", "region attribute 1.5 is not a whole number"},
                                   std::pair{"3e9", "region attribute 3e+09 is not a whole number in int range"}}) {
    std::istringstream n(kNode), e("3 4 1\n0 0 1 2 3 " + std::string(first) + "\n1 1 2 3 4 -0.25\n2 0 1 2 4 " +
                                   first + "\n");
    const TetMesh mesh = read_tetgen(n, "box.node", e, "box.ele");
    EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{2, 1, 2})) << first;
    ASSERT_EQ(mesh.extras.read_notes.size(), 1u);
    EXPECT_NE(mesh.extras.read_notes[0].find(why), std::string::npos) << mesh.extras.read_notes[0];
    EXPECT_NE(mesh.extras.read_notes[0].find("the 2 regions are tagged 1, 2, ..."), std::string::npos);
    EXPECT_EQ(mesh.extras.tet_attribute_count, 1);
    write_tetgen(mesh, path("ranked"));
    const TetMesh back = read_tetgen(path("ranked"));
    EXPECT_EQ(back.extras.tet_attributes, mesh.extras.tet_attributes);
    EXPECT_EQ(back.extras.tet_tags, mesh.extras.tet_tags);
  }
}

// Several attributes a tet (TetGen keeps an input's on refinement): the
// first is the region, and all of them are written back.
TEST_F(TetGenIo, SeveralTetAttributesAreKept) {
  std::istringstream n(kNode), e("2 4 3\n0 0 1 2 3 1e6 0.5 1e-3\n1 1 2 3 4 -3 2 -1e300\n");
  const TetMesh mesh = read_tetgen(n, "box.node", e, "box.ele");
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{1000000, -3}));
  EXPECT_TRUE(mesh.extras.read_notes.empty());
  EXPECT_EQ(mesh.extras.tet_attribute_count, 3);
  EXPECT_EQ(mesh.extras.tet_attributes, (std::vector<double>{1e6, 0.5, 1e-3, -3, 2, -1e300}));
  write_tetgen(mesh, path("three"));
  std::ifstream ele(path("three.ele"));
  std::string line;
  std::getline(ele, line);
  EXPECT_EQ(line, "2 4 3");
  std::getline(ele, line);
  EXPECT_EQ(line, "1 1 2 3 4 1000000 0.5 0.001");  // whole numbers as integers, as meshio reads them
  EXPECT_EQ(read_tetgen(path("three")).extras.tet_attributes, mesh.extras.tet_attributes);
  // One whole region attribute needs no copy: the tags give it back.
  // The ends of int's range are tags as they are (-2^31 is an int too).
  std::istringstream n2(kNode), e2("2 4 1\n0 0 1 2 3 2147483647\n1 1 2 3 4 -2147483648\n");
  const TetMesh ends = read_tetgen(n2, "box.node", e2, "box.ele");
  EXPECT_EQ(ends.extras.tet_tags, (std::vector<int>{2147483647, -2147483647 - 1}));
  EXPECT_TRUE(ends.extras.read_notes.empty());
  std::istringstream n1(kNode), e1("2 4 1\n0 0 1 2 3 7\n1 1 2 3 4 -3\n");
  const TetMesh one = read_tetgen(n1, "box.node", e1, "box.ele");
  EXPECT_TRUE(one.extras.tet_attributes.empty());
  EXPECT_EQ(one.extras.tet_attribute_count, 0);
}

// A node attribute count without values (validate_mesh accepts it: the
// values were not kept) writes a node file with no attribute columns that
// reads back, rather than a header promising columns the rows lack.
TEST_F(TetGenIo, NodeAttributeCountWithoutValuesWritesNoAttributes) {
  TetMesh mesh = testing::regular_tet();
  mesh.extras.node_attribute_count = 2;
  write_tetgen(mesh, path("bare"));
  std::ifstream node(path("bare.node"));
  std::string header;
  std::getline(node, header);
  EXPECT_EQ(header, "4 3 0 0");
  const TetMesh back = read_tetgen(path("bare"));
  EXPECT_EQ(back.xyz, mesh.xyz);
  EXPECT_TRUE(back.extras.node_attributes.empty());
}

// A tet attribute of -0.0 is not a whole number to write as "0": the
// round trip must keep its sign bit, as it keeps every other bit.
TEST_F(TetGenIo, NegativeZeroTetAttributeKeepsItsSign) {
  TetMesh mesh = testing::regular_tet();
  mesh.extras.tet_attribute_count = 2;
  mesh.extras.tet_attributes = {3, -0.0};
  write_tetgen(mesh, path("signed"));
  const TetMesh back = read_tetgen(path("signed"));
  ASSERT_EQ(back.extras.tet_attributes.size(), 2u);
  EXPECT_EQ(back.extras.tet_attributes[1], 0.0);
  EXPECT_TRUE(std::signbit(back.extras.tet_attributes[1]));
}

TEST(TetGenErrors, MissingTetAttributeNamesTheLine) {
  const std::string msg = read_error(kNode, "2 4 2\n0 0 1 2 3 1 4\n1 1 2 3 4 1\n");
  EXPECT_NE(msg.find("box.ele:3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("tet attribute"), std::string::npos) << msg;
}

TEST(TetGenErrors, ReadsRegionAttributesWrittenAsReals) {
  std::istringstream n(kNode), e("2 4 1\n0 0 1 2 3 1.0\n1 1 2 3 4 -2e0\n");
  EXPECT_EQ(read_tetgen(n, "box.node", e, "box.ele").extras.tet_tags, (std::vector<int>{1, -2}));
}

// meshio writes the markers of its float point data as "1.0"; TetGen reads
// them with strtol. A whole value in any form is a marker, "1.5" is not.
TEST(TetGenErrors, BoundaryMarkersWrittenAsWholeRealsAreRead) {
  const std::string node = "5 3 0 1\n0 0 0 0 1.0\n1 1 0 0 -2e0\n2 0 1 0 0.0\n3 0 0 1 1E+1\n4 1 1 1 3\n";
  std::istringstream n(node), e(kEle);
  EXPECT_EQ(read_tetgen(n, "box.node", e, "box.ele").extras.node_markers, (std::vector<int>{1, -2, 0, 10, 3}));
  std::string msg = read_error("5 3 0 1\n0 0 0 0 1\n1 1 0 0 1.5\n2 0 1 0 0\n3 0 0 1 0\n4 1 1 1 0\n", kEle);
  EXPECT_NE(msg.find("box.node:3: expected an integer boundary marker, found '1.5'"), std::string::npos) << msg;
  msg = read_error("5 3 0 1\n0 0 0 0 1\n1 1 0 0 1e30\n2 0 1 0 0\n3 0 0 1 0\n4 1 1 1 0\n", kEle);
  EXPECT_NE(msg.find("box.node:3: expected an integer boundary marker, found '1e30'"), std::string::npos) << msg;
}

}  // namespace
}  // namespace tetsmooth
