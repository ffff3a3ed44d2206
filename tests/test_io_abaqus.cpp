// Abaqus/CalculiX .inp: nodes, tets and other elements, regions from
// sections or element sets, pins from *BOUNDARY/*CLOAD, the deck written back
// with only its coordinates changed, new decks that read back as written,
// *INCLUDE, and errors naming file:line.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "abaqus_text.hpp"
#include "input_error.hpp"
#include "mesh/errors.hpp"
#include "mesh/io/abaqus_element_types.hpp"
#include "mesh/io/abaqus_io.hpp"
#include "mesh/io/mesh_io.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/io/writable_check.hpp"
#include "support/scratch_dir.hpp"
#include "support/test_meshes.hpp"

namespace tetsmooth {
namespace {

using testing::abaqus_read_error;
using testing::read_abaqus_text;
using testing::write_abaqus_text;

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// Two tets of two materials, a surface element, a pinned node (6) and
// Abaqus's spellings: mixed case, spaces in keywords, a keyword and an
// element that go on on the next line, a D exponent, an omitted coordinate.
const std::string kDeck =
    "*Heading\n"
    " two tets\n"
    "** a comment\n"
    "*Node, nset=All\n"
    "1, 0, 0, 0\n"
    "2, 1, 0, 0\n"
    "3, 0, 1, 0\n"
    "4, 0, 0, 1\n"
    "5, 1.0D0, 1., 1\n"
    "6, 0.3, 0.3\n"
    "*Element, type=C3D4, elset=Lower\n"
    "10, 1, 2, 3,\n"
    " 4\n"
    "*ELEMENT, TYPE=C3D4H\n"
    "11, 2, 3, 4, 5\n"
    "*Element, type=S3R, elset=Skin\n"
    "20, 1, 2, 3\n"
    "*Elset, elset=Upper, generate\n"
    "11, 11, 1\n"
    "*Solid Section, elset=Upper, material=Rock\n"
    "*Solid Section,\n"
    "  elset=LOWER, material=Soil\n"
    "*Material, name=Rock\n"
    "*Elastic\n"
    "1e9, 0.3\n"
    "*Boundary\n"
    "6, 1, 3\n"
    "*Step\n"
    "*Static\n"
    "*End Step\n";

TEST(AbaqusIo, ReadsNodesElementsSectionsAndPins) {
  const TetMesh mesh = read_abaqus_text(kDeck);
  EXPECT_EQ(mesh.xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1, 0.3, 0.3, 0}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3, 1, 2, 3, 4}));
  EXPECT_TRUE(mesh.midsides.empty());
  EXPECT_EQ(mesh.extras.node_tags, (std::vector<long long>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(mesh.extras.tet_element_tags, (std::vector<long long>{10, 11}));
  // Regions are the sections' ordinals: Upper first.
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{2, 1}));
  ASSERT_EQ(mesh.extras.blocks.size(), 1u);
  const PassThroughBlock& skin = mesh.extras.blocks[0];
  EXPECT_EQ(skin.kind, "triangle");
  EXPECT_EQ(skin.connectivity, (std::vector<index_t>{0, 1, 2}));
  EXPECT_EQ(skin.element_tags, (std::vector<long long>{20}));
  // The triangle's nodes, and node 6 that *BOUNDARY names.
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{1, 1, 1, 0, 0, 1}));
  EXPECT_EQ(*raw_section(mesh.extras, "abaqus:keywords"),
            "*Elset, *Solid Section, *Material, *Elastic, *Boundary, *Step, *Static, *End Step");
  EXPECT_EQ(*raw_section(mesh.extras, "abaqus:deck"), "6 2");
  // The regions' names as the deck writes them, for MSH output.
  EXPECT_EQ(*raw_section(mesh.extras, "$PhysicalNames"), "3\n3 1 \"Upper\"\n3 2 \"LOWER\"\n2 1 \"Skin\"\n");
}

TEST(AbaqusIo, ReadsADeckGmshWrote) {
  // tests/data/gmsh_layers_make.py: two volumes, the bottom face's
  // triangles, and Gmsh's lists of its physical groups' elements and nodes.
  const TetMesh mesh = read_abaqus_file(testing::data_path("abaqus_gmsh_layers.inp"));
  EXPECT_EQ(mesh.num_nodes(), 157u);
  ASSERT_EQ(mesh.num_tets(), 470u);
  EXPECT_EQ(mesh.extras.tet_element_tags.front(), 45);
  // The tets of ELSET=Volume1, then Volume2: entity tags as regions.
  EXPECT_EQ(std::count(mesh.extras.tet_tags.begin(), mesh.extras.tet_tags.end(), 1), 234);
  EXPECT_EQ(std::count(mesh.extras.tet_tags.begin(), mesh.extras.tet_tags.end(), 2), 236);
  ASSERT_EQ(mesh.extras.blocks.size(), 1u);
  EXPECT_EQ(mesh.extras.blocks[0].kind, "triangle");
  EXPECT_EQ(mesh.extras.blocks[0].tags, std::vector<int>(44, 5));
  std::vector<std::uint8_t> pinned(mesh.num_nodes(), 0);
  mark_element_nodes(mesh.extras.blocks, pinned);
  EXPECT_EQ(mesh.fixed, pinned);
  EXPECT_EQ(*raw_section(mesh.extras, "abaqus:keywords"), "*ELSET, *NSET");
  EXPECT_EQ(*raw_section(mesh.extras, "$PhysicalNames"),
            "3\n3 1 \"Volume1\"\n3 2 \"Volume2\"\n2 5 \"Surface5\"\n");
}

TEST(AbaqusIo, WritesTheDeckBackWithOnlyItsCoordinatesChanged) {
  TetMesh mesh = read_abaqus_text(kDeck);
  mesh.xyz[3 * 3 + 2] = 0.875;  // node 4
  std::string expected = replaced(kDeck, "4, 0, 0, 1\n", "4, 0, 0, 0.875\n");
  expected = replaced(expected, "5, 1.0D0, 1., 1\n", "5, 1, 1, 1\n");
  expected = replaced(expected, "6, 0.3, 0.3\n", "6, 0.3, 0.3, 0\n");
  EXPECT_EQ(write_abaqus_text(mesh), expected);
}

TEST(AbaqusIo, CommentsAmongNodeLinesStayInPlace) {
  const std::string deck = replaced(kDeck, "3, 0, 1, 0\n", "3, 0, 1, 0\n** the top\n\n");
  EXPECT_EQ(write_abaqus_text(read_abaqus_text(deck)),
            replaced(replaced(deck, "5, 1.0D0, 1., 1\n", "5, 1, 1, 1\n"), "6, 0.3, 0.3\n", "6, 0.3, 0.3, 0\n"));
}

TEST(AbaqusIo, ADeckIsWrittenOnlyForTheMeshItWasReadWith) {
  TetMesh mesh = read_abaqus_text(kDeck);
  mesh.tets.resize(4);
  mesh.extras.tet_tags.resize(1);
  mesh.extras.tet_element_tags.resize(1);
  try {
    write_abaqus_text(mesh);
    FAIL() << "a deck of two tets written for one";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("lists (nodes, tets) 6 2, and the mesh has 6 1"), std::string::npos)
        << e.what();
  }
  TetMesh unnumbered = read_abaqus_text(kDeck);
  unnumbered.extras.node_tags.clear();
  try {
    write_abaqus_text(unnumbered);
    FAIL() << "a deck written without its node numbers";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("and the mesh has 6 2 without their numbers"), std::string::npos) << e.what();
  }
}

TEST(AbaqusIo, RegionsWithoutSectionsComeFromTheElementLinesSets) {
  const std::string two_sets =
      "*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n5,1,1,1\n"
      "*ELEMENT, TYPE=C3D4, ELSET=Volume7\n1, 1, 2, 3, 4\n"
      "*ELEMENT, TYPE=C3D4, ELSET=Volume3\n2, 2, 3, 4, 5\n";
  EXPECT_EQ(read_abaqus_text(two_sets).extras.tet_tags, (std::vector<int>{7, 3}));
  // Names without distinct trailing numbers are numbered in the order met.
  EXPECT_EQ(read_abaqus_text(replaced(two_sets, "Volume3", "Set-7")).extras.tet_tags, (std::vector<int>{1, 2}));
  EXPECT_EQ(read_abaqus_text(replaced(two_sets, "Volume3", "Soil")).extras.tet_tags, (std::vector<int>{1, 2}));
  // No set at all: no regions.
  EXPECT_TRUE(read_abaqus_text(replaced(replaced(two_sets, ", ELSET=Volume7", ""), ", ELSET=Volume3", ""))
                  .extras.tet_tags.empty());
}

TEST(AbaqusIo, NodeSetsAndElementSetsPinThroughBoundaryAndLoads) {
  const std::string deck =
      "*NODE, NSET=Corner\n1,0,0,0\n*NODE\n2,1,0,0\n3,0,1,0\n4,0,0,1\n5,1,1,1\n6,0.4,0.4,0.4\n7,0.3,0.3,0.3\n"
      "*ELEMENT, TYPE=C3D4, ELSET=A\n1, 1, 2, 3, 4\n2, 2, 3, 4, 5\n"
      "*NSET, NSET=Loaded\nInner,\n"
      "*NSET, NSET=Inner, GENERATE\n6, 7\n"
      "*NSET, NSET=FromElements, ELSET=Second\n"
      "*ELSET, ELSET=Second\n2\n"
      "*STEP\n*STATIC\n*CLOAD\nLoaded, 1, 10.\n*END STEP\n";
  EXPECT_EQ(read_abaqus_text(deck).fixed, (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 1, 1}));
  EXPECT_EQ(read_abaqus_text(replaced(deck, "Loaded, 1", "FromElements, 1")).fixed,
            (std::vector<std::uint8_t>{0, 1, 1, 1, 1, 0, 0}));
  EXPECT_EQ(read_abaqus_text(replaced(deck, "Loaded, 1", "corner, 1")).fixed,
            (std::vector<std::uint8_t>{1, 0, 0, 0, 0, 0, 0}));
  // The set the writer leaves for pins.
  EXPECT_EQ(read_abaqus_text(replaced(deck, "NSET=Inner", "NSET=tetsmooth_pinned") + "*NSET, NSET=Inner\n7\n").fixed,
            (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 1, 1}));
  EXPECT_TRUE(read_abaqus_text(replaced(deck, "*CLOAD\nLoaded, 1, 10.\n", "")).fixed.empty());
}

TEST(AbaqusIo, ANewDeckReadsBackAsWritten) {
  TetMesh mesh = testing::cube_grid(3, 0.2);
  mesh.extras.tet_tags.assign(mesh.num_tets(), 4);
  for (std::size_t t = 0; t < mesh.num_tets() / 3; ++t) mesh.extras.tet_tags[t] = -2;
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) mesh.extras.node_tags.push_back(100 + 2 * static_cast<long long>(i));
  PassThroughBlock lines{"line3", 3, {0, 2, 1, 4, 6, 5}, {9, 9}, {}, {}};
  mesh.extras.blocks.push_back(lines);
  mesh.fixed.assign(mesh.num_nodes(), 0);
  mesh.fixed[21] = 1;  // an interior node that no element pins
  for (index_t n : lines.connectivity) mesh.fixed[static_cast<std::size_t>(n)] = 1;
  const std::string text = write_abaqus_text(mesh);
  EXPECT_NE(text.find("*ELEMENT, TYPE=C3D4, ELSET=REGION_M2\n1, "), std::string::npos) << text;
  EXPECT_NE(text.find("*ELEMENT, TYPE=C3D4, ELSET=REGION_4\n"), std::string::npos);
  // A 3-node line is written end, middle, end.
  EXPECT_NE(text.find("*ELEMENT, TYPE=T3D3, ELSET=LINE3_9\n" + std::to_string(mesh.num_tets() + 1) + ", 100, 102, 104\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("*NSET, NSET=TETSMOOTH_PINNED\n142\n"), std::string::npos) << text;
  const TetMesh back = read_abaqus_text(text);
  EXPECT_EQ(back.xyz, mesh.xyz);
  EXPECT_EQ(back.tets, mesh.tets);
  EXPECT_EQ(back.extras.node_tags, mesh.extras.node_tags);
  EXPECT_EQ(back.extras.tet_tags, mesh.extras.tet_tags);
  // MSH output renumbers negative tags, so only the others are named.
  EXPECT_EQ(*raw_section(back.extras, "$PhysicalNames"), "2\n3 4 \"REGION_4\"\n1 9 \"LINE3_9\"\n");
  ASSERT_EQ(back.extras.blocks.size(), 1u);
  EXPECT_EQ(back.extras.blocks[0].kind, "line3");
  EXPECT_EQ(back.extras.blocks[0].connectivity, lines.connectivity);
  EXPECT_EQ(back.extras.blocks[0].tags, lines.tags);
  EXPECT_EQ(back.fixed, mesh.fixed);
}

TEST(AbaqusIo, ANewDeckNamesTheElementSetsAfterTheRegionsWhereAbaqusTakesTheNames) {
  TetMesh mesh = testing::cube_grid(2);
  const std::size_t tets = mesh.num_tets();
  // Tags 1..7, a run of tets each; 8 (unnamed) for the rest.
  mesh.extras.tet_tags.assign(tets, 8);
  for (std::size_t t = 0; t < 7; ++t) mesh.extras.tet_tags[t] = static_cast<int>(t) + 1;
  mesh.extras.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 1, 2, 3, 4, 5}, {5, 6}, {}, {}});
  const std::string long_name(81, 'L');
  mesh.extras.raw_sections.emplace_back("$PhysicalNames",
                                        "9\n3 1 \"granite\"\n3 2 \"soft clay\"\n3 3 \"Rock\"\n3 4 \"ROCK\"\n3 5 \"\"\n"
                                        "3 6 \"" +
                                            long_name + "\"\n3 7 \"region_8\"\n2 5 \"Top_2\"\n2 6 \"rock\"\n");
  const std::string text = write_abaqus_text(mesh);
  EXPECT_NE(text.find("*ELEMENT, TYPE=C3D4, ELSET=granite\n1, "), std::string::npos) << text;
  // Quotes would be needed, the same in another case, no name, over 80
  // characters, another region's set (tag 8's REGION_8): named by tag.
  for (const char* by_tag : {"REGION_2", "REGION_3", "REGION_4", "REGION_5", "REGION_6", "REGION_7", "REGION_8"})
    EXPECT_NE(text.find(std::string("*ELEMENT, TYPE=C3D4, ELSET=") + by_tag + "\n"), std::string::npos) << by_tag;
  // Names are per dimension: tag 5 of triangles is Top_2; rock is that of
  // volumes too.
  EXPECT_NE(text.find("*ELEMENT, TYPE=SFM3D3, ELSET=Top_2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("*ELEMENT, TYPE=SFM3D3, ELSET=TRIANGLE_6\n"), std::string::npos) << text;
  EXPECT_EQ(abaqus_names_lost(mesh),
            (std::vector<std::string>{"rock", "soft clay", "Rock", "ROCK", long_name, "region_8"}));
  // Read back, the sets name the regions (tags by order, as the names have
  // no numbers of their own to give).
  const TetMesh back = read_abaqus_text(text);
  const std::map<int, std::string> names = physical_names_of(*raw_section(back.extras, "$PhysicalNames"), 3);
  ASSERT_EQ(back.extras.tet_tags.size(), tets);
  EXPECT_EQ(names.at(back.extras.tet_tags[0]), "granite");
  EXPECT_EQ(names.at(back.extras.tet_tags[1]), "REGION_2");
  EXPECT_EQ(physical_names_of(*raw_section(back.extras, "$PhysicalNames"), 2).at(back.extras.blocks[0].tags[0]),
            "Top_2");
  // The warning names only the names not written, and no longer says that
  // Abaqus has no place for them.
  // And that the tags come back as other numbers (sets named without numbers).
  const std::vector<std::string> notes = output_losses(mesh, "out.inp");
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_EQ(notes[1].substr(0, 41), "the region tags will not be kept: a new a");
  EXPECT_FALSE(abaqus_tags_read_back(mesh));
  EXPECT_EQ(notes[0],
            "the names of 6 regions (Gmsh physical names: \"rock\", \"soft clay\", \"Rock\", \"ROCK\", \"" + long_name +
                "\" and 1 more) will not be written: a new abaqus deck names a region's element set by its tag where "
                "the name is no plain set name (1 to 80 letters, digits and underscores, the first a letter) or is "
                "another's in any case");
  mesh.extras.raw_sections.back().second = "2\n3 1 \"granite\"\n3 8 \"Rest_of_it\"\n";
  EXPECT_EQ(output_losses(mesh, "out.inp").size(), 1u);  // the tags alone
  EXPECT_NE(write_abaqus_text(mesh).find("*ELEMENT, TYPE=C3D4, ELSET=Rest_of_it\n"), std::string::npos);
  // Names that end in their own tags, apart from every other set's number,
  // give the tags back: nothing is lost.
  mesh.extras.blocks.clear();
  mesh.extras.raw_sections.back().second = "2\n3 1 \"Layer_1\"\n3 8 \"Layer_8\"\n";
  EXPECT_TRUE(abaqus_tags_read_back(mesh));
  EXPECT_TRUE(output_losses(mesh, "out.inp").empty());
  EXPECT_EQ(read_abaqus_text(write_abaqus_text(mesh)).extras.tet_tags, mesh.extras.tet_tags);
  // Numbers that are other regions' tags come back swapped: said so.
  mesh.extras.raw_sections.back().second = "2\n3 1 \"Part8\"\n3 8 \"Part1\"\n";
  EXPECT_FALSE(abaqus_tags_read_back(mesh));
}

TEST(AbaqusIo, ANewDeckListsManyPinsSixteenALineAndRenumbersWhatItCannotKeep) {
  TetMesh mesh = testing::cube_grid(5);
  mesh.fixed.assign(mesh.num_nodes(), 0);
  std::vector<std::string> pinned;
  for (std::size_t i = 0; i < mesh.num_nodes() && pinned.size() < 20; ++i)
    if (i % 7 == 3) {
      mesh.fixed[i] = 1;
      pinned.push_back(std::to_string(i + 1));
    }
  const std::string text = write_abaqus_text(mesh);
  std::string lines = "*NSET, NSET=TETSMOOTH_PINNED\n";
  for (std::size_t k = 0; k < pinned.size(); ++k) lines += pinned[k] + (k + 1 == pinned.size() ? "\n" : k % 16 == 15 ? "\n" : ", ");
  EXPECT_NE(text.find(lines), std::string::npos) << text.substr(text.find("*NSET"));
  EXPECT_EQ(read_abaqus_text(text).fixed, mesh.fixed);
  EXPECT_TRUE(output_losses(mesh, "out.inp").empty());
  // A node number 0 cannot be kept: every node is numbered by position.
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) mesh.extras.node_tags.push_back(static_cast<long long>(i) * 5);
  EXPECT_EQ(read_abaqus_text(write_abaqus_text(mesh)).extras.node_tags.back(),
            static_cast<long long>(mesh.num_nodes()));
  const std::vector<std::string> notes = output_losses(mesh, "out.inp");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "the node numbers of the file cannot all be kept (each must be positive and distinct): abaqus "
                      "numbers them 1, 2, ... instead");
}

TEST(AbaqusIo, SecondOrderTetsListTheirMidsideNodesInEdgeOrder) {
  const TetMesh mesh = testing::with_midsides(testing::cube_grid(2, 0.1));
  const std::string text = write_abaqus_text(mesh);
  ASSERT_NE(text.find("*ELEMENT, TYPE=C3D10\n"), std::string::npos);
  const TetMesh back = read_abaqus_text(text);
  EXPECT_EQ(back.tets, mesh.tets);
  EXPECT_EQ(back.midsides, mesh.midsides);
  EXPECT_EQ(back.xyz, mesh.xyz);
  // A C3D10 lists its corners, then the midside nodes of edges 12, 23, 31,
  // 14, 24, 34 (Abaqus's manual), which are kTetEdges.
  const std::string ten =
      "*NODE\n1,0,0,0\n2,2,0,0\n3,0,2,0\n4,0,0,2\n5,1,0,0\n6,1,1,0\n7,0,1,0\n8,0,0,1\n9,1,0,1\n10,0,1,1\n"
      "*ELEMENT, TYPE=C3D10MH\n1, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10\n";
  EXPECT_EQ(read_abaqus_text(ten).midsides, (std::vector<index_t>{4, 5, 6, 7, 8, 9}));
}

TEST(AbaqusIo, IncludedFilesAreReadInPlaceAndWrittenInline) {
  testing::ScratchDir dir("abaqus_include");
  std::filesystem::create_directory(dir.file("mesh"));
  {
    // Relative paths, in a nested file too, start from the job's directory
    // (the first deck's), as Abaqus takes them; '\' is read as '/'.
    std::ofstream(dir.file("mesh/nodes.inp")) << "\xEF\xBB\xBF*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n";
    std::ofstream(dir.file("mesh/model.inp")) << "*INCLUDE, INPUT=mesh\\nodes.inp\n*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n";
    std::ofstream(dir.file("job.inp")) << "*HEADING\n*INCLUDE, INPUT=\"mesh/model.inp\"\n*STEP\n";
  }
  const TetMesh mesh = read_abaqus_file(dir.file("job.inp"));
  EXPECT_EQ(mesh.num_nodes(), 4u);
  EXPECT_EQ(write_abaqus_text(mesh),
            "*HEADING\n*NODE\n1, 0, 0, 0\n2, 1, 0, 0\n3, 0, 1, 0\n4, 0, 0, 1\n"
            "*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n*STEP\n");
  const std::vector<std::string> notes = output_losses(mesh, "out.inp");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "the *INCLUDE files (" + dir.file("mesh/model.inp") + ", " + dir.file("mesh/nodes.inp") +
                          ") will be written inline, in the one output deck");
  // Errors name the line of the included file.
  std::ofstream(dir.file("mesh/nodes.inp")) << "*NODE\n1,0,0,0\n1,1,0,0\n";
  EXPECT_NE(testing::input_error_message([&] { read_abaqus_file(dir.file("job.inp")); }, "job.inp")
                .find(dir.file("mesh/nodes.inp") + ":3: node 1 is defined a second time"),
            std::string::npos);
  std::ofstream(dir.file("self.inp")) << "*HEADING\n*INCLUDE, INPUT=self.inp\n";
  EXPECT_NE(testing::input_error_message([&] { read_abaqus_file(dir.file("self.inp")); }, "self.inp")
                .find("self.inp:2: *INCLUDE: " + dir.file("self.inp") + " includes itself"),
            std::string::npos);
  // Files nested 65 deep (no file includes itself), repeated too often, and
  // a device.
  for (int k = 0; k < 66; ++k)
    std::ofstream(dir.file("n" + std::to_string(k) + ".inp")) << "*INCLUDE, INPUT=n" << k + 1 << ".inp\n";
  EXPECT_NE(testing::input_error_message([&] { read_abaqus_file(dir.file("n0.inp")); }, "n0.inp")
                .find("n64.inp:1: *INCLUDE: nested more than 64 files deep"),
            std::string::npos);
  // Files that each include the next twice: the last would be read 512
  // times (and 40 such files would make 2^40 lines).
  for (int k = 0; k < 10; ++k)
    std::ofstream(dir.file("d" + std::to_string(k) + ".inp"))
        << (k == 9 ? std::string("** leaf\n")
                   : "*INCLUDE, INPUT=d" + std::to_string(k + 1) + ".inp\n*INCLUDE, INPUT=d" + std::to_string(k + 1) +
                         ".inp\n");
  EXPECT_NE(testing::input_error_message([&] { read_abaqus_file(dir.file("d0.inp")); }, "d0.inp")
                .find("d8.inp:1: *INCLUDE: " + dir.file("d9.inp") +
                      " is included more than 256 times in all: files that include others several times multiply "
                      "their lines"),
            std::string::npos);
  std::ofstream(dir.file("device.inp")) << "*INCLUDE, INPUT=/dev/null\n";
  EXPECT_NE(testing::input_error_message([&] { read_abaqus_file(dir.file("device.inp")); }, "device.inp")
                .find("device.inp:1: *INCLUDE: /dev/null is not a regular file"),
            std::string::npos);
  // An error names the keyword's first line.
  std::ofstream(dir.file("split.inp")) << "*HEADING\n*INCLUDE,\n INPUT=missing.inp\n";
  EXPECT_NE(testing::input_error_message([&] { read_abaqus_file(dir.file("split.inp")); }, "split.inp")
                .find("split.inp:2: *INCLUDE: "),
            std::string::npos);
  std::ofstream(dir.file("lost.inp")) << "*HEADING\n*INCLUDE, INPUT=missing.inp\n";
  EXPECT_NE(testing::input_error_message([&] { read_abaqus_file(dir.file("lost.inp")); }, "lost.inp")
                .find("lost.inp:2: *INCLUDE: " + dir.file("missing.inp") +
                      ": cannot open: No such file or directory (a relative path starts from the job's directory"),
            std::string::npos);
}

TEST(AbaqusIo, ShortenedKeywordsAndParametersAndQuotedNames) {
  // Abaqus takes any unambiguous prefix of a keyword or parameter.
  std::string deck = replaced(kDeck, "*Element, type=C3D4, elset=Lower", "*ELEM, TYP=C3D4, ELS=Lower");
  deck = replaced(deck, "*Elset, elset=Upper, generate", "*ELSET, ELSET=Upper, GEN");
  deck = replaced(deck, "*Solid Section, elset=Upper", "*Solid Sec, elset=Upper");
  deck = replaced(deck, "*Boundary\n6, 1, 3\n", "*BOUND\n\"Free, node\", 1, 3\n*NSET, NSET=\"Free, node\"\n6\n");
  const TetMesh mesh = read_abaqus_text(deck);
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{2, 1}));
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{1, 1, 1, 0, 0, 1}));
  // A quoted name keeps its spaces and commas; an unquoted one loses its spaces.
  EXPECT_NE(abaqus_read_error(replaced(deck, "NSET=\"Free, node\"", "NSET=Freenode"))
                .find("no node set FREE, NODE is defined"),
            std::string::npos);
  // A prefix of two keywords the reader knows is no abbreviation of either.
  EXPECT_NE(abaqus_read_error(replaced(kDeck, "*Element, type=C3D4, elset=Lower", "*EL, type=C3D4"))
                .find("t.inp:11: keyword line: the keyword EL could be short for ELEMENT, ELSET, ELGEN or ELCOPY"),
            std::string::npos);
}

TEST(AbaqusIo, EquationsAndMultiPointConstraintsPinTheirNodes) {
  const std::string base =
      "*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n5,1,1,1\n6,0.4,0.4,0.4\n7,0.3,0.3,0.3\n"
      "*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n2, 2, 3, 4, 5\n*NSET, NSET=Six\n6\n";
  EXPECT_EQ(read_abaqus_text(base + "*EQUATION\n2\n7, 1, 1.0, Six, 1, -1.0\n").fixed,
            (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 1, 1}));
  EXPECT_EQ(read_abaqus_text(base + "*MPC\nBEAM, 7, 0, 1\n").fixed, (std::vector<std::uint8_t>{1, 0, 0, 0, 0, 0, 1}));
  EXPECT_EQ(read_abaqus_text(base + "*CFLOW\nSix, , 2.5\n").fixed, (std::vector<std::uint8_t>{0, 0, 0, 0, 0, 1, 0}));
}

TEST(AbaqusIo, RegionsFromElementSetsAloneWhereTheDeckHasNothingElse) {
  // meshio writes Gmsh's physical groups as *ELSET lists; a set over every
  // tet splits nothing.
  const std::string deck =
      "*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n5,1,1,1\n6,-1,-1,-1\n"
      "*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n2, 2, 3, 4, 5\n3, 6, 1, 3, 2\n"
      "*ELEMENT, TYPE=COH3D6\n4, 1, 2, 3, 1, 2, 3\n"
      "*ELSET, ELSET=All\n1, 2, 3, 4\n*ELSET, ELSET=Rock\n2\n*ELSET, ELSET=Soil\n1, 3\n";
  const TetMesh mesh = read_abaqus_text(deck);
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{1, 2, 1}));
  ASSERT_EQ(mesh.extras.blocks.size(), 1u);
  EXPECT_EQ(mesh.extras.blocks[0].kind, "wedge");
}

TEST(AbaqusIo, RegionsFromElementSetsAloneTakeTheNamesOfTheSetsThatHoldThem) {
  // A region is named after the first set that holds its tets and no others
  // (as written, quotes removed); one that only several sets describe, or
  // none, stays unnamed. All holds both regions and names neither.
  const std::string nodes = "*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n5,1,1,1\n6,-1,-1,-1\n";
  const std::string tets = "*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n2, 2, 3, 4, 5\n3, 6, 1, 3, 2\n";
  const TetMesh named =
      read_abaqus_text(nodes + tets +
                       "*ELSET, ELSET=All\n1, 2, 3\n*ELSET, ELSET=\"Hard rock\"\n2\n"
                       "*ELSET, ELSET=granite, GENERATE\n1, 3, 2\n*ELSET, ELSET=AlsoGranite\n3, 1, 1\n");
  EXPECT_EQ(named.extras.tet_tags, (std::vector<int>{1, 2, 1}));
  ASSERT_NE(raw_section(named.extras, "$PhysicalNames"), nullptr);
  EXPECT_EQ(*raw_section(named.extras, "$PhysicalNames"), "2\n3 2 \"Hard rock\"\n3 1 \"granite\"\n");
  // Tet 1 in A and B, tet 2 in B, tet 3 in none: no set holds tet 1 alone.
  const TetMesh unnamed =
      read_abaqus_text(nodes + tets + "*ELSET, ELSET=A\n1\n*ELSET, ELSET=B\n1, 2\n*ELSET, ELSET=C\n2, 3\n");
  EXPECT_EQ(unnamed.extras.tet_tags, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(*raw_section(unnamed.extras, "$PhysicalNames"), "1\n3 1 \"A\"\n");
  const TetMesh none = read_abaqus_text(nodes + tets + "*ELSET, ELSET=A\n1, 2\n*ELSET, ELSET=B\n2, 3\n");
  EXPECT_EQ(none.extras.tet_tags, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(raw_section(none.extras, "$PhysicalNames"), nullptr);
  // The engineer's deck, in meshio's layout: the names reach MSH.
  const TetMesh meshio_layout =
      read_abaqus_text(nodes +
                       "*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n*ELEMENT, TYPE=C3D4\n2, 2, 3, 4, 5\n"
                       "*ELSET, ELSET=granite\n1\n*ELSET, ELSET=clay\n2\n");
  EXPECT_EQ(*raw_section(meshio_layout.extras, "$PhysicalNames"), "2\n3 1 \"granite\"\n3 2 \"clay\"\n");
}

TEST(AbaqusIo, SetsByStepsByElementSetsAndSectionsThatOverlap) {
  const std::string base =
      "*NODE, SYSTEM=R\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n5,1,1,1\n6,0.4,0.4,0.4\n7,0.3,0.3,0.3\n8,0.2,0.2,0.2\n"
      "9,0.1,0.1,0.1\n*ELEMENT, TYPE=C3D4\n1, 1, 2, 3, 4\n2, 2, 3, 4, 5\n";
  // GENERATE with a step of 3: nodes 2, 5 and 8.
  EXPECT_EQ(read_abaqus_text(base + "*NSET, NSET=S, GENERATE\n2, 8, 3\n*BOUNDARY\nS, 1\n").fixed,
            (std::vector<std::uint8_t>{0, 1, 0, 0, 1, 0, 0, 1, 0}));
  // *NSET, ELSET: the data lines name element sets.
  EXPECT_EQ(read_abaqus_text(base + "*ELSET, ELSET=Second\n2\n*NSET, NSET=N, ELSET\nSecond\n*BOUNDARY\nN, 1\n").fixed,
            (std::vector<std::uint8_t>{0, 1, 1, 1, 1, 0, 0, 0, 0}));
  // A tet in two sections (Abaqus would refuse it) takes the first.
  const std::string sections = "*ELSET, ELSET=A\n1, 2\n*ELSET, ELSET=B\n2\n";
  EXPECT_EQ(read_abaqus_text(base + sections + "*SOLID SECTION, ELSET=B\n*SOLID SECTION, ELSET=A\n").extras.tet_tags,
            (std::vector<int>{2, 1}));
  // Regions from element sets alone, however many: sets that hold both
  // tets, or one each, keep them apart; those that hold one, together.
  std::string many = base;
  for (int s = 0; s < 300; ++s)
    many += "*ELSET, ELSET=E" + std::to_string(s) + "\n" + (s % 3 == 0 ? "1, 2" : std::to_string(1 + s % 2)) + "\n";
  EXPECT_EQ(read_abaqus_text(many).extras.tet_tags, (std::vector<int>{1, 2}));
  EXPECT_EQ(read_abaqus_text(base + "*ELSET, ELSET=All\n1, 2\n*ELSET, ELSET=Again\n2, 1\n").extras.tet_tags,
            (std::vector<int>{1, 1}));
  // A set numbered 0 is no tag of its own: 0 is that of tets without a set.
  const std::string zero =
      "*NODE\n1,0,0,0\n2,1,0,0\n3,0,1,0\n4,0,0,1\n5,1,1,1\n*ELEMENT, TYPE=C3D4, ELSET=Volume0\n1, 1, 2, 3, 4\n"
      "*ELEMENT, TYPE=C3D4\n2, 2, 3, 4, 5\n";
  EXPECT_EQ(read_abaqus_text(zero).extras.tet_tags, (std::vector<int>{1, 0}));
}

TEST(AbaqusIo, EveryRefusedKeywordSaysWhy) {
  for (const char* keyword : {"NGEN", "NFILL", "NCOPY", "NMAP", "SYSTEM", "ELGEN", "ELCOPY"}) {
    const std::string message = abaqus_read_error(replaced(kDeck, "*Step\n", "*" + std::string(keyword) + "\n"));
    EXPECT_NE(message.find("t.inp:28: *" + std::string(keyword) + ": "), std::string::npos) << message;
    EXPECT_NE(message.find(" not read"), std::string::npos) << message;
  }
}

TEST(AbaqusIo, ErrorsNameTheFileAndLine) {
  const struct {
    std::string from, to, message;
  } cases[] = {
      {"*Heading\n", "*Part, name=Block\n", "t.inp:1: *PART without *END PART"},
      {"*Step\n", "*Instance, name=B-1, part=B\n", "t.inp:28: *INSTANCE outside *ASSEMBLY"},
      {"*Step\n", "*NGEN\n", "t.inp:28: *NGEN: node generation is not read"},
      {"*Node, nset=All\n", "*Node, system=C\n", "t.inp:4: *NODE, SYSTEM=C: nodes in cylindrical or spherical"},
      {"type=S3R", "type=C3D20R", "t.inp:16: unsupported element type C3D20R (a 20-node hexahedron)"},
      {"type=S3R", "type=XYZ", "t.inp:16: unsupported element type XYZ;"},
      {"type=S3R, elset=Skin", "elset=Skin", "t.inp:16: *ELEMENT without TYPE="},
      {"10, 1, 2, 3,\n 4\n", "10, 1, 2, 3\n",
       "t.inp:12: element 10 of type C3D4 lists 3 of its 4 nodes (a line that goes on"},
      {"11, 2, 3, 4, 5\n", "11, 2, 3, 4, 5, 6\n", "t.inp:15: element 11 of type C3D4H lists 5 nodes, not 4"},
      {"11, 2, 3, 4, 5\n", "11, 2, 3, x, 5\n", "t.inp:15: expected a positive node number, found 'x'"},
      {"11, 2, 3, 4, 5\n", "11, 2, 3, 4, 9\n", "t.inp:15: element 11 names node 9, which no *NODE line defines"},
      {"*ELEMENT, TYPE=C3D4H\n", "*ELEMENT, TYPE=C3D10\n",
       "t.inp:15: element 11 of type C3D10 lists 4 of its 10 nodes"},
      {"6, 0.3, 0.3\n", "6, 0.3, zero\n", "t.inp:10: node 6: expected a finite coordinate, found 'zero'"},
      {"6, 0.3, 0.3\n", "6, 0.3, 0.3, 0, 1, 0\n", "t.inp:10: node 6 has 6 fields"},
      {"6, 0.3, 0.3\n", "5, 0.3, 0.3\n", "t.inp:10: node 5 is defined a second time"},
      {"20, 1, 2, 3\n", "10, 1, 2, 3\n", "t.inp:17: element 10 is defined a second time"},
      {"elset=Upper, material", "elset=Middle, material", "t.inp:20: no element set MIDDLE is defined"},
      {"6, 1, 3\n", "Top, 1, 3\n", "t.inp:27: no node set TOP is defined"},
      {"6, 1, 3\n", "60, 1, 3\n", "t.inp:27: node 60 is not defined"},
      {"11, 11, 1\n", "11, 9\n", "t.inp:19: a GENERATE range that ends before it starts"},
      {"*Heading\n", "1, 2\n*Heading\n", "t.inp:1: a data line before the first keyword"},
      {"*Material, name=Rock\n", "*Material, name=\"Rock\n", "t.inp:23: keyword line: a quote that does not close"},
      {"*Material, name=Rock\n", "*Material, name=Rock,\n",
       "t.inp:23: the keyword line ends with a comma, and the next line is a keyword line"},
      {"*End Step\n", "*End Step,\n", "t.inp:30: the keyword line ends with a comma, and its file ends after it"},
      {"*Element, type=C3D4, elset=Lower\n", "*Element, type=C3D4, elset=Lower,\n",
       "t.inp:11: keyword line: '10' is no parameter (does a comma at the end of the keyword line join a data line"},
      {"*Boundary\n", "*Boundary, input=bc.inp\n", "t.inp:26: *BOUNDARY lines from another file (INPUT=) are not read"},
      {"*Node, nset=All\n", "*Node, nset=All, inp=n.inp\n", "t.inp:4: *NODE lines from another file (INPUT=)"},
      {"6, 1, 3\n", "Lower, 1, 3\n", "t.inp:27: no node set LOWER is defined (LOWER is a set of elements)"},
  };
  for (const auto& c : cases) {
    const std::string message = abaqus_read_error(replaced(kDeck, c.from, c.to));
    EXPECT_NE(message.find(c.message), std::string::npos) << "expected: " << c.message << "\ngot: " << message;
  }
  EXPECT_NE(abaqus_read_error("*HEADING\n*NODE\n1,0,0,0\n").find("t.inp: no tets (C3D4 or C3D10 elements)"),
            std::string::npos);
  EXPECT_NE(abaqus_read_error("*ELSET, ELSET=A\n10\n*ELSET, ELSET=B\nA\n*ELSET, ELSET=A\nB\n" + kDeck.substr(9) +
                              "*SOLID SECTION, ELSET=A\n")
                .find("element set A contains itself"),
            std::string::npos);
}

TEST(AbaqusIo, ElementTypesByFamily) {
  const auto kind = [](const char* name) {
    const auto type = abaqus::element_type(name);
    return type ? type->kind + "/" + std::to_string(type->nodes) : std::string("none");
  };
  EXPECT_EQ(kind("c3d4"), "tetra/4");
  EXPECT_EQ(kind("C3D4PH"), "tetra/4");
  EXPECT_EQ(kind("DC3D4"), "tetra/4");
  EXPECT_EQ(kind("C3D10MPH"), "tetra10/10");
  EXPECT_EQ(kind("AC3D10"), "tetra10/10");
  EXPECT_EQ(kind("C3D8R"), "hexahedron/8");
  EXPECT_EQ(kind("CPS6"), "triangle6/6");
  EXPECT_EQ(kind("S4R5"), "quad/4");
  EXPECT_EQ(kind("B31OS"), "line/2");
  EXPECT_EQ(kind("B32"), "line3/3");
  EXPECT_EQ(kind("MASS"), "vertex/1");
  EXPECT_EQ(kind("C3D15"), "none");
  EXPECT_EQ(kind("C3D20R"), "none");
  EXPECT_EQ(kind("XC3D4"), "none");
  // Each type the writer gives reads back as its kind.
  const struct {
    const char* kind;
    int nodes;
  } written[] = {{"tetra", 4},    {"tetra10", 10}, {"hexahedron", 8}, {"wedge", 6}, {"pyramid", 5}, {"triangle", 3},
                 {"triangle6", 6}, {"quad", 4},     {"line", 2},       {"line3", 3}, {"vertex", 1}};
  for (const auto& w : written) {
    const char* name = abaqus::type_name_of(w.kind, w.nodes);
    ASSERT_NE(name, nullptr) << w.kind;
    EXPECT_EQ(kind(name), std::string(w.kind) + "/" + std::to_string(w.nodes));
  }
  EXPECT_EQ(abaqus::type_name_of("quad", 8), nullptr);
}

TEST(AbaqusIo, FormatByNameAndWhatOtherFormatsLose) {
  EXPECT_EQ(format_from_path("model.INP"), MeshFormat::Abaqus);
  EXPECT_EQ(parse_format("inp"), MeshFormat::Abaqus);
  EXPECT_STREQ(format_name(MeshFormat::Abaqus), "abaqus");
  const TetMesh mesh = read_abaqus_text(kDeck);
  EXPECT_TRUE(output_losses(mesh, "out.inp").empty());
  const std::vector<std::string> to_vtu = output_losses(mesh, "out.vtu");
  ASSERT_EQ(to_vtu.size(), 3u);
  EXPECT_EQ(to_vtu[0], "the Abaqus element numbers will not be written: vtu numbers them by position");
  EXPECT_EQ(to_vtu[1], "the rest of the Abaqus deck (*Elset, *Solid Section, *Material, *Elastic, *Boundary, *Step, "
                       "*Static, *End Step) will not be written: vtu holds the mesh alone");
  EXPECT_EQ(to_vtu[2], "the names of the regions (the deck's element sets) will not be written: vtu has no place for "
                       "them");
  // MSH keeps the numbers and the names (as physical names), not the rest,
  // nor the pin of node 6, which no element holds.
  const std::vector<std::string> to_msh = output_losses(mesh, "out.msh");
  ASSERT_EQ(to_msh.size(), 2u);
  EXPECT_EQ(to_msh[0], "1 pinned node will not be pinned in the msh41 output, so a later run may move it");
  EXPECT_EQ(to_msh[1].substr(0, 30), "the rest of the Abaqus deck (*");
  TetMesh hexes = testing::cube_grid(1);
  hexes.extras.blocks.push_back(PassThroughBlock{"polygon", 7, {}, {}, {}, {}});
  try {
    check_writable(hexes, "out.inp");
    FAIL() << "a 7-node polygon block written to Abaqus";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("Abaqus output cannot hold the pass-through 'polygon' block"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace tetsmooth
