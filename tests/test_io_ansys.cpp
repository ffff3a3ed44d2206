// ANSYS archive files (.cdb): the blocks' Fortran formats and fields, tets
// of every form ANSYS writes them in, regions from materials and element
// components, pins from components, elements and loads, the file written
// back with only moved nodes' records changed, new files that read back as
// written, and errors naming file:line.
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/errors.hpp"
#include "mesh/io/ansys_element_types.hpp"
#include "mesh/io/ansys_fields.hpp"
#include "mesh/io/ansys_io.hpp"
#include "mesh/io/mesh_io.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/io/writable_check.hpp"
#include "support/input_error.hpp"
#include "support/test_meshes.hpp"

namespace tetsmooth {
namespace {

using ansys::BlockFormat;

TetMesh read_text(const std::string& text) {
  std::istringstream in(text);
  return read_ansys(in, "t.cdb");
}

std::string write_text(const TetMesh& mesh) {
  std::ostringstream out;
  write_ansys(mesh, out);
  return out.str();
}

std::string read_error(const std::string& text) {
  return testing::input_error_message([&] { read_text(text); }, "read_ansys:\n" + text);
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// Integers right-aligned in fields of `width`.
std::string ints(const std::vector<long long>& values, int width) {
  std::string line;
  for (long long v : values) {
    const std::string t = std::to_string(v);
    line += std::string(static_cast<std::size_t>(width) - t.size(), ' ') + t;
  }
  return line;
}

// A deck in CDWRITE's layout: the nodes of `mesh` numbered 1, 2, ..., the
// `elements` records as given (each a full record, lines included), and
// `extra` after the EBLOCK.
std::string deck(const TetMesh& mesh, const std::string& types, const std::string& elements,
                 const std::string& extra = "") {
  std::string text = "/PREP7\n" + types + "NBLOCK,6,SOLID," + std::to_string(mesh.num_nodes()) + "\n(3i9,6e21.13e3)\n";
  const BlockFormat f{3, 9, 6, 21, 13, 3, 0};
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) {
    std::string line = ints({static_cast<long long>(i) + 1, 0, 0}, 9);
    for (int c = 0; c < 3; ++c) ansys::format_real(mesh.xyz[3 * i + static_cast<std::size_t>(c)], f, line);
    text += line + "\n";
  }
  return text + "N,R5.3,LOC,       -1,\nEBLOCK,19,SOLID\n(19i9)\n" + elements + "       -1\n" + extra + "FINISH\n";
}

// A solid EBLOCK record (19i9) of element `number`, MAT `mat`, TYPE `type`.
std::string solid(long long number, int mat, int type, const std::vector<long long>& nodes) {
  std::vector<long long> first{mat, type, 1, 1, 0, 0, 0, 0, static_cast<long long>(nodes.size()), 0, number};
  std::string text;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    if (k == 8) {
      text += ints(first, 9) + "\n";
      first.clear();
    }
    first.push_back(nodes[k]);
  }
  return text + ints(first, 9) + "\n";
}

// The tets of `mesh` as SOLID285 records (TYPE 1), MAT from `mats` or 1.
std::string tet_records(const TetMesh& mesh, const std::vector<int>& mats = {}) {
  std::string text;
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    std::vector<long long> nodes;
    for (int k = 0; k < 4; ++k) nodes.push_back(mesh.tets[4 * t + static_cast<std::size_t>(k)] + 1);
    text += solid(static_cast<long long>(t) + 1, mats.empty() ? 1 : mats[t], 1, nodes);
  }
  return text;
}

bool pinned(const TetMesh& mesh, std::size_t node) { return !mesh.fixed.empty() && mesh.fixed[node] != 0; }

TEST(AnsysFormat, NamesAndExtension) {
  EXPECT_EQ(parse_format("ansys"), MeshFormat::Ansys);
  EXPECT_EQ(parse_format("cdb"), MeshFormat::Ansys);
  EXPECT_EQ(format_from_path("model.cdb"), MeshFormat::Ansys);
  EXPECT_EQ(format_from_path("MODEL.CDB"), MeshFormat::Ansys);
  EXPECT_STREQ(format_name(MeshFormat::Ansys), "ansys");
}

TEST(AnsysFields, FormatLines) {
  const auto f = ansys::parse_block_format(" (3i9,6e21.13e3) \r");
  ASSERT_TRUE(f.has_value());
  EXPECT_EQ(f->ints, 3);
  EXPECT_EQ(f->int_width, 9);
  EXPECT_EQ(f->reals, 6);
  EXPECT_EQ(f->real_width, 21);
  EXPECT_EQ(f->decimals, 13);
  EXPECT_EQ(f->exponent_digits, 3);
  const auto old = ansys::parse_block_format("(3I8,6E20.13)");
  ASSERT_TRUE(old.has_value());
  EXPECT_EQ(old->exponent_digits, 2);
  EXPECT_EQ(old->real_width, 20);
  const auto workbench = ansys::parse_block_format("(1i9,3e20.9e3)");
  ASSERT_TRUE(workbench.has_value());
  EXPECT_EQ(workbench->ints, 1);
  EXPECT_EQ(workbench->reals, 3);
  const auto elements = ansys::parse_block_format("(19i9)");
  ASSERT_TRUE(elements.has_value());
  EXPECT_EQ(elements->ints, 19);
  EXPECT_EQ(elements->reals, 0);
  for (const char* bad : {"", "3i9,6e21.13", "(6e21.13)", "(3i9,6e21)", "(3i0)", "(i9", "(3i9,6e21.13,2i3)", "(3x9)",
                          "(3i9;6e21.13)", "(99999i9)"})
    EXPECT_FALSE(ansys::parse_block_format(bad).has_value()) << bad;
}

TEST(AnsysFields, RealsInFortranForms) {
  double v = 1;
  EXPECT_TRUE(ansys::real_field("   ", v));
  EXPECT_EQ(v, 0.0);
  EXPECT_TRUE(ansys::real_field(" 1.5D-03", v));
  EXPECT_EQ(v, 1.5e-3);
  EXPECT_TRUE(ansys::real_field("-5.0000000000000E-001", v));
  EXPECT_EQ(v, -0.5);
  EXPECT_TRUE(ansys::real_field("-.25", v));
  EXPECT_EQ(v, -0.25);
  for (const char* bad : {"1.5.2", "nan", "inf", "1,5", "x"}) EXPECT_FALSE(ansys::real_field(bad, v)) << bad;
  // Adjacent fields without a blank between them, as CDWRITE writes
  // negative values.
  const std::string record = " 0.0000000000000E+00-5.0000000000000E-01";
  EXPECT_TRUE(ansys::real_field(ansys::field_at(record, 20, 20), v));
  EXPECT_EQ(v, -0.5);
  EXPECT_TRUE(ansys::field_at(record, 40, 20).empty());
}

TEST(AnsysFields, RealsWrittenAsMapdlDoes) {
  const BlockFormat wide{3, 9, 6, 21, 13, 3, 0}, narrow{3, 8, 6, 20, 13, 2, 0};
  std::string out;
  ASSERT_TRUE(ansys::format_real(-0.5, wide, out));
  EXPECT_EQ(out, "-5.0000000000000E-001");
  out.clear();
  ASSERT_TRUE(ansys::format_real(-0.5, narrow, out));
  EXPECT_EQ(out, "-5.0000000000000E-01");
  out.clear();
  ASSERT_TRUE(ansys::format_real(1234.5678901234567, wide, out));
  EXPECT_EQ(out, " 1.2345678901235E+003");
  // A residue past the exponent's digits is 0; a value past them does not
  // fit.
  out.clear();
  ASSERT_TRUE(ansys::format_real(3e-120, narrow, out));
  EXPECT_EQ(out, " 0.0000000000000E+00");
  out.clear();
  EXPECT_FALSE(ansys::format_real(3e120, narrow, out));
  out.clear();
  ASSERT_TRUE(ansys::format_real(3e120, wide, out));
  EXPECT_EQ(out, " 3.0000000000000E+120");
}

TEST(AnsysElementTypes, ShapesFromNodes) {
  using ansys::Family;
  using ansys::Shape;
  EXPECT_EQ(ansys::type_number_of("SOLID187"), 187);
  EXPECT_EQ(ansys::type_number_of("185"), 185);
  EXPECT_EQ(ansys::type_number_of("solid285"), 285);
  EXPECT_EQ(ansys::type_number_of("MESH"), -1);
  EXPECT_EQ(ansys::family_of(187), Family::Tet);
  EXPECT_EQ(ansys::family_of(186), Family::Brick);
  EXPECT_EQ(ansys::family_of(181), Family::Other);
  const long long tet8[8] = {1, 2, 3, 3, 4, 4, 4, 4}, wedge[8] = {1, 2, 3, 3, 4, 5, 6, 6},
                  pyramid[8] = {1, 2, 3, 4, 5, 5, 5, 5}, hex[8] = {1, 2, 3, 4, 5, 6, 7, 8},
                  flat[8] = {1, 1, 3, 3, 4, 4, 4, 4};
  EXPECT_EQ(ansys::solid_shape(Family::Brick, tet8, 8).shape, Shape::Tet4);
  EXPECT_EQ(ansys::solid_shape(Family::Brick, wedge, 8).shape, Shape::Wedge);
  EXPECT_EQ(ansys::solid_shape(Family::Brick, pyramid, 8).shape, Shape::Pyramid);
  EXPECT_EQ(ansys::solid_shape(Family::Brick, hex, 8).shape, Shape::Hexahedron);
  EXPECT_EQ(ansys::solid_shape(Family::Brick, flat, 8).shape, Shape::Other);
  EXPECT_EQ(ansys::solid_shape(Family::Other, tet8, 8).shape, Shape::Other);
  // SOLID186's tet: the corners I, J, K, M and the edges Q, R, T, Y, Z, A.
  const long long tet20[20] = {1, 2, 3, 3, 4, 4, 4, 4, 11, 12, 3, 13, 4, 4, 4, 4, 14, 15, 16, 16};
  const ansys::SolidShape s = ansys::solid_shape(Family::Brick, tet20, 20);
  ASSERT_EQ(s.shape, Shape::Tet10);
  std::vector<long long> nodes;
  for (int k = 0; k < s.count; ++k) nodes.push_back(tet20[s.places[k]]);
  EXPECT_EQ(nodes, (std::vector<long long>{1, 2, 3, 4, 11, 12, 13, 14, 15, 16}));
  const long long tet10_linear[10] = {1, 2, 3, 4, 0, 0, 0, 0, 0, 0}, tet10_partial[10] = {1, 2, 3, 4, 5, 0, 0, 0, 0, 0};
  EXPECT_EQ(ansys::solid_shape(Family::Tet, tet10_linear, 10).shape, Shape::Tet4);
  EXPECT_EQ(ansys::solid_shape(Family::Tet, tet10_partial, 10).shape, Shape::Other);
  EXPECT_TRUE(ansys::changes_mesh("N"));
  EXPECT_TRUE(ansys::changes_mesh("NMOD"));
  EXPECT_TRUE(ansys::changes_mesh("CDREAD"));
  EXPECT_FALSE(ansys::changes_mesh("NBLOCK"));
  EXPECT_FALSE(ansys::changes_mesh("NSEL"));
}

TEST(AnsysRead, TetsRegionsAndNumbers) {
  const TetMesh cube = testing::cube_with_centre(0.4, 0.5, 0.6);
  std::vector<int> mats(12, 7);
  std::fill(mats.begin() + 6, mats.end(), 9);
  const TetMesh m = read_text(deck(cube, "ET,1,SOLID285\n", tet_records(cube, mats)));
  ASSERT_EQ(m.num_nodes(), 9u);
  ASSERT_EQ(m.num_tets(), 12u);
  EXPECT_EQ(m.tets, cube.tets);
  for (std::size_t i = 0; i < m.xyz.size(); ++i) EXPECT_DOUBLE_EQ(m.xyz[i], cube.xyz[i]) << i;
  EXPECT_EQ(m.extras.tet_tags, mats);
  EXPECT_EQ(m.extras.node_tags.front(), 1);
  EXPECT_EQ(m.extras.tet_element_tags.back(), 12);
  EXPECT_TRUE(m.fixed.empty());
  EXPECT_TRUE(m.extras.read_notes.empty());
}

TEST(AnsysRead, EveryFormOfTet) {
  const TetMesh cube = testing::cube_with_centre(0.4, 0.5, 0.6);
  // SOLID185's degenerate tet, and SOLID187 with the midside nodes left out
  // (as the TetBeam example of mapdl-archive lists them).
  std::string bricks, tens;
  for (std::size_t t = 0; t < cube.num_tets(); ++t) {
    const auto n = [&](int k) { return static_cast<long long>(cube.tets[4 * t + static_cast<std::size_t>(k)]) + 1; };
    bricks += solid(static_cast<long long>(t) + 1, 1, 3, {n(0), n(1), n(2), n(2), n(3), n(3), n(3), n(3)});
    tens += solid(static_cast<long long>(t) + 1, 1, 2, {n(0), n(1), n(2), n(3), 0, 0, 0, 0, 0, 0});
  }
  EXPECT_EQ(read_text(deck(cube, "ET,3,185\n", bricks)).tets, cube.tets);
  EXPECT_EQ(read_text(deck(cube, "ET,2,187\n", tens)).tets, cube.tets);
  // 10-node tets: SOLID187's order, and SOLID186's degenerate tet.
  const TetMesh ten = testing::with_midsides(cube);
  std::string s187, s186;
  for (std::size_t t = 0; t < ten.num_tets(); ++t) {
    std::vector<long long> n;
    for (int k = 0; k < 4; ++k) n.push_back(ten.tets[4 * t + static_cast<std::size_t>(k)] + 1);
    for (int k = 0; k < 6; ++k) n.push_back(ten.midsides[6 * t + static_cast<std::size_t>(k)] + 1);
    s187 += solid(static_cast<long long>(t) + 1, 1, 1, n);
    // I J K K M M M M, Q(IJ) R(JK) K T(KI) M M M M, Y(IM) Z(JM) A(KM) A.
    s186 += solid(static_cast<long long>(t) + 1, 1, 1, {n[0], n[1], n[2], n[2], n[3], n[3], n[3], n[3], n[4], n[5],
                                                        n[2], n[6], n[3], n[3], n[3], n[3], n[7], n[8], n[9], n[9]});
  }
  for (const auto& [types, records] : {std::pair{"ET,1,187\n", s187}, std::pair{"ET,1,SOLID186\n", s186}}) {
    const TetMesh m = read_text(deck(ten, types, records));
    EXPECT_EQ(m.tets, ten.tets) << types;
    EXPECT_EQ(m.midsides, ten.midsides) << types;
  }
}

TEST(AnsysRead, OtherSolidsPassThroughAndOtherElementsPin) {
  TetMesh cube = testing::cube_with_centre(0.4, 0.5, 0.6);
  // Extra nodes 10-15 off the cube for a brick, a wedge and a pyramid, and
  // a shell on the cube's face 1-2-4-3 (ANSYS numbers), and a SURF154 on
  // nodes 5, 6, 8 (a non-solid EBLOCK).
  for (int k = 0; k < 6; ++k) cube.xyz.insert(cube.xyz.end(), {2.0 + k, 0.0, 0.0});
  const std::string records = tet_records(cube) + solid(13, 4, 2, {10, 11, 12, 13, 14, 15, 1, 2}) +
                              solid(14, 4, 2, {10, 11, 12, 12, 13, 14, 15, 15}) +
                              solid(15, 4, 2, {10, 11, 12, 13, 14, 14, 14, 14}) + solid(16, 1, 5, {1, 2, 4, 3});
  const std::string surface =
      "ET,6,154\nEBLOCK,10,,,1\n(15i9)\n" + ints({17, 6, 6, 6, 12, 5, 6, 8, 8}, 9) + "\n       -1\n";
  const TetMesh m = read_text(deck(cube, "ET,1,285\nET,2,185\nET,5,SHELL181\n", records, surface));
  ASSERT_EQ(m.num_tets(), 12u);
  ASSERT_EQ(m.extras.blocks.size(), 3u);
  EXPECT_EQ(m.extras.blocks[0].kind, "hexahedron");
  EXPECT_EQ(m.extras.blocks[0].connectivity, (std::vector<std::int32_t>{9, 10, 11, 12, 13, 14, 0, 1}));
  EXPECT_EQ(m.extras.blocks[1].kind, "wedge");
  EXPECT_EQ(m.extras.blocks[1].connectivity, (std::vector<std::int32_t>{9, 10, 11, 12, 13, 14}));
  EXPECT_EQ(m.extras.blocks[2].kind, "pyramid");
  EXPECT_EQ(m.extras.blocks[2].tags, std::vector<int>{4});
  EXPECT_EQ(m.extras.blocks[0].element_tags, std::vector<long long>{13});
  for (std::size_t node : {0u, 1u, 2u, 3u, 4u, 5u, 7u, 9u, 14u}) EXPECT_TRUE(pinned(m, node)) << node;
  EXPECT_FALSE(pinned(m, 6));
  EXPECT_FALSE(pinned(m, 8));
  const std::string* uncarried = raw_section(m.extras, "ansys:uncarried");
  ASSERT_NE(uncarried, nullptr);
  EXPECT_EQ(*uncarried, "SHELL181, 154");
  // Components that divide a material number the pass-through solids' regions
  // with the tets', and name them.
  const std::string named =
      "CMBLOCK,LEFT,ELEM,2\n(8i10)\n         1        -6\n"
      "CMBLOCK,BLOCK,ELEM,2\n(8i10)\n        13       -15\n";
  const TetMesh split = read_text(deck(cube, "ET,1,285\nET,2,185\nET,5,SHELL181\n", records, surface + named));
  EXPECT_EQ(split.extras.tet_tags, (std::vector<int>{1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2}));
  for (const PassThroughBlock& b : split.extras.blocks) EXPECT_EQ(b.tags, std::vector<int>{3}) << b.kind;
  EXPECT_EQ(physical_names_of(*raw_section(split.extras, "$PhysicalNames"), 3),
            (std::map<int, std::string>{{1, "LEFT"}, {3, "BLOCK"}}));
}

TEST(AnsysRead, ComponentsAndLoadsPin) {
  const TetMesh grid = testing::cube_grid(3, 0.1);
  // Interior nodes of a 4x4x4 grid (numbers from 1): 22, 23, 26, 27, 38,
  // 39, 42, 43.
  const std::string extra =
      "CMBLOCK,SUPPORT,NODE,        2\n(8i10)\n        22       -23\n"
      "D,26,UX,0.0 ! a support\nF,       38,FY, 1.0\nCP,1,UX,39,-42\nCE,1,0.0,43,UX,1.0\nD,ALL,UZ,0\n";
  const TetMesh m = read_text(deck(grid, "ET,1,285\n", tet_records(grid), extra));
  for (std::size_t node : {21u, 22u, 25u, 37u, 38u, 42u}) EXPECT_TRUE(pinned(m, node)) << node;
  EXPECT_FALSE(pinned(m, 26));  // in no command
  EXPECT_FALSE(pinned(m, 41));  // removed from the CP set (-42)
  ASSERT_EQ(m.extras.read_notes.size(), 1u);
  EXPECT_NE(m.extras.read_notes[0].find("the file's D commands name nodes through APDL's selection"), std::string::npos)
      << m.extras.read_notes[0];
}

TEST(AnsysRead, LoadRangesAndRecentReleasesForms) {
  const TetMesh grid = testing::cube_grid(3, 0.1);
  // D from node 22 to 42 in steps of 4: 22, 26, 30 (boundary), 34, 38, 42;
  // M from 23 to 27 in steps of 4: 23, 27.
  const TetMesh m = read_text(deck(grid, "ET,1,285\n", tet_records(grid), "D,22,UX,0,,42,4\nM,23,UX,27,4\n"));
  for (std::size_t node : {21u, 22u, 25u, 26u, 37u, 41u}) EXPECT_TRUE(pinned(m, node)) << node;
  EXPECT_FALSE(pinned(m, 38));
  EXPECT_FALSE(pinned(m, 42));
  // An NBLOCK closed by "N,UNBL,LOC,-1" and the types in an ETBLOCK.
  const std::string etblock = "ETBLOCK,        1,        1\n(2i9,19a9)\n" + ints({1, 285, 0, 0}, 9) + "\n       -1\n";
  const std::string recent =
      replaced(deck(grid, etblock, tet_records(grid)), "N,R5.3,LOC,       -1,", "N,UNBL,LOC,       -1,");
  EXPECT_EQ(read_text(recent).tets, grid.tets);
  EXPECT_NE(read_error(replaced(recent, "(2i9,19a9)", "(1i9,19a9)")).find("t.cdb:3: ETBLOCK's format must start"),
            std::string::npos);
}

TEST(AnsysRead, ParametersAndConstraintsWorkbenchWrites) {
  const TetMesh grid = testing::cube_grid(3, 0.1);
  // Workbench names its element types by parameter; loads may give a node
  // as a whole real; CERIG names a master and a slave; a component that no
  // CMBLOCK defines (made by selection) is noted.
  const std::string types = "*SET,tid,1\ncid = 1\nET,tid,285\nET,cid,285\n";
  const TetMesh m = read_text(deck(grid, types, tet_records(grid), "D,22.0,UX,0\nCERIG,23,26,ALL\nD,FIXED,ALL\n"));
  for (std::size_t node : {21u, 22u, 25u}) EXPECT_TRUE(pinned(m, node)) << node;
  EXPECT_FALSE(pinned(m, 26));
  ASSERT_EQ(m.extras.read_notes.size(), 1u);
  EXPECT_NE(m.extras.read_notes[0].find("no node CMBLOCK defines (D FIXED)"), std::string::npos)
      << m.extras.read_notes[0];
  // CDWRITE's constraint equations name their nodes on NODE lines.
  const TetMesh equations = read_text(deck(
      grid, types, tet_records(grid), "CE,R5.0,DEFI,       2,       1,  0.0\nCE,R5.0,NODE,27,UX,1.0,38,UX,-1.0\n"));
  EXPECT_TRUE(pinned(equations, 26));
  EXPECT_TRUE(pinned(equations, 37));
  EXPECT_TRUE(equations.extras.read_notes.empty());
  // A parameter that *DO or *GET sets is no longer one tetsmooth knows.
  const TetMesh looped =
      read_text(deck(grid, types, tet_records(grid), "*SET,I,22\n*DO,I,22,26,4\nD,I,UX,0\n*ENDDO\n"));
  EXPECT_FALSE(pinned(looped, 21));
  ASSERT_EQ(looped.extras.read_notes.size(), 1u);
  EXPECT_NE(looped.extras.read_notes[0].find("(D I)"), std::string::npos) << looped.extras.read_notes[0];
  // A parameter set again to a word no longer names a number.
  EXPECT_NE(read_error(deck(grid, types + "*SET,tid,'x'\nET,tid,285\n", tet_records(grid)))
                .find("ET needs a positive element type number, not 'tid'"),
            std::string::npos);
}

TEST(AnsysRead, ElementComponentsSplitAndNameRegions) {
  const TetMesh cube = testing::cube_with_centre(0.4, 0.5, 0.6);
  // Tets 1-12 all MAT 1; the component ROCK holds 1-6, and FILL holds 7-12.
  const std::string named =
      "CMBLOCK,ROCK,ELEM,2\n(8i10)\n         1        -6\n"
      "CMBLOCK,FILL,ELEM,2\n(8i10)\n         7       -12\n";
  const TetMesh m = read_text(deck(cube, "ET,1,285\n", tet_records(cube), named));
  EXPECT_EQ(m.extras.tet_tags, (std::vector<int>{1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2}));
  ASSERT_EQ(m.extras.read_notes.size(), 1u);
  EXPECT_NE(m.extras.read_notes[0].find("element components divide materials"), std::string::npos);
  const std::string* names = raw_section(m.extras, "$PhysicalNames");
  ASSERT_NE(names, nullptr);
  EXPECT_EQ(physical_names_of(*names, 3), (std::map<int, std::string>{{1, "ROCK"}, {2, "FILL"}}));
  // A component that matches a material names it and keeps the MATs.
  std::vector<int> mats(12, 5);
  std::fill(mats.begin() + 6, mats.end(), 8);
  const TetMesh by_mat = read_text(deck(cube, "ET,1,285\n", tet_records(cube, mats), named));
  EXPECT_EQ(by_mat.extras.tet_tags, mats);
  EXPECT_TRUE(by_mat.extras.read_notes.empty());
  EXPECT_EQ(physical_names_of(*raw_section(by_mat.extras, "$PhysicalNames"), 3),
            (std::map<int, std::string>{{5, "ROCK"}, {8, "FILL"}}));
}

TEST(AnsysWrite, KeptFileChangesOnlyMovedRecords) {
  const TetMesh cube = testing::cube_with_centre(0.4, 0.5, 0.6);
  // The centre's record carries rotation angles, which stay as read; CRLF
  // line ends stay too.
  std::string text = deck(cube, "ET,1,285 ! tets\n", tet_records(cube), "D,1,ALL,0\n");
  // Its Z, in Fortran's D form, stays as written when only Y moves.
  text = replaced(text, " 6.0000000000000E-001\n", " 6.0000000000000D-001 4.5000000000000E+001\n");
  std::string crlf;
  for (char c : text) crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  TetMesh m = read_text(crlf);
  EXPECT_EQ(write_text(m), crlf);
  m.xyz[3 * 8 + 1] = 0.55;
  const std::string moved = replaced(crlf, " 5.0000000000000E-001 6.0000000000000D-001 4.5000000000000E+001\r\n",
                                     " 5.5000000000000E-001 6.0000000000000D-001 4.5000000000000E+001\r\n");
  EXPECT_EQ(write_text(m), moved);
  // The record written reads back as the new value, within its 14 digits.
  m.xyz[3 * 8] = 0.123456789012345678;
  const TetMesh back = read_text(write_text(m));
  EXPECT_NEAR(back.xyz[3 * 8], 0.123456789012345678, 1e-14);
  EXPECT_EQ(back.xyz[3 * 8 + 1], 0.55);
  // A mesh that is no longer the file's is not written as it.
  TetMesh other = m;
  other.tets.resize(4 * 11);
  EXPECT_THROW(write_text(other), OutputError);
}

TEST(AnsysWrite, NewFilesReadBack) {
  TetMesh grid = testing::cube_grid(3, 0.1);
  grid.extras.tet_tags.assign(grid.num_tets(), 3);
  std::fill(grid.extras.tet_tags.begin(), grid.extras.tet_tags.begin() + 10, -2);
  grid.extras.raw_sections.emplace_back("$PhysicalNames", "2\n3 3 \"soil layer\"\n2 11 \"base\"\n");
  PassThroughBlock base;
  base.kind = "triangle";
  base.nodes_per_element = 3;
  base.connectivity = {0, 1, 4};
  base.tags = {11};
  grid.extras.blocks.push_back(base);
  grid.fixed.assign(grid.num_nodes(), 0);
  grid.fixed[0] = grid.fixed[1] = grid.fixed[4] = grid.fixed[21] = 1;
  const std::string text = write_text(grid);
  EXPECT_NE(text.find("ET,1,285\n"), std::string::npos);
  EXPECT_NE(text.find("CMBLOCK,SOIL_LAYER,ELEM,"), std::string::npos) << text;
  EXPECT_NE(text.find("CMBLOCK,BASE,NODE,"), std::string::npos);
  const TetMesh back = read_text(text);
  EXPECT_EQ(back.tets, grid.tets);
  for (std::size_t i = 0; i < grid.xyz.size(); ++i) EXPECT_NEAR(back.xyz[i], grid.xyz[i], 1e-13) << i;
  // -2 has no material number: the next free one after 3.
  EXPECT_EQ(back.extras.tet_tags[0], 4);
  EXPECT_EQ(back.extras.tet_tags[20], 3);
  EXPECT_EQ(ansys_new_materials(grid), (std::map<int, int>{{-2, 4}}));
  for (std::size_t node : {0u, 1u, 4u, 21u}) EXPECT_TRUE(pinned(back, node)) << node;
  EXPECT_FALSE(pinned(back, 22));
  EXPECT_EQ(physical_names_of(*raw_section(back.extras, "$PhysicalNames"), 3),
            (std::map<int, std::string>{{3, "SOIL_LAYER"}}));
  // Second order: SOLID187 with its midside nodes.
  const TetMesh ten = testing::with_midsides(testing::cube_with_centre());
  const TetMesh ten_back = read_text(write_text(ten));
  EXPECT_NE(write_text(ten).find("ET,1,187\n"), std::string::npos);
  EXPECT_EQ(ten_back.midsides, ten.midsides);
  // What the new file drops is said before the work.
  const std::vector<std::string> losses = output_losses(grid, "out.cdb", MeshFormat::Auto);
  const auto said = [&](const std::string& part) {
    return std::any_of(losses.begin(), losses.end(),
                       [&](const std::string& s) { return s.find(part) != std::string::npos; });
  };
  EXPECT_TRUE(said("1 triangle will not be written")) << ::testing::PrintToString(losses);
  EXPECT_TRUE(said("-2 as 4")) << ::testing::PrintToString(losses);
}

TEST(AnsysRead, ErrorsNameFileAndLine) {
  const TetMesh cube = testing::cube_with_centre(0.4, 0.5, 0.6);
  const std::string good = deck(cube, "ET,1,285\n", tet_records(cube));
  const std::string node9 = ints({9, 0, 0}, 9);  // line 13 holds node 9
  struct Case {
    std::string text, expected;
  };
  const std::vector<Case> cases = {
      {replaced(good, "FINISH\n", "N,20,1,2,3\nFINISH\n"), "t.cdb:30: the N command makes, moves or deletes"},
      {replaced(good, "FINISH\n", "nmodif,3,1,1,1\nFINISH\n"), "t.cdb:30: the NMODIF command"},
      {replaced(good, "FINISH\n", "/INPUT,more,cdb\nFINISH\n"), "t.cdb:30: the /INPUT command reads another file"},
      {replaced(good, node9 + " 4.0", node9 + " 4x0"), "t.cdb:13: expected a real number in field 4 of node 9"},
      {replaced(good, node9, ints({8, 0, 0}, 9)), "t.cdb:13: node 8 is defined a second time"},
      {replaced(good, "ET,1,285\n", "ET,2,285\n"), "t.cdb:17: element 1 is of type 1, which no ET command defines"},
      {replaced(good, ints({9, 1, 3, 4}, 9), ints({19, 1, 3, 4}, 9)),
       "t.cdb:17: element 1 lists node 19, which no NBLOCK defines"},
      {good.substr(0, good.find("N,R5.3")), "t.cdb:13: the file ends inside an NBLOCK"},
      {replaced(good, "(19i9)", "(19i9,2e9.2)"), "t.cdb:16: EBLOCK's format must hold integers alone"},
      {replaced(good, "(3i9,6e21.13e3)", "(3i9,2e21.13e3)"), "t.cdb:4: NBLOCK's format gives 2 real fields"},
      {replaced(good, "FINISH\n", "CMBLOCK,TOP,NODE,3\n(8i10)\n         1         2\nFINISH\n"),
       "t.cdb:32: CMBLOCK 'TOP' holds 2 items on its lines, and its count says 3"},
      {replaced(good, "FINISH\n", "CMBLOCK,TOP,NODE,1\n(8i10)\n        44\n"),
       "t.cdb:30: component 'TOP' lists node 44"},
      {replaced(good, "FINISH\n", "D,77,UX,0\n"), "t.cdb:30: node 77 is named here, and no NBLOCK defines it"},
      {replaced(good, "ET,1,285\n", "ET,1,285\nET,1,187\n"), "t.cdb:3: element type 1 is defined again"},
      {replaced(good, "       -1\n", "       -1\n" + ints({1, 1, 1, 1, 0, 0, 0, 0, 4, 0, 13, 1, 2, 3, 4}, 9) + "\n"),
       "t.cdb:30: a record after the end of the block above (line 29)"},
      {replaced(good, "       -1\n",
                "       -1\n/COM\n" + ints({1, 1, 1, 1, 0, 0, 0, 0, 4, 0, 13, 1, 2, 3, 4}, 9) + "\n"),
       "t.cdb:31: a line of element fields outside an EBLOCK"},
      {replaced(good, "FINISH\n", "CMBLOCK,C,NODE,2\n(8i10)\n         1         2\n         3\n"),
       "t.cdb:33: a record after the end of the block above (line 32)"},
      {replaced(good, "FINISH\n", "CMBLOCK,C,NODE,1\n(8i10)\n         1         2\n"),
       "t.cdb:32: CMBLOCK 'C' lists more items than its count, 1"},
      {replaced(good, "FINISH\n", "numof,node,100\nFINISH\n"), "t.cdb:30: NUMOFF after an NBLOCK"},
      {replaced(good, "FINISH\n", "EN,R5.5,NODE,1,2,3,4\nFINISH\n"), "t.cdb:30: the EN command makes"},
      {replaced(good, "FINISH\n", "MPCHG,2,ALL\nFINISH\n"), "t.cdb:30: the MPCHG command"},
      {replaced(good, "FINISH\n", "NUMOFF,NODE,100\nFINISH\n"), "t.cdb:30: NUMOFF after an NBLOCK"},
      {replaced(good, "FINISH\n", "CMBLOCK,C,NODE,2\n(8i20)\n" + ints({1, LLONG_MIN}, 20) + "\n"),
       "t.cdb:32: CMBLOCK 'C' lists -9223372036854775808"},
      // A record cut off inside its header, as where the file was copied in part.
      {good.substr(0, good.find(ints({1, 1, 1, 1, 0}, 9)) + 45) + "\n",
       "t.cdb:17: an EBLOCK record of 5 fields, short of the 11 of its header (is the file cut short?)"},
  };
  for (const Case& c : cases) {
    EXPECT_NE(read_error(c.text).find(c.expected), std::string::npos) << read_error(c.text);
  }
  // 4-node tets after 10-node ones.
  std::string mixed = tet_records(cube);
  mixed = replaced(
      mixed, ints({1, 1, 1, 1, 0, 0, 0, 0, 4, 0, 1}, 9) + ints({9, 1, 3, 4}, 9) + "\n",
      ints({1, 1, 1, 1, 0, 0, 0, 0, 10, 0, 1}, 9) + ints({9, 1, 3, 4, 2, 5, 6, 7}, 9) + "\n" + ints({8, 10}, 9) + "\n");
  TetMesh big = cube;
  big.xyz.insert(big.xyz.end(), {0.1, 0.1, 0.1});
  EXPECT_NE(read_error(deck(big, "ET,1,187\n", mixed)).find("a 4-node tet after 10-node ones"), std::string::npos);
  EXPECT_NE(read_error("/PREP7\nET,1,285\nFINISH\n").find("no NBLOCK with nodes"), std::string::npos);
}

}  // namespace
}  // namespace tetsmooth
