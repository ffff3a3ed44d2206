// Nastran bulk data: entries in small, large and free field, regions from
// PIDs, pins from constraints, loads and rigid elements, the deck written
// back with only moved GRIDs changed, new decks that read back as written,
// Nastran's real numbers, and errors naming file:line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <string>

#include "mesh/errors.hpp"
#include "mesh/io/mesh_io.hpp"
#include "mesh/io/nastran_fields.hpp"
#include "mesh/io/nastran_io.hpp"
#include "mesh/io/writable_check.hpp"
#include "mesh/second_order.hpp"
#include "support/input_error.hpp"
#include "support/scratch_dir.hpp"
#include "support/test_meshes.hpp"

namespace tetsmooth {
namespace {

TetMesh read_text(const std::string& text) {
  std::istringstream in(text);
  return read_nastran(in, "t.bdf");
}

std::string write_text(const TetMesh& mesh) {
  std::ostringstream out;
  write_nastran(mesh, out);
  return out.str();
}

std::string read_error(const std::string& text) {
  return testing::input_error_message([&] { read_text(text); }, "read_nastran:\n" + text);
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// A small-field line: each field left in its 8 columns.
std::string small(const std::vector<std::string>& fields) {
  std::string line;
  for (const std::string& f : fields) line += f + std::string(8 - f.size(), ' ');
  line.erase(line.find_last_not_of(' ') + 1);
  return line + "\n";
}

// A large-field field: right in its 16 columns.
std::string wide(const std::string& f) { return std::string(16 - f.size(), ' ') + f; }

// Two tets of two properties and a triangle, in the three field formats,
// after executive and case control (whose "SPC = 1" is no entry), with
// Nastran's reals: an exponent without E, a leading point, a tab.
const std::string kDeck =
    "SOL 101\n"
    "CEND\n"
    "SPC = 1\n"
    "BEGIN BULK\n"
    "$ nodes\n" +
    small({"GRID", "1", "", "0.", "0.", "0."}) + small({"GRID", "2", "0", "1.", "0.", "0."}) + "GRID*   " + wide("3") +
    wide("") + wide("0.") + wide("1.") + "\n*       " + wide("0.") + "\n" +
    "GRID,4,,0.,0.,1.\n"
    "GRID    5               1.+0    10.-1\t1.0D0\n"
    "GRID, 6, , .3, .3, .3\n" +
    small({"CTETRA", "10", "1", "1", "2", "3", "4"}) + "CTETRA,11,2,2,3,4,5\n" +
    small({"CTRIA3", "20", "7", "1", "2", "3"}) + small({"PSOLID", "1", "1"}) + small({"SPC1", "1", "123", "6"}) +
    "ENDDATA\n"
    "anything after ENDDATA\n";

TEST(NastranIo, ReadsEntriesInEveryFieldFormat) {
  const TetMesh mesh = read_text(kDeck);
  EXPECT_EQ(mesh.xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1, 0.3, 0.3, 0.3}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3, 1, 2, 3, 4}));
  EXPECT_EQ(mesh.extras.node_tags, (std::vector<long long>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(mesh.extras.tet_element_tags, (std::vector<long long>{10, 11}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{1, 2}));
  ASSERT_EQ(mesh.extras.blocks.size(), 1u);
  const PassThroughBlock& skin = mesh.extras.blocks[0];
  EXPECT_EQ(skin.kind, "triangle");
  EXPECT_EQ(skin.connectivity, (std::vector<index_t>{0, 1, 2}));
  EXPECT_EQ(skin.tags, (std::vector<int>{7}));
  EXPECT_EQ(skin.element_tags, (std::vector<long long>{20}));
  // The triangle's nodes, and node 6 that SPC1 names.
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{1, 1, 1, 0, 0, 1}));
  EXPECT_EQ(*raw_section(mesh.extras, "nastran:types"), "PSOLID, SPC1");
  EXPECT_EQ(raw_section(mesh.extras, "nastran:uncarried"), nullptr);
  EXPECT_EQ(*raw_section(mesh.extras, "nastran:deck"), "6 2");
}

// A deck with BEGIN BULK but no ENDDATA reads as it is, with a note: a
// deck cut short looks just so. Bulk data alone needs no ENDDATA.
TEST(NastranIo, ADeckWithoutEnddataIsNoted) {
  EXPECT_TRUE(read_text(kDeck).extras.read_notes.empty());
  const std::string cut = kDeck.substr(0, kDeck.find("ENDDATA"));
  const TetMesh mesh = read_text(cut);
  EXPECT_EQ(mesh.num_tets(), 2u);
  EXPECT_EQ(mesh.extras.read_notes,
            std::vector<std::string>{"the deck has BEGIN BULK but ends without ENDDATA, as a deck cut short would: "
                                     "check that its last entries are all there"});
  EXPECT_TRUE(read_text(cut.substr(cut.find("BEGIN BULK\n") + 11)).extras.read_notes.empty());
}

TEST(NastranIo, WritesTheDeckBackChangingOnlyTheGridsOfMovedNodes) {
  EXPECT_EQ(write_text(read_text(kDeck)), kDeck);
  std::string crlf;
  for (char c : kDeck) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  EXPECT_EQ(write_text(read_text(crlf)), kDeck);

  TetMesh mesh = read_text(kDeck);
  mesh.xyz[3 * 3 + 2] = 0.875;      // node 4, free field
  mesh.xyz[3 * 4 + 0] = 1.0 / 3.0;  // node 5, small field with a tab
  const std::string expected = replaced(
      replaced(kDeck, "GRID,4,,0.,0.,1.\n",
               "GRID*   " + wide("4") + wide("") + wide("0.") + wide("0.") + "\n*       " + wide(".875") + "\n"),
      "GRID    5               1.+0    10.-1\t1.0D0\n",
      "GRID*   " + wide("5") + wide("") + wide(".333333333333333") + wide("1.") + "\n*       " + wide("1.") + "\n");
  EXPECT_EQ(write_text(mesh), expected);
  // What the large field keeps reads back within its 15 digits.
  const TetMesh back = read_text(expected);
  EXPECT_EQ(back.xyz[3 * 3 + 2], 0.875);
  EXPECT_NEAR(back.xyz[3 * 4], 1.0 / 3.0, 1e-15);
}

TEST(NastranIo, ADeckIsWrittenOnlyForTheMeshItWasReadWith) {
  TetMesh mesh = read_text(kDeck);
  mesh.tets.resize(4);
  try {
    write_text(mesh);
    FAIL() << "a deck written for another mesh";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("the Nastran deck read with this mesh lists (nodes, tets) 6 2, and the mesh "
                                         "has 6 1"),
              std::string::npos)
        << e.what();
  }
}

TEST(NastranIo, ReadsADeckGmshWrote) {
  // tests/data/gmsh_layers_make.py: two volumes (PIDs 1 and 2, their entity
  // tags) and the bottom face's triangles, in small field, no BEGIN BULK.
  const TetMesh mesh = read_nastran_file(testing::data_path("nastran_gmsh_layers.bdf"));
  EXPECT_EQ(mesh.num_nodes(), 157u);
  ASSERT_EQ(mesh.num_tets(), 470u);
  EXPECT_EQ(std::count(mesh.extras.tet_tags.begin(), mesh.extras.tet_tags.end(), 1), 234);
  EXPECT_EQ(std::count(mesh.extras.tet_tags.begin(), mesh.extras.tet_tags.end(), 2), 236);
  ASSERT_EQ(mesh.extras.blocks.size(), 1u);
  EXPECT_EQ(mesh.extras.blocks[0].kind, "triangle");
  EXPECT_EQ(mesh.extras.blocks[0].connectivity.size(), 3u * 44u);
  std::vector<std::uint8_t> pinned(mesh.num_nodes(), 0);
  mark_element_nodes(mesh.extras.blocks, pinned);
  EXPECT_EQ(mesh.fixed, pinned);
  // Its coordinates are Gmsh's 8 columns, such as 0.00E+00 and 0.500000.
  EXPECT_EQ(mesh.xyz[5], 0.5);
}

TEST(NastranIo, ConstraintsLoadsAndRigidElementsPinTheirGridPoints) {
  std::string deck = "BEGIN BULK\n";
  for (int i = 1; i <= 20; ++i)
    deck += "GRID," + std::to_string(i) + ",," + std::to_string(i % 3) + ".," + std::to_string(i % 5) + ".," +
            std::to_string(i) + ".\n";
  deck +=
      "GRID,21,,0.,0.,0.,,123\n"  // PS: a permanent constraint
      "CTETRA,1,1,1,2,3,4\n"
      "SPC1,1,123,2,THRU,3\n"  // 2, 3
      "SPC,1,5,1,0.,6,2,0.\n"  // 5, 6
      "FORCE,2,7,,1.,0.,0.,1.\n"
      "MPC,3,8,1,1.,,,,,+\n"
      "+,,9,1,-1.,10,1,1.\n"           // 8, 9, 10
      "RBE2,50,11,123456,12,13,0.5\n"  // 11, 12, 13; 0.5 is ALPHA
      "RBE3,51,,14,123,1.,123,15,16,+\n"
      "+,2.5,1,17,UM,18,1\n"   // 14, 15, 16, 17 and 18
      "CELAS2,52,1.,19,1,0\n"  // 19 to the ground
      "$TETSMOOTH PINNED 20\n"
      "ENDDATA\n";
  const TetMesh mesh = read_text(deck);
  std::vector<std::uint8_t> expected(21, 1);
  expected[0] = expected[3] = 0;  // nodes 1 and 4
  EXPECT_EQ(mesh.fixed, expected);
  EXPECT_EQ(*raw_section(mesh.extras, "nastran:uncarried"), "RBE2, RBE3, CELAS2");
  EXPECT_EQ(*raw_section(mesh.extras, "nastran:types"), "SPC1, SPC, FORCE, MPC");
  EXPECT_TRUE(mesh.extras.blocks.empty());
}

TEST(NastranIo, SecondOrderTetsAndOtherShapes) {
  // A 10-node CTETRA on two lines (a blank first field goes on), its
  // midside nodes in kTetEdges order; a CHEXA with corners only passes
  // through, one with midside nodes only pins.
  std::string deck = "BEGIN BULK\n";
  const double corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int i = 0; i < 4; ++i)
    deck += "GRID*," + std::to_string(i + 1) + ",," + std::to_string(corners[i][0]) + "," +
            std::to_string(corners[i][1]) + "\n*," + std::to_string(corners[i][2]) + "\n";
  for (int e = 0; e < 6; ++e) {
    const int a = kTetEdges[e][0], b = kTetEdges[e][1];
    deck += "GRID," + std::to_string(5 + e) + ",";
    for (int c = 0; c < 3; ++c) deck += "," + std::to_string(0.5 * (corners[a][c] + corners[b][c]));
    deck += "\n";
  }
  deck += small({"CTETRA", "1", "3", "1", "2", "3", "4", "5", "6"}) + small({"", "7", "8", "9", "10"}) +
          "CHEXA,2,4,1,2,3,4,5,6,+\n+,7,8\n"
          "CHEXA,3,4,1,2,3,4,5,6,+\n+,7,8,9\n"
          "ENDDATA\n";
  const TetMesh mesh = read_text(deck);
  ASSERT_EQ(mesh.num_tets(), 1u);
  EXPECT_EQ(mesh.midsides, (std::vector<index_t>{4, 5, 6, 7, 8, 9}));
  EXPECT_EQ(testing::largest_midside_offset(mesh), 0.0);
  ASSERT_EQ(mesh.extras.blocks.size(), 1u);
  EXPECT_EQ(mesh.extras.blocks[0].kind, "hexahedron");
  EXPECT_EQ(mesh.extras.blocks[0].tags, (std::vector<int>{4}));
  EXPECT_EQ(*raw_section(mesh.extras, "nastran:uncarried"), "CHEXA");
  EXPECT_EQ(read_error(replaced(deck, small({"", "7", "8", "9", "10"}), small({"", "7", "8", "9"}))),
            "t.bdf:16: CTETRA 1 lists 9 grid points: a CTETRA has G1 to G4, or G1 to G10 with its midside nodes");
  EXPECT_EQ(read_error("BEGIN BULK\nCTETRA,1,1,1,2,3,,4\n"),
            "t.bdf:2: CTETRA 1 lists 4 grid points with a gap before G4: a CTETRA has G1 to G4, or G1 to G10 with its "
            "midside nodes");
}

TEST(NastranIo, ANewDeckReadsBackAsWritten) {
  TetMesh mesh = testing::with_midsides(testing::cube_grid(2, 0.2, 11));
  mesh.extras.tet_tags.assign(mesh.num_tets(), 3);
  mesh.extras.tet_tags[0] = 0;
  mesh.extras.tet_tags[1] = -2;
  mesh.extras.node_tags.resize(mesh.num_nodes());
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) mesh.extras.node_tags[i] = 1000 + 7 * static_cast<long long>(i);
  mesh.extras.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 1, 2}, {5}, {}, {}});
  mesh.extras.blocks.push_back(PassThroughBlock{"vertex", 1, {8}, {}, {}, {}});
  mesh.fixed.assign(mesh.num_nodes(), 0);
  for (std::size_t i = 0; i < mesh.num_nodes(); i += 3) mesh.fixed[i] = 1;
  mark_element_nodes(mesh.extras.blocks, mesh.fixed);
  const std::string text = write_text(mesh);
  EXPECT_EQ(text.substr(0, 34), "$ written by tetsmooth\nBEGIN BULK\n");
  EXPECT_NE(text.find("\n$TETSMOOTH PINNED 1021 1042 1063 1084 1105 1126\n$TETSMOOTH PINNED "), std::string::npos);
  const TetMesh back = read_text(text);
  ASSERT_EQ(back.num_nodes(), mesh.num_nodes());
  for (std::size_t k = 0; k < mesh.xyz.size(); ++k) EXPECT_NEAR(back.xyz[k], mesh.xyz[k], 1e-14) << k;
  EXPECT_EQ(back.tets, mesh.tets);
  EXPECT_EQ(back.midsides, mesh.midsides);
  EXPECT_EQ(back.extras.node_tags, mesh.extras.node_tags);
  // 0 and -2 as the next ids after the largest tag (the triangle's 5).
  std::vector<int> tags = mesh.extras.tet_tags;
  tags[0] = 6;
  tags[1] = 7;
  EXPECT_EQ(back.extras.tet_tags, tags);
  ASSERT_EQ(back.extras.blocks.size(), 2u);
  EXPECT_EQ(back.extras.blocks[0].tags, (std::vector<int>{5}));
  EXPECT_EQ(back.extras.blocks[1].kind, "vertex");
  EXPECT_EQ(back.fixed, mesh.fixed);
  EXPECT_EQ(output_losses(mesh, "out.bdf"),
            (std::vector<std::string>{"region tags that are no PIDs are written as new ones (-2 as 7, 0 as 6): "
                                      "Nastran's PIDs are positive, of at most 8 digits"}));
  // New ids are ids no tag holds, past the largest id from 1 on; tags past
  // it get new ones too.
  TetMesh big = testing::cube_grid(1);
  big.extras.tet_tags = {99999999, 0, -1, 1, 2147483647, 3};
  EXPECT_EQ(nastran_region_ids(big).renumbered(), (std::map<int, int>{{0, 2}, {-1, 4}, {2147483647, 5}}));
  // A PID names one property entry: a triangle of a tet's tag gets its own.
  TetMesh shared = testing::cube_grid(1);
  shared.extras.tet_tags.assign(shared.num_tets(), 4);
  shared.extras.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 1, 2}, {4}, {}, {}});
  const TetMesh shared_back = read_text(write_text(shared));
  EXPECT_EQ(shared_back.extras.tet_tags, shared.extras.tet_tags);
  ASSERT_EQ(shared_back.extras.blocks.size(), 1u);
  EXPECT_EQ(shared_back.extras.blocks[0].tags, (std::vector<int>{5}));
  EXPECT_EQ(output_losses(shared, "out.bdf"),
            (std::vector<std::string>{"elements of several dimensions in one region get PIDs of their own (shells of "
                                      "region 4 as PID 5): a Nastran PID names one property entry (PSOLID, PSHELL "
                                      "or PROD)"}));
  // A mesh without regions gets PID 1, which Gmsh needs.
  EXPECT_NE(write_text(testing::cube_grid(1)).find("CTETRA         1       1"), std::string::npos);
}

TEST(NastranIo, IncludedFilesAreReadInPlaceAndWrittenInline) {
  testing::ScratchDir dir("nastran_include");
  std::filesystem::create_directory(dir.file("mesh"));
  {
    // Relative paths start from the job's directory, in a nested file too;
    // '\' is read as '/'; a quoted name may go on on the next line.
    std::ofstream(dir.file("mesh/grids.bdf")) << "GRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,0.,1.,0.\n"
                                                 "GRID,4,,0.,0.,1.\n";
    std::ofstream(dir.file("mesh/model.bdf")) << "include 'mesh\\grids.bdf'\nCTETRA,1,1,1,2,3,4\n";
    std::ofstream(dir.file("case.dat")) << "SUBCASE 1\n";
    std::ofstream(dir.file("job.bdf")) << "SOL 101\nCEND\nINCLUDE 'case.dat'\nBEGIN BULK\nINCLUDE 'me\n  sh/model.bdf'\n"
                                          "SPC1,1,123,1\nENDDATA\n";
  }
  const TetMesh mesh = read_nastran_file(dir.file("job.bdf"));
  EXPECT_EQ(mesh.num_nodes(), 4u);
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{1, 0, 0, 0}));
  EXPECT_EQ(write_text(mesh),
            "SOL 101\nCEND\nSUBCASE 1\nBEGIN BULK\nGRID,1,,0.,0.,0.\nGRID,2,,1.,0.,0.\nGRID,3,,0.,1.,0.\n"
            "GRID,4,,0.,0.,1.\nCTETRA,1,1,1,2,3,4\nSPC1,1,123,1\nENDDATA\n");
  const std::vector<std::string> notes = output_losses(mesh, "out.bdf");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "the INCLUDE files (" + dir.file("case.dat") + ", " + dir.file("mesh/model.bdf") + ", " +
                          dir.file("mesh/grids.bdf") + ") will be written inline, in the one output deck");
  // Errors name the line of the included file.
  std::ofstream(dir.file("mesh/grids.bdf")) << "GRID,1,,0.,0.,0.\nGRID,1,,1.,0.,0.\n";
  EXPECT_EQ(testing::input_error_message([&] { read_nastran_file(dir.file("job.bdf")); }, "job.bdf"),
            dir.file("mesh/grids.bdf") + ":2: grid point 1 is defined a second time");
  std::ofstream(dir.file("lost.bdf")) << "BEGIN BULK\nINCLUDE 'missing.bdf'\n";
  EXPECT_NE(testing::input_error_message([&] { read_nastran_file(dir.file("lost.bdf")); }, "lost.bdf")
                .find(dir.file("lost.bdf") + ":2: INCLUDE: " + dir.file("missing.bdf") + ": cannot open"),
            std::string::npos);
  // An INCLUDE right after an entry and a comment, indented, and without a
  // space before its name.
  std::ofstream(dir.file("mesh/model.bdf")) << "GRID,1,,0.,0.,0.\n$ the rest\n  INCLUDE'grids2.bdf'\n"
                                               "CTETRA,1,1,1,2,3,4\n";
  std::ofstream(dir.file("grids2.bdf")) << "GRID,2,,1.,0.,0.\nGRID,3,,0.,1.,0.\nGRID,4,,0.,0.,1.\n";
  EXPECT_EQ(read_nastran_file(dir.file("job.bdf")).num_nodes(), 4u);
  std::ofstream(dir.file("open.bdf")) << "BEGIN BULK\nINCLUDE 'never\n";
  EXPECT_EQ(testing::input_error_message([&] { read_nastran_file(dir.file("open.bdf")); }, "open.bdf"),
            dir.file("open.bdf") + ":2: INCLUDE: the file name's closing quote is missing");
}

// Four tets around one interior node, 5.
const std::string kStar = "BEGIN BULK\n" + small({"GRID", "1", "", "0.", "0.", "0."}) +
                          small({"GRID", "2", "", "1.", "0.", "0."}) + small({"GRID", "3", "", "0.", "1.", "0."}) +
                          small({"GRID", "4", "", "0.", "0.", "1."}) + small({"GRID", "5", "", ".3", ".2", ".1"}) +
                          small({"CTETRA", "1", "1", "5", "2", "3", "4"}) +
                          small({"CTETRA", "2", "1", "1", "5", "3", "4"}) +
                          small({"CTETRA", "3", "1", "1", "2", "5", "4"}) +
                          small({"CTETRA", "4", "1", "1", "2", "3", "5"}) + "ENDDATA\n";

bool node5_pinned(const std::string& entries) {
  const TetMesh mesh = read_text(replaced(kStar, "BEGIN BULK\n", "BEGIN BULK\n" + entries));
  return !mesh.fixed.empty() && mesh.fixed[4] == 1;
}

TEST(NastranIo, PointsThatGiveDirectionsOrSetsApartArePinned) {
  EXPECT_FALSE(node5_pinned(""));
  for (const std::string& entries : {
           small({"FORCE1", "1", "4", "100.", "5", "4"}),             // the direction's G1
           small({"FORCE2", "1", "4", "100.", "1", "2", "5", "3"}),   // G3
           small({"MOMENT1", "1", "4", "100.", "4", "5"}),            // G2
           small({"CBAR", "101", "1", "1", "2", "5"}),                // the orientation node G0
           small({"CBUSH", "101", "1", "1", "2", "5"}),
           small({"CORD1R", "7", "1", "2", "5"}),                     // a system defined by points
           small({"RFORCE", "1", "5", "", "100.", "0.", "0.", "1."}),  // the centre of rotation
           small({"SPC1", "1", "123", "1", "THRU", "3", "5"}),        // a list after a range
           small({"ASET1", "3", "4", "THRU", "6"}),                   // analysis sets
           small({"ASET", "4", "3", "5", "3"}),
           small({"CMASS2", "9", "1.", "5", "1"}),
           small({"PLOTEL", "9", "1", "5"}),
           small({"RBE1", "9", "1", "123", "2", "123", "3", "123"}) + small({"", "UM", "5", "123", "1.-5"}),
           small({"RBE1", "9", "1", "123456"}) + small({"", "UM", "5", "123", "1.-5"}),  // ALPHA after the pairs
           small({"RBE3", "9", "", "4", "123", "1.", "123", "1", "2"}) + small({"", "5", "ALPHA", "1.-5"}),
           small({"USET1", "U1", "123", "5"}),
           small({"RBAR1", "9", "1", "5", "123"}),
           small({"BAROR", "", "1", "", "", "5"}) + small({"CBAR", "101", "1", "1", "2"}),  // G0 by default
           small({"CBEAM3", "101", "1", "1", "2", "3", "5"}),
           small({"RFORCE1", "1", "5", "", "100."}),
           small({"BNDFIX1", "123", "4", "THRU", "6"}),
           small({"NOLIN1", "1", "4", "1", "2.", "5", "1"}),
           small({"GRDSET", "", "", "", "", "", "", "3"}),            // a PS for blank ones
       })
    EXPECT_TRUE(node5_pinned(entries)) << entries;
  // A CBAR's orientation as a vector names no point; a GRID's own PS wins
  // over GRDSET's.
  EXPECT_FALSE(node5_pinned(small({"CBAR", "101", "1", "1", "2", "1.", "0.", "0."})));
  const TetMesh own_ps =
      read_text(replaced(replaced(kStar, "BEGIN BULK\n", "BEGIN BULK\n" + small({"GRDSET", "", "", "", "", "", "", "3"})),
                         small({"GRID", "5", "", ".3", ".2", ".1"}), small({"GRID", "5", "", ".3", ".2", ".1", "", "0"})));
  EXPECT_EQ(own_ps.fixed[4], 0);
  // Scalar points are no grid points, and no error.
  const TetMesh scalar = read_text(replaced(
      kStar, "BEGIN BULK\n",
      "BEGIN BULK\n" + small({"SPOINT", "101", "THRU", "103"}) + small({"CELAS2", "9", "1.", "4", "1", "102"}) +
          small({"SPC", "1", "101", "0", "0."})));
  EXPECT_EQ(scalar.fixed, (std::vector<std::uint8_t>{0, 0, 0, 1, 0}));
  // Entries that name grid points in ways not read are said.
  const TetMesh welded = read_text(replaced(kStar, "BEGIN BULK\n", "BEGIN BULK\nCWELD,9,1,5\n"));
  ASSERT_EQ(welded.extras.read_notes.size(), 1u);
  EXPECT_EQ(welded.extras.read_notes[0].substr(0, 70),
            "the deck's CWELD entries name grid points that tetsmooth does not read");
  // So are the entries of types not known at all; properties, materials,
  // parameters, tables and element loads are known to name none.
  const TetMesh unknown = read_text(replaced(
      kStar, "BEGIN BULK\n",
      "BEGIN BULK\nPARAM,POST,-1\nPSOLID,1,1\nMAT1,1,2.1E5,,.3\nPLOAD4,1,1,1.\nTABLED1,1\nSET1,1,5\nXYZ,5\n"));
  ASSERT_EQ(unknown.extras.read_notes.size(), 1u);
  EXPECT_EQ(unknown.extras.read_notes[0],
            "the deck's SET1, XYZ entries are not read: where they name grid points, their nodes are not pinned (list "
            "those that must stay on a \"$TETSMOOTH PINNED <id> ...\" comment line)");
}

TEST(NastranIo, LeftHandedTetsAreTurnedRound) {
  const std::string deck = replaced(kStar, small({"CTETRA", "1", "1", "5", "2", "3", "4"}),
                                    small({"CTETRA", "1", "1", "2", "5", "3", "4"}));
  const TetMesh mesh = read_text(deck);
  EXPECT_EQ(std::vector<index_t>(mesh.tets.begin(), mesh.tets.begin() + 4), (std::vector<index_t>{1, 2, 4, 3}));
  ASSERT_EQ(mesh.extras.read_notes.size(), 1u);
  EXPECT_EQ(mesh.extras.read_notes[0], "1 of the 4 CTETRA list their grid points left-handed, which Nastran takes: "
                                       "they are read turned round (G2 and G3 swapped), and the deck keeps them as "
                                       "written");
  EXPECT_EQ(write_text(mesh), deck);
  // With midside nodes, which turn with their edges.
  TetMesh ten = testing::with_midsides(testing::cube_grid(1));
  for (std::size_t t = 0; t < ten.num_tets(); t += 2) {
    std::swap(ten.tets[4 * t + 1], ten.tets[4 * t + 2]);
    std::swap(ten.midsides[6 * t + 0], ten.midsides[6 * t + 2]);
    std::swap(ten.midsides[6 * t + 4], ten.midsides[6 * t + 5]);
  }
  std::ostringstream left;
  write_nastran(ten, left);
  const TetMesh back = read_text(left.str());
  EXPECT_EQ(testing::largest_midside_offset(back), 0.0);
  EXPECT_EQ(back.tets, testing::with_midsides(testing::cube_grid(1)).tets);
  EXPECT_EQ(back.midsides, testing::with_midsides(testing::cube_grid(1)).midsides);
}

TEST(NastranIo, DataPastAnEntrysFieldsIsRefusedNotDropped) {
  const std::string large = "GRID*   " + wide("5") + wide("") + wide(".3") + wide(".2") + "\n+       .1\n";
  EXPECT_EQ(read_error(replaced(kStar, small({"GRID", "5", "", ".3", ".2", ".1"}), large)),
            "t.bdf:6: GRID 5 has '.1' past its last field (field 2 of its line 2): a large-field entry goes on on "
            "lines that start with '*', and each line of an entry holds 8 fields");
  EXPECT_EQ(read_error(replaced(kStar, small({"GRID", "5", "", ".3", ".2", ".1"}), "GRID,5,,.3,.2\n,.1\n")),
            "t.bdf:6: GRID 5 has '.1' past its last field (field 2 of its line 2): a large-field entry goes on on "
            "lines that start with '*', and each line of an entry holds 8 fields");
  // A UTF-8 byte order mark before the first entry, and meshio's CTETRA_.
  const TetMesh marked = read_text("\xEF\xBB\xBF" + kStar.substr(11));
  EXPECT_EQ(marked.num_nodes(), 5u);
  const TetMesh meshio = read_text(replaced(kStar, "CTETRA  1 ", "CTETRA_ 1 "));
  ASSERT_EQ(meshio.extras.read_notes.size(), 1u);
  EXPECT_EQ(meshio.extras.read_notes[0],
            "CTETRA_ entries (meshio 5's name for 10-node tets, which Nastran does not know) were read as CTETRA");
}

TEST(NastranIo, GridFieldsTheWriterCopiesAreChecked) {
  EXPECT_EQ(read_error(replaced(kStar, small({"GRID", "5", "", ".3", ".2", ".1"}), "GRID,5,,.3,.2,.1,,12x\n")),
            "t.bdf:6: GRID 5: expected the components of a permanent constraint (PS: digits 1 to 6), found '12x'");
  EXPECT_EQ(read_error(replaced(kStar, small({"GRID", "5", "", ".3", ".2", ".1"}), "GRID,5,,.3,.2,.1,1.5\n")),
            "t.bdf:6: GRID 5: expected a coordinate system id (CD), found '1.5'");
  // Ids with leading zeros, longer than a field, are written plain.
  TetMesh mesh = read_text(
      replaced(kStar, small({"GRID", "5", "", ".3", ".2", ".1"}), "GRID,0000000000000000005,,.3,.2,.1,0000000000000000007\n"));
  mesh.xyz[3 * 4] = 0.25;
  const TetMesh back = read_text(write_text(mesh));
  EXPECT_EQ(back.xyz[3 * 4], 0.25);
  EXPECT_TRUE(back.fixed.empty());
  // A carriage return inside a line (line ends "\n\r") would shift its
  // columns: refused. Those at a line's end are line ends.
  const std::string grid4 = small({"GRID", "4", "", "0.", "0.", "1."}), grid5 = small({"GRID", "5", "", ".3", ".2", ".1"});
  EXPECT_EQ(read_error(replaced(kStar, grid4, "\r" + grid4)),
            "t.bdf:5: a carriage return inside the line: the file mixes line ends (give it one kind, LF or CRLF)");
  EXPECT_EQ(read_error(replaced(kStar, grid5, "GRID,123456789,,.3,.2,.1\n")),
            "t.bdf:6: GRID 123456789: Nastran ids have at most 8 digits");
  // A 4-node CTETRA may give its midside fields as 0.
  EXPECT_EQ(read_text(replaced(kStar, small({"CTETRA", "4", "1", "1", "2", "3", "5"}),
                               small({"CTETRA", "4", "1", "1", "2", "3", "5", "0", "0"}) + small({"", "0", "0", "0", "0"})))
                .num_tets(),
            4u);
  const TetMesh spc = read_text(replaced(kStar, "BEGIN BULK\n", "BEGIN BULK\nSPC1    1       123     5\r\r\n\r\r\n"));
  EXPECT_EQ(spc.fixed[4], 1);
  EXPECT_EQ(write_text(spc), replaced(kStar, "BEGIN BULK\n", "BEGIN BULK\nSPC1    1       123     5\n\n"));
}

TEST(NastranIo, AMovedGridKeepsItsComments) {
  TetMesh mesh = read_text(replaced(kStar, small({"GRID", "5", "", ".3", ".2", ".1"}),
                                    "GRID*   " + wide("5") + wide("") + wide(".3") + wide(".2") +
                                        "\n$ between\n*       " + wide(".1") + "   $ monitor point\n"));
  mesh.xyz[3 * 4] = 0.25;
  const std::string text = write_text(mesh);
  EXPECT_NE(text.find("$ between\n$ monitor point\nGRID*   " + wide("5") + wide("") + wide(".25") + wide(".2") +
                      "\n*       " + wide(".1") + "\n"),
            std::string::npos)
      << text;
  // A comment inside the entry that would read as a pin line on its own is
  // marked off.
  mesh = read_text(replaced(kStar, small({"GRID", "5", "", ".3", ".2", ".1"}),
                            "GRID,5,,.3,.2,.1 $TETSMOOTH PINNED 0.\n"));
  mesh.xyz[3 * 4] = 0.25;
  EXPECT_NE(write_text(mesh).find("\n$$TETSMOOTH PINNED 0.\nGRID*"), std::string::npos);
  EXPECT_TRUE(read_text(write_text(mesh)).fixed.empty());
}

TEST(NastranIo, RealsInEveryFormAndInTheirWidth) {
  const std::pair<const char*, double> forms[] = {{"7.0", 7},   {".7E1", 7},  {"0.7+1", 7},        {".70+1", 7},
                                                  {"7.E+0", 7}, {"70.-1", 7}, {"-1.5-3", -1.5e-3}, {"1.5D+2", 150},
                                                  {"2", 2},     {"+.5", 0.5}};
  for (const auto& [text, value] : forms) {
    double v = 0;
    EXPECT_TRUE(nastran::parse_real_field(text, v)) << text;
    EXPECT_DOUBLE_EQ(v, value) << text;
  }
  for (const char* bad : {"", "1.5E", "abc", "1.5-", "-", "1.5+3x", "inf", "nan"}) {
    double v = 0;
    EXPECT_FALSE(nastran::parse_real_field(bad, v)) << bad;
  }
  // Values whose shortest form fits come back exactly; others as close as
  // the width allows, always with a decimal point.
  EXPECT_EQ(nastran::real_field(0.25, 8), ".25");
  EXPECT_EQ(nastran::real_field(-0.25, 8), "-.25");
  EXPECT_EQ(nastran::real_field(3, 8), "3.");
  EXPECT_EQ(nastran::real_field(1.5e-7, 8), "1.5E-7");
  EXPECT_EQ(nastran::real_field(1e20, 8), "1.E20");
  // C's style: a 0 before the point and the exponent's sign.
  EXPECT_EQ(nastran::real_field(-0.25, 8, nastran::RealStyle::C), "-0.25");
  EXPECT_EQ(nastran::real_field(1e20, 8, nastran::RealStyle::C), "1.E+20");
  EXPECT_EQ(nastran::real_field(-DBL_MAX, 8, nastran::RealStyle::C), "-1.E+308");  // "-2.E+308" overflows
  // A rounded value without the zeros after its last digit.
  EXPECT_EQ(nastran::real_field(100.00000000000001, 16), "100.");
  EXPECT_EQ(nastran::real_field(1.5e-7, 8, nastran::RealStyle::C), "1.5E-7");
  // A number whose whole part rounds up a digit keeps every digit that fits.
  EXPECT_EQ(nastran::real_field(-9.5456041617964971, 16), "-9.5456041617965");
  // Any double fits, the largest and the smallest too; the relative error
  // bounds of nastran_fields.hpp hold.
  const auto check = [](double value, std::size_t width, double relative,
                        nastran::RealStyle style = nastran::RealStyle::Nastran) {
    const std::string text = nastran::real_field(value, width, style);
    double back = 0;
    ASSERT_LE(text.size(), width) << value;
    ASSERT_TRUE(nastran::parse_real_field(text, back)) << value << " as '" << text << "'";
    EXPECT_NE(text.find('.'), std::string::npos) << text;
    EXPECT_LE(std::fabs(back - value), std::fabs(value) * relative) << value << " " << text;
  };
  for (double extreme : {DBL_MAX, -DBL_MAX, DBL_MIN, -DBL_MIN, 4.9e-324, -4.9e-324, 1.2345678901234567e300}) {
    check(extreme, 8, 0.5);
    check(extreme, 16, 5e-9);
  }
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> mantissa(-10, 10);
  std::uniform_int_distribution<int> power(-300, 300);
  for (int i = 0; i < 4000; ++i) {
    const int p = i % 2 == 0 ? power(rng) : power(rng) / 30;  // half of them near 1
    const double value = mantissa(rng) * std::pow(10.0, p);
    check(value, 16, std::abs(p) < 13 && std::fabs(value) >= 1 ? 5e-14 : std::abs(p) < 99 ? 5e-10 : 5e-9);
    check(value, 8, std::abs(p) < 99 ? 5e-2 : 0.5);
    // C's style spends a character on the exponent's sign or a leading 0.
    check(value, 16,
          std::abs(p) < 13 && std::fabs(value) >= 1 ? 5e-14
          : std::abs(p) < 99                        ? 5e-9
                                                    : 5e-8,
          nastran::RealStyle::C);
  }
}

TEST(NastranIo, ErrorsNameTheFileAndLine) {
  const std::pair<std::string, std::string> cases[] = {
      {replaced(kDeck, "GRID,4,,", "GRID,4,2,"),
       "t.bdf:10: GRID 4 is given in coordinate system 2: nodes in other coordinate systems than the basic one are "
       "not read"},
      {replaced(kDeck, "BEGIN BULK", "BEGIN BULK SUPER=2"),
       "t.bdf:4: superelements are not read: give the model as one bulk data section"},
      {replaced(kDeck, "$ nodes\n", "$ nodes\n+ABC    1\n"), "t.bdf:6: a continuation line with no entry before it"},
      {replaced(kDeck, "GRID, 6,", "=, *1,"), "t.bdf:12: replicated entries ('=' lines) are not read: write each entry out"},
      {replaced(kDeck, "CTETRA,11,2,2,3,4,5", "CTETRA,11,2,2,3,4,9"),
       "t.bdf:14: element 11 names grid point 9, which no GRID defines"},
      {replaced(kDeck, "GRID, 6,", "GRID, 5,"), "t.bdf:12: grid point 5 is defined a second time"},
      {replaced(kDeck, "CTRIA3  20", "CTRIA3  10"), "t.bdf:15: element id 10 is used a second time"},
      {replaced(kDeck, "GRID, 6, , .3,", "GRID, 6, , .3x,"),
       "t.bdf:12: GRID 6: expected a finite coordinate, found '.3x'"},
      {replaced(kDeck, "CTETRA,11,2,2,3,4,5", "CTETRA,11,2,2,3,4,5,6,7,8,9,10,11"),
       "t.bdf:14: a free-field line of small fields holds 8 data fields and a continuation marker, and this one has 12 "
       "fields after its first"},
      {replaced(kDeck, small({"SPC1", "1", "123", "6"}), small({"SPC1", "1", "123", "66"})),
       "t.bdf:17: SPC1 names grid point 66, which no GRID defines"},
      {replaced(kDeck, "CTETRA,11,2,", "CTETRA,11,x,"), "t.bdf:14: expected a property id (PID), found 'x'"},
      {"BEGIN BULK\nGRID,1,,0.,0.,0.\nENDDATA\n", "t.bdf: no CTETRA elements: a volume mesh of tets is needed"},
      {"SOL 101\nCEND\n", "t.bdf: no GRID entries: not a Nastran mesh"},
  };
  for (const auto& [deck, message] : cases) EXPECT_EQ(read_error(deck), message);
}

TEST(NastranIo, FormatByNameAndWhatOtherFormatsLose) {
  EXPECT_EQ(format_from_path("model.BDF"), MeshFormat::Nastran);
  EXPECT_EQ(format_from_path("model.nas"), MeshFormat::Nastran);
  EXPECT_EQ(parse_format("bdf"), MeshFormat::Nastran);
  EXPECT_STREQ(format_name(MeshFormat::Nastran), "nastran");
  const TetMesh mesh = read_text(kDeck);
  EXPECT_TRUE(output_losses(mesh, "out.bdf").empty());
  const std::vector<std::string> to_vtu = output_losses(mesh, "out.vtu");
  ASSERT_EQ(to_vtu.size(), 2u);
  EXPECT_EQ(to_vtu[0], "the Nastran element ids will not be written: vtu numbers them by position");
  EXPECT_EQ(to_vtu[1], "the rest of the Nastran deck (PSOLID, SPC1) will not be written: vtu holds the mesh alone");
  // MSH keeps the ids, not the pin of node 6, which no element holds.
  const std::vector<std::string> to_msh = output_losses(mesh, "out.msh");
  ASSERT_EQ(to_msh.size(), 2u);
  EXPECT_EQ(to_msh[0], "1 pinned node will not be pinned in the msh41 output, so a later run may move it");
  EXPECT_EQ(to_msh[1], "the rest of the Nastran deck (PSOLID, SPC1) will not be written: msh41 holds the mesh alone");
  TetMesh lines = testing::cube_grid(1);
  lines.extras.blocks.push_back(PassThroughBlock{"line3", 3, {}, {}, {}, {}});
  try {
    check_writable(lines, "out.bdf");
    FAIL() << "a 3-node line block written to Nastran";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("Nastran output cannot hold the pass-through 'line3' block"),
              std::string::npos);
  }
  TetMesh renumbered = testing::cube_grid(1);
  renumbered.extras.node_tags.assign(renumbered.num_nodes(), 5);
  const std::vector<std::string> notes = output_losses(renumbered, "out.nas");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0],
            "the node numbers of the file cannot all be kept (each must be positive and distinct, at most "
            "99,999,999): nastran numbers them 1, 2, ... instead");
}

}  // namespace
}  // namespace tetsmooth
