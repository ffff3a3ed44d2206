// FLAC3D grids: gridpoints, zones of every type (bricks, wedges and pyramids
// reordered to VTK's corners), faces, groups in several slots as region
// tags, pins, the grid written back with only moved gridpoints changed, new
// grids that read back as written, and errors naming file:line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "mesh/errors.hpp"
#include "mesh/io/flac3d_io.hpp"
#include "mesh/io/mesh_io.hpp"
#include "mesh/io/writable_check.hpp"
#include "mesh/second_order.hpp"
#include "support/input_error.hpp"
#include "support/same_partition.hpp"
#include "support/test_meshes.hpp"

namespace tetsmooth {
namespace {

TetMesh read_text(const std::string& text) {
  std::istringstream in(text);
  return read_flac3d(in, "t.f3grid");
}

std::string write_text(const TetMesh& mesh) {
  std::ostringstream out;
  write_flac3d(mesh, out);
  return out.str();
}

std::string read_error(const std::string& text) {
  return testing::input_error_message([&] { read_text(text); }, "read_flac3d:\n" + text);
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// tests/data/flac3d_mixed.f3grid: a brick (zone 1), a wedge (2) and a
// pyramid (3) over a cube of twelve tets (zones 11 to 22) round gridpoint
// 30, a cut brick (4) apart, faces, groups in two slots and a pin comment;
// gridpoint ids 1-11, 21-24, 30 and 40-46, written in several ways.
std::string fixture() {
  std::ifstream in(testing::data_path("flac3d_mixed.f3grid"), std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The node index of each gridpoint id of the fixture.
int node_of(const TetMesh& mesh, long long id) {
  const auto& tags = mesh.extras.node_tags;
  return static_cast<int>(std::find(tags.begin(), tags.end(), id) - tags.begin());
}

const PassThroughBlock* block_of(const TetMesh& mesh, const std::string& kind) {
  for (const PassThroughBlock& b : mesh.extras.blocks)
    if (b.kind == kind) return &b;
  return nullptr;
}

std::string raw(const TetMesh& mesh, const std::string& name) {
  const std::string* body = raw_section(mesh.extras, name);
  return body == nullptr ? "(none)" : *body;
}

TEST(Flac3dIo, ReadsZonesFacesGroupsAndPins) {
  const TetMesh mesh = read_text(fixture());
  const FileExtras& e = mesh.extras;
  ASSERT_EQ(mesh.num_nodes(), 23u);
  EXPECT_EQ(e.node_tags, (std::vector<long long>{1,  2,  3,  4,  5,  6,  7,  8,  9,  10, 11, 21,
                                                 22, 23, 24, 30, 40, 41, 42, 43, 44, 45, 46}));
  // "g 9 2 0 0", "G<tab>10<tab>2.0...e+00", "G 11, 0.5, 0.5, 2".
  EXPECT_EQ(std::vector<double>(mesh.xyz.begin() + 24, mesh.xyz.begin() + 33),
            (std::vector<double>{2, 0, 0, 2, 1, 0, 0.5, 0.5, 2}));
  ASSERT_EQ(mesh.num_tets(), 12u);
  EXPECT_EQ(e.tet_element_tags, (std::vector<long long>{11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22}));
  // Z T4 11 1 5 2 30, as listed.
  EXPECT_EQ(std::vector<index_t>(mesh.tets.begin(), mesh.tets.begin() + 4),
            (std::vector<index_t>{0, 4, 1, static_cast<index_t>(node_of(mesh, 30))}));

  // Blocks in the order their kinds come, corners in VTK's order.
  ASSERT_EQ(e.blocks.size(), 5u);
  const std::string kinds[] = {"hexahedron", "wedge", "pyramid", "triangle", "quad"};
  for (std::size_t b = 0; b < 5; ++b) EXPECT_EQ(e.blocks[b].kind, kinds[b]);
  // Brick 1..8 (origin, x, y, z, xy, yz, xz, xyz): bottom 1 2 5 3, top 4 7 8 6.
  EXPECT_EQ(block_of(mesh, "hexahedron")->connectivity, (std::vector<std::int32_t>{0, 1, 4, 2, 3, 6, 7, 5}));
  // Wedge 2 9 5 7 10 8: triangles (2 7 9) and (5 8 10), the one over the
  // other, the first wound into the cell (as Gmsh's).
  EXPECT_EQ(block_of(mesh, "wedge")->connectivity, (std::vector<std::int32_t>{1, 6, 8, 4, 7, 9}));
  // Pyramid 4 7 6 11 8: base 4 7 8 6, apex 11.
  EXPECT_EQ(block_of(mesh, "pyramid")->connectivity, (std::vector<std::int32_t>{3, 6, 7, 5, 10}));
  EXPECT_EQ(block_of(mesh, "triangle")->connectivity, (std::vector<std::int32_t>{11, 12, 14, 11, 14, 13}));
  EXPECT_EQ(block_of(mesh, "quad")->element_tags, (std::vector<long long>{3}));
  EXPECT_EQ(block_of(mesh, "wedge")->element_tags, (std::vector<long long>{2}));

  // Regions: {Soil, excavated} (zones 1, 11, 12), {Soil} (2, 3, 13-16), no
  // group (the cut brick 4), {Rock} (17-22), numbered in zone order.
  EXPECT_EQ(e.tet_tags, (std::vector<int>{1, 1, 2, 2, 2, 2, 4, 4, 4, 4, 4, 4}));
  EXPECT_EQ(block_of(mesh, "hexahedron")->tags, (std::vector<int>{1}));
  EXPECT_EQ(block_of(mesh, "pyramid")->tags, (std::vector<int>{2}));
  EXPECT_EQ(block_of(mesh, "triangle")->tags, (std::vector<int>{1, 1}));
  EXPECT_EQ(block_of(mesh, "quad")->tags, (std::vector<int>{2}));
  // Names: the groups, "slot=group" outside the default slot.
  EXPECT_EQ(raw(mesh, "$PhysicalNames"),
            "5\n3 1 \"Soil layer + stage 1=excavated\"\n3 2 \"Soil layer\"\n3 4 \"Rock\"\n"
            "2 1 \"bottom\"\n2 2 \"top\"\n");

  // Every gridpoint of a zone other than a tet, of a face or of the pin
  // comment is pinned: all but 30.
  ASSERT_EQ(mesh.fixed.size(), mesh.num_nodes());
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) EXPECT_EQ(mesh.fixed[i], e.node_tags[i] != 30) << e.node_tags[i];
  EXPECT_EQ(raw(mesh, "flac3d:cut-bricks"), "1");
}

TEST(Flac3dIo, WritesTheGridBackChangingOnlyTheLinesOfMovedGridpoints) {
  const std::string text = fixture();
  TetMesh mesh = read_text(text);
  EXPECT_EQ(write_text(mesh), text);
  const int centre = node_of(mesh, 30);
  mesh.xyz[3 * centre] = 0.5;
  mesh.xyz[3 * centre + 1] = 1.0 / 3;
  const std::string moved = write_text(mesh);
  EXPECT_EQ(moved, replaced(text, "G 30 0.4 0.55 -0.45\n", "G 30 0.5 0.3333333333333333 -0.45\n"));
  const TetMesh again = read_text(moved);
  EXPECT_EQ(again.xyz, mesh.xyz);
  EXPECT_EQ(again.tets, mesh.tets);

  // CRLF lines, and a byte order mark, stay as they were.
  std::string crlf = "\xEF\xBB\xBF";
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  TetMesh windows = read_text(crlf);
  EXPECT_EQ(write_text(windows), crlf);
  windows.xyz[3 * centre + 2] = -0.5;
  EXPECT_EQ(write_text(windows), replaced(crlf, "G 30 0.4 0.55 -0.45\r\n", "G 30 0.4 0.55 -0.5\r\n"));
}

// Records of other kinds (a gridpoint group, say, which some exporters may
// write) and the ids after them are kept and named, not refused.
TEST(Flac3dIo, RecordsOfOtherKindsAreKeptWithANote) {
  const std::string text = replaced(fixture(), "* FACES\n", "GPGROUP 'Fixed' SLOT 'Default'\n 21 22\n\n 23\n* FACES\n");
  TetMesh mesh = read_text(text);
  EXPECT_EQ(mesh.extras.read_notes,
            (std::vector<std::string>{"records of kinds tetsmooth does not read, 'GPGROUP' (line 53), are kept in "
                                      "FLAC3D output and left out of other formats; gridpoints they name are not "
                                      "pinned: list those that must stay on a '* TETSMOOTH PINNED' line"}));
  EXPECT_EQ(write_text(mesh), text);
  EXPECT_EQ(read_text(fixture()).tets, mesh.tets);
}

TEST(Flac3dIo, AGridIsWrittenOnlyForTheMeshItWasReadWith) {
  TetMesh mesh = read_text(fixture());
  mesh.tets.resize(4 * 11);
  try {
    write_text(mesh);
    FAIL() << "a grid written for another mesh";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("the FLAC3D grid read with this mesh lists (nodes, tets) 23 12, and the mesh "
                                         "has 23 11"),
              std::string::npos)
        << e.what();
  }
}

TEST(Flac3dIo, ANewGridReadsBackAsWritten) {
  TetMesh mesh = read_text(fixture());
  auto& sections = mesh.extras.raw_sections;
  sections.erase(
      std::remove_if(sections.begin(), sections.end(), [](const auto& s) { return s.first.rfind("flac3d:", 0) == 0; }),
      sections.end());
  const std::string text = write_text(mesh);
  // Ids as the file had them, zones and faces numbered apart; the cut brick
  // is not written, its gridpoints listed as pins.
  EXPECT_NE(text.find("\nG 30 0.4 0.55 -0.45\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nZ T4 11 1 5 2 30\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nZ B8 1 1 2 3 4 5 6 7 8\nZ W6 2 2 9 5 7 10 8\nZ P5 3 4 7 6 11 8\n"), std::string::npos) << text;
  // Each group once, in its slot, read back from the regions' names.
  EXPECT_NE(text.find("\nZGROUP \"Soil layer\" SLOT Default\n 11 12 1 13 14 15 16 2 3\nZGROUP \"excavated\" SLOT "
                      "\"stage 1\"\n 11 12 1\nZGROUP \"Rock\" SLOT Default\n 17 18 19 20 21 22\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("\nF T3 1 21 22 24\nF T3 2 21 24 23\nF Q4 3 4 7 8 6\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nFGROUP \"top\" SLOT Default\n 3\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\n* TETSMOOTH PINNED 40 41 42 43 44 45 46\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("B7"), std::string::npos) << text;

  const TetMesh again = read_text(text);
  EXPECT_EQ(again.xyz, mesh.xyz);
  EXPECT_EQ(again.tets, mesh.tets);
  EXPECT_EQ(again.fixed, mesh.fixed);
  EXPECT_EQ(again.extras.tet_element_tags, mesh.extras.tet_element_tags);
  ASSERT_EQ(again.extras.blocks.size(), mesh.extras.blocks.size());
  for (std::size_t b = 0; b < mesh.extras.blocks.size(); ++b) {
    EXPECT_EQ(again.extras.blocks[b].connectivity, mesh.extras.blocks[b].connectivity) << b;
    EXPECT_EQ(again.extras.blocks[b].element_tags, mesh.extras.blocks[b].element_tags) << b;
  }
  // The groups give the same regions; the cut brick's has gone with it.
  EXPECT_TRUE(testing::same_partition(again.extras.tet_tags, mesh.extras.tet_tags));
  EXPECT_EQ(raw(again, "$PhysicalNames"),
            "5\n3 1 \"Soil layer + stage 1=excavated\"\n3 2 \"Soil layer\"\n3 3 \"Rock\"\n"
            "2 1 \"bottom\"\n2 2 \"top\"\n");
}

// Groups as FLAC3D takes them: one name (in any case) in one slot is one
// group however many headers list it, a zone is in one group a slot (the
// last), and "Default", no slot and "1" name the default slot.
TEST(Flac3dIo, GroupsAreMergedByNameAndSlotAndTheLastOfASlotHoldsAZone) {
  const std::string grid =
      "G 1 0 0 0\nG 2 1 0 0\nG 3 0 1 0\nG 4 0 0 1\nG 5 1 1 1\n"
      "Z T4 1 1 2 3 4\nZ T4 2 2 5 3 4\nZ T4 3 1 2 3 5\n"
      "* tetsmooth pinned these by hand:\n"
      "* TETSMOOTH PINNED 5 and more\n"
      "ZGROUP 'Rock' SLOT 'Default'\n 1\n"
      "* a comment among the ids\n 1\n"
      "ZGROUP ROCK\n 2\n"
      "ZGROUP 'A' SLOT 'x'\n 1 2 3\n"
      "ZGROUP 'B' SLOT 'X'\n 3\n";
  const TetMesh mesh = read_text(grid);
  // Zones 1 and 2: Rock and A; zone 3: B only (listed in A, then in B).
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{1, 1, 2}));
  EXPECT_EQ(raw(mesh, "$PhysicalNames"), "2\n3 1 \"Rock + x=A\"\n3 2 \"x=B\"\n");
  // The pin comments are no lists of ids: they pin nothing, with a note.
  EXPECT_TRUE(mesh.fixed.empty());
  EXPECT_EQ(mesh.extras.read_notes,
            (std::vector<std::string>{"lines 9, 10: a '* TETSMOOTH PINNED' comment whose words are not all gridpoint "
                                      "ids pins nothing",
                                      "1 zone is listed in two groups of one slot: each is taken to be in the last, "
                                      "as FLAC3D does"}));
  // A name with a tab (in quotes) is one line of $PhysicalNames.
  EXPECT_EQ(raw(read_text(grid + "ZGROUP 'C\td'\n 2\n"), "$PhysicalNames").find("\t"), std::string::npos);

  // A new grid gives each group its zones once; names that are no groups of
  // different slots are one group, a tag whose groups another tag has got
  // (in any case, order or spelling of the default slot) is set apart, and
  // the one tag without a name gets no group.
  TetMesh fresh = testing::cube_with_centre();
  fresh.extras.tet_tags = {1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6};
  fresh.extras.raw_sections.emplace_back("$PhysicalNames",
                                         "5\n3 1 \"Soil + stage 1=dug\"\n3 2 \"Soil\"\n3 3 \"a + b\"\n"
                                         "3 4 \"stage 1=dug + 1=soil\"\n3 5 \"'E=200'\"\n");
  const std::string text = write_text(fresh);
  EXPECT_NE(
      text.find("ZGROUP \"Soil\" SLOT Default\n 1 2 3 4\nZGROUP \"dug\" SLOT \"stage 1\"\n 1 2\n"
                "ZGROUP \"a + b\" SLOT Default\n 5 6\nZGROUP \"stage 1=dug + 1=soil (tag 4)\" SLOT Default\n 7 8\n"
                "ZGROUP \"E=200\" SLOT Default\n 9 10\n* FACES\n"),
      std::string::npos)
      << text;
  const TetMesh again = read_text(text);
  EXPECT_TRUE(testing::same_partition(again.extras.tet_tags, fresh.extras.tet_tags));
  // Names that hold "=", " + " or quotes are quoted, and read back so.
  EXPECT_EQ(raw(again, "$PhysicalNames"),
            "5\n3 1 \"Soil + stage 1=dug\"\n3 2 \"Soil\"\n3 3 \"'a + b'\"\n"
            "3 4 \"'stage 1=dug + 1=soil (tag 4)'\"\n3 5 \"'E=200'\"\n");
  // A new grid from those names has the same groups again.
  TetMesh twice = again;
  auto& sections = twice.extras.raw_sections;
  sections.erase(std::remove_if(sections.begin(), sections.end(),
                                [](const auto& section) { return section.first.rfind("flac3d:", 0) == 0; }),
                 sections.end());
  const std::string text_again = write_text(twice);
  EXPECT_EQ(text_again.substr(text_again.find("* ZONE GROUPS")), text.substr(text.find("* ZONE GROUPS")));
}

TEST(Flac3dIo, ZonesOfOtherFormatsAreWrittenRightHanded) {
  // A unit brick in VTK's order, and one mirrored (z flipped), over one tet;
  // region tags without names, a line to drop.
  TetMesh mesh;
  for (const double z : {1.0, -1.0})
    for (const auto& p : {std::array<double, 3>{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}})
      for (const double level : {0.0, 1.0}) mesh.xyz.insert(mesh.xyz.end(), {p[0], p[1], z * (level + 2)});
  // Nodes 8k + 2c (+1 above) for corner c of square k (k = 0 up, 1 down).
  mesh.tets = {0, 2, 6, 1};
  const auto hex = [](int k) {
    return std::vector<std::int32_t>{8 * k,     8 * k + 2, 8 * k + 4, 8 * k + 6,
                                     8 * k + 1, 8 * k + 3, 8 * k + 5, 8 * k + 7};
  };
  std::vector<std::int32_t> hexes = hex(0), down = hex(1);
  hexes.insert(hexes.end(), down.begin(), down.end());
  mesh.extras.blocks.push_back(PassThroughBlock{"hexahedron", 8, hexes, {7, 7}, {}, {}});
  mesh.xyz.insert(mesh.xyz.end(), {5, 5, 5});  // node 16, in the line alone
  mesh.extras.blocks.push_back(PassThroughBlock{"line", 2, {0, 16}, {}, {}, {}});
  mesh.extras.tet_tags = {-3};
  const std::string text = write_text(mesh);
  // The brick below lists its corners mirrored (x and y swapped).
  EXPECT_NE(text.find("\nZ B8 2 1 3 7 2 5 8 4 6\nZ B8 3 9 15 11 10 13 12 16 14\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nZGROUP \"region -3\" SLOT Default\n 1\nZGROUP \"region 7\" SLOT Default\n 2 3\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("\n* TETSMOOTH PINNED 17\n"), std::string::npos) << text;
  const TetMesh again = read_text(text);
  // The brick above reads back as written; the one below mirrored.
  ASSERT_EQ(again.extras.blocks.size(), 1u);
  EXPECT_EQ(std::vector<std::int32_t>(again.extras.blocks[0].connectivity.begin(),
                                      again.extras.blocks[0].connectivity.begin() + 8),
            hex(0));
  EXPECT_EQ(std::vector<std::int32_t>(again.extras.blocks[0].connectivity.begin() + 8,
                                      again.extras.blocks[0].connectivity.end()),
            (std::vector<std::int32_t>{8, 14, 12, 10, 9, 15, 13, 11}));
  EXPECT_EQ(again.fixed[16], 1);
}

// Ids past FLAC3D's 2^31 - 1 (a Gmsh or Abaqus file may have them): a new
// grid numbers the gridpoints 1, 2, ... and says so before the work.
TEST(Flac3dIo, IdsPastTheLargestAreRenumberedWithANote) {
  TetMesh mesh = testing::cube_with_centre();
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i)
    mesh.extras.node_tags.push_back(3000000000LL + static_cast<long long>(i));
  const std::vector<std::string> notes = output_losses(mesh, "out.f3grid");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0],
            "the node numbers of the file cannot all be kept (each must be positive and distinct, at most "
            "2,147,483,647): flac3d numbers them 1, 2, ... instead");
  const std::string text = write_text(mesh);
  EXPECT_NE(text.find("\nG 1 "), std::string::npos) << text;
  EXPECT_EQ(text.find("3000000000"), std::string::npos) << text;
  EXPECT_EQ(read_text(text).xyz, mesh.xyz);
}

TEST(Flac3dIo, SecondOrderTetsAreRefused) {
  const TetMesh mesh = testing::with_midsides(testing::cube_grid(1));
  try {
    check_writable(mesh, "out.f3grid");
    FAIL() << "10-node tets written to FLAC3D";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("FLAC3D output holds 4-node tets only"), std::string::npos) << e.what();
  }
}

TEST(Flac3dIo, ErrorsNameTheFileAndLine) {
  const std::string text = fixture();
  const std::pair<std::string, std::string> cases[] = {
      {replaced(text, "G 21 0 0 -1", "G 99999999999999999999 0 0 -1"),
       "t.f3grid:15: gridpoint id '99999999999999999999' is out of range"},
      {replaced(text, "G 21 0 0 -1", "G 21 0 0 1.5D+00"), "t.f3grid:15: coordinate z '1.5D+00' is not a number"},
      {replaced(text, "G 21 0 0 -1", "G 21 0 0 1e-400"),
       "t.f3grid:15: coordinate z '1e-400' is out of the range of a double"},
      {replaced(text, "G 21 0 0 -1", "G 21 0 0 inf"), "t.f3grid:15: coordinate z 'inf' is not finite"},
      {"\xFF\xFEG", "t.f3grid: UTF-16 text (as Windows PowerShell saves it): save the grid as ASCII or UTF-8"},
      {"G 1 0 0 0\rG 2 1 0 0\r",
       "t.f3grid: lines that end in a carriage return alone: save the grid with LF or CRLF line ends"},
      {replaced(text, "G 21 0 0 -1", "G 21 0 0"),
       "t.f3grid:15: a gridpoint is 'G id x y z', and this line has 4 values"},
      {replaced(text, "G 21 0 0 -1", "G 21 0 0 -1x"), "t.f3grid:15: coordinate z '-1x' is not a number"},
      {replaced(text, "G 22 1 0 -1", "G 21 1 0 -1"), "t.f3grid:16: gridpoint 21 is defined a second time"},
      {replaced(text, "G 22 1 0 -1", "G 0 1 0 -1"), "t.f3grid:16: gridpoint id 0 is not positive"},
      {replaced(text, "Z W6 2 2 9 5 7 10 8", "Z W6 2 2 9 5 7 10"),
       "t.f3grid:29: a W6 zone has 6 gridpoints, and this line lists 5"},
      {replaced(text, "Z W6 2 2 9 5 7 10 8", "Z H8 2 2 9 5 7 10 8"),
       "t.f3grid:29: zone type 'H8' is not one of T4, B8, W6, P5 or B7"},
      {replaced(text, "Z W6 2 2 9 5 7 10 8", "Z W6 2 2 9 5 7 10 12"),
       "t.f3grid:29: zone 2 names gridpoint 12, which no gridpoint defines"},
      {replaced(text, "Z W6 2 2", "Z W6 1 2"), "t.f3grid:29: zone 1 is defined a second time"},
      {replaced(text, "F T3 2 21", "F T3 1 21"), "t.f3grid:55: face 1 is defined a second time"},
      {replaced(text, " 11 12 1\n", " 11 12 5\n"), "t.f3grid:52: zone 5 of group 'excavated' is not defined"},
      {replaced(text, "ZGROUP 'Rock' SLOT 1", "ZGROUP 'Rock SLOT 1"), "t.f3grid:47: a quote that is not closed"},
      {replaced(text, "ZGROUP 'Rock' SLOT 1", "ZGROUP 'Rock' 1"),
       "t.f3grid:47: a group is 'ZGROUP name' or 'ZGROUP name SLOT slot'"},
      {replaced(text, "* ZONES\n", "* ZONES\n 1 2\n"), "t.f3grid:28: a line of ids outside a ZGROUP or FGROUP"},
      {replaced(text, "* TETSMOOTH PINNED 40", "* TETSMOOTH PINNED 41 47"),
       "t.f3grid:62: pinned gridpoint 47 is not defined"},
      {"G 1 0 0 0\nZ B8 1 1 1 1 1 1 1 1 1\n", "t.f3grid: no T4 zones: tetsmooth smooths tetrahedral grids"},
      {"", "t.f3grid: no T4 zones: tetsmooth smooths tetrahedral grids"},
      {"\xEF\xBB\xBF", "t.f3grid: no T4 zones: tetsmooth smooths tetrahedral grids"},
      {std::string("\x0c\x00\x00\x00", 4),
       "t.f3grid, byte 0: not a FLAC3D grid: a binary file that does not start with the binary grid's mark "
       "(1375135718)"},
  };
  for (const auto& [grid, message] : cases) EXPECT_EQ(read_error(grid), message);
}

// A binary grid in the layout of flac3d_binary.cpp: a tet and a brick over
// gridpoints 10-18 (the brick's corners 11-18 in FLAC3D's order, the tet's
// apex 10 under its origin), zone groups in two slots, a face with a group.
std::string binary_grid() {
  std::string bytes;
  const auto u32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) bytes += static_cast<char>(v >> (8 * i));
  };
  const auto f64 = [&](double v) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, 8);
    for (int i = 0; i < 8; ++i) bytes += static_cast<char>(bits >> (8 * i));
  };
  const auto text = [&](const std::string& t) {
    bytes += static_cast<char>(t.size());
    bytes += '\0';
    bytes += t;
  };
  u32(1375135718);
  u32(3);
  const double corners[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {0, 1, 1}, {1, 0, 1}, {1, 1, 1}};
  u32(9);
  u32(10);
  for (double v : {0.25, 0.25, -1.0}) f64(v);
  for (std::uint32_t k = 0; k < 8; ++k) {
    u32(11 + k);
    for (double v : corners[k]) f64(v);
  }
  u32(2);                                                       // zones
  for (std::uint32_t v : {7u, 4u, 11u, 13u, 12u, 10u}) u32(v);  // T4 7: (0,0,0) (0,1,0) (1,0,0) apex
  u32(5);
  u32(8);
  for (std::uint32_t k = 0; k < 8; ++k) u32(11 + k);
  u32(2);  // zone groups
  text("rock");
  text("Default");
  u32(2);
  u32(7);
  u32(5);
  text("cut");
  text("stage");
  u32(1);
  u32(5);
  u32(1);  // faces
  for (std::uint32_t v : {1u, 3u, 11u, 12u, 13u}) u32(v);
  u32(1);  // face groups
  text("base");
  text("Default");
  u32(1);
  u32(1);
  return bytes;
}

TEST(Flac3dIo, BinaryGridsAreReadAndWrittenBackByteForByte) {
  const std::string bytes = binary_grid();
  TetMesh mesh = read_text(bytes);
  EXPECT_EQ(mesh.extras.node_tags, (std::vector<long long>{10, 11, 12, 13, 14, 15, 16, 17, 18}));
  EXPECT_EQ(std::vector<double>(mesh.xyz.begin(), mesh.xyz.begin() + 6),
            (std::vector<double>{0.25, 0.25, -1, 0, 0, 0}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{1, 3, 2, 0}));
  EXPECT_EQ(mesh.extras.tet_element_tags, (std::vector<long long>{7}));
  ASSERT_EQ(mesh.extras.blocks.size(), 2u);
  EXPECT_EQ(mesh.extras.blocks[0].connectivity, (std::vector<std::int32_t>{1, 2, 5, 3, 4, 7, 8, 6}));
  EXPECT_EQ(mesh.extras.blocks[1].connectivity, (std::vector<std::int32_t>{1, 2, 3}));
  // {rock} and {rock, cut}: the tet and the brick in regions of their own.
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{1}));
  EXPECT_EQ(mesh.extras.blocks[0].tags, (std::vector<int>{2}));
  EXPECT_EQ(raw(mesh, "$PhysicalNames"), "3\n3 1 \"rock\"\n3 2 \"rock + stage=cut\"\n2 1 \"base\"\n");
  EXPECT_TRUE(mesh.extras.read_notes.empty());

  EXPECT_EQ(write_text(mesh), bytes);
  mesh.xyz[2] = -0.75;  // the apex's z: bytes 12 + 4 + 16 on
  std::string moved = bytes;
  const double z = -0.75;
  std::memcpy(&moved[32], &z, 8);  // the test hosts are little-endian
  EXPECT_EQ(write_text(mesh), moved);
  EXPECT_EQ(read_text(moved).xyz, mesh.xyz);

  // Bytes past the face groups are kept, with a note.
  const TetMesh longer = read_text(bytes + "more");
  ASSERT_EQ(longer.extras.read_notes.size(), 1u);
  EXPECT_EQ(longer.extras.read_notes[0], "4 bytes after the face groups (from byte " + std::to_string(bytes.size()) +
                                             ") were not read; the FLAC3D output keeps them");
  EXPECT_EQ(write_text(longer), bytes + "more");

  const std::pair<std::string, std::string> cases[] = {
      {bytes.substr(0, 300), "t.f3grid, byte 300: the file ends inside the gridpoint id"},
      {bytes.substr(0, 12) + std::string("\0\0\0\0", 4) + bytes.substr(16),
       "t.f3grid, byte 12: gridpoint id 0 is not positive"},
      {replaced(bytes, std::string("\x05\0\0\0\x08\0\0\0", 8), std::string("\x05\0\0\0\x09\0\0\0", 8)),
       "t.f3grid, byte 292: a zone of 9 gridpoints, which no zone type has (T4, B8, W6, P5 or B7)"},
      {replaced(bytes, std::string("\x09\0\0\0\x0a\0\0\0", 8), std::string("\x09\0\0\x01\x0a\0\0\0", 8)),
       "t.f3grid, byte 8: gridpoint count 16777225 is more than the rest of the file holds"},
      {"\x01" + bytes.substr(1),
       "t.f3grid, byte 0: not a FLAC3D grid: a binary file that does not start with the "
       "binary grid's mark (1375135718)"},
      // A line break or a zero byte in a name, which no text format holds.
      {replaced(bytes, std::string("\x04\0rock", 6), std::string("\x04\0ro\nk", 6)),
       "t.f3grid, byte 340: a group name holds the control byte \\x0a"},
      {replaced(bytes, std::string("\x04\0base", 6), std::string("\x04\0ba\0e", 6)),
       "t.f3grid, byte 415: a group name holds the control byte \\x00"},
  };
  for (const auto& [grid, message] : cases) EXPECT_EQ(read_error(grid), message);
}

TEST(Flac3dIo, FormatByNameAndWhatOtherFormatsLose) {
  EXPECT_EQ(format_from_path("model.F3GRID"), MeshFormat::Flac3d);
  EXPECT_EQ(parse_format("f3grid"), MeshFormat::Flac3d);
  EXPECT_EQ(parse_format("flac3d"), MeshFormat::Flac3d);
  EXPECT_STREQ(format_name(MeshFormat::Flac3d), "flac3d");
  const TetMesh mesh = read_text(fixture());
  EXPECT_TRUE(output_losses(mesh, "out.f3grid").empty());
  const std::vector<std::string> to_vtu = output_losses(mesh, "out.vtu");
  ASSERT_EQ(to_vtu.size(), 3u);
  EXPECT_EQ(to_vtu[0], "the FLAC3D gridpoint and zone ids will not be written: vtu numbers them by position");
  EXPECT_EQ(to_vtu[1], "1 B7 zone will not be written: vtu has no place for it (its nodes were pinned)");
  EXPECT_EQ(
      to_vtu[2],
      "the names of the regions (the grid's zone and face groups) will not be written: vtu has no place for them");
  // MSH keeps the names and the gridpoint ids, not zone and face ids that
  // overlap; it pins through elements alone: the cut brick's gridpoints go
  // with it.
  const std::vector<std::string> to_msh = output_losses(mesh, "out.msh");
  ASSERT_EQ(to_msh.size(), 3u);
  EXPECT_EQ(to_msh[0], "7 pinned nodes will not be pinned in the msh41 output, so a later run may move them");
  EXPECT_EQ(to_msh[1],
            "the FLAC3D zone and face ids cannot all be kept (MSH element tags must be positive and "
            "distinct across all elements, at most 2147482623): msh41 numbers the elements 1, 2, ... "
            "instead");
  EXPECT_EQ(to_msh[2], "1 B7 zone will not be written: msh41 has no place for it (its nodes were pinned)");

  // A new Abaqus deck names its element sets after the groups, but for
  // names that would need quotes: those sets are named by tag.
  const std::vector<std::string> to_inp = output_losses(mesh, "out.inp");
  EXPECT_NE(std::find(to_inp.begin(), to_inp.end(),
                      "the names of 2 regions (the grid's zone and face groups: \"Soil layer + stage 1=excavated\", "
                      "\"Soil layer\") will not be written: a new abaqus deck names a region's element set by its tag "
                      "where the name is no plain set name (1 to 80 letters, digits and underscores, the first a "
                      "letter) or is another's in any case"),
            to_inp.end());

  // Lines, and shapes of other sizes than FLAC3D's (a 20-node brick), are
  // not written; their nodes are listed as pins.
  TetMesh lines = testing::cube_grid(1);
  lines.extras.blocks.push_back(PassThroughBlock{"line", 2, {0, 1}, {}, {}, {}});
  std::vector<std::int32_t> twenty(20, 2);
  twenty[19] = 3;
  lines.extras.blocks.push_back(PassThroughBlock{"hexahedron", 20, twenty, {}, {}, {}});
  const std::vector<std::string> to_flac3d = output_losses(lines, "out.f3grid");
  ASSERT_EQ(to_flac3d.size(), 1u);
  EXPECT_EQ(to_flac3d[0], "1 line, 1 hexahedron will not be written: flac3d holds tets, bricks, wedges, pyramids, "
                          "triangles and quads (their nodes are listed as pins)");
  const std::string text = write_text(lines);
  EXPECT_EQ(text.find("Z B8"), std::string::npos) << text;
  EXPECT_NE(text.find("\n* TETSMOOTH PINNED 1 2 3 4\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace tetsmooth
