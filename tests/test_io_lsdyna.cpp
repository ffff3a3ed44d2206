// LS-DYNA keyword decks (.k): keyword lines and card fields, tets in every
// form the decks write them, other elements passing through or pinning,
// pins from constraints, sets and loads, the deck written back with only
// moved nodes' cards changed, new decks that read back as written, included
// files, and errors naming file:line.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/errors.hpp"
#include "mesh/io/lsdyna_cards.hpp"
#include "mesh/io/lsdyna_io.hpp"
#include "mesh/io/mesh_io.hpp"
#include "mesh/io/nastran_io.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/io/writable_check.hpp"
#include "mesh/tet_quality.hpp"
#include "support/input_error.hpp"
#include "support/scratch_dir.hpp"
#include "support/test_meshes.hpp"

namespace tetsmooth {
namespace {

TetMesh read_text(const std::string& text) {
  std::istringstream in(text);
  return read_lsdyna(in, "t.k");
}

std::string write_text(const TetMesh& mesh) {
  std::ostringstream out;
  write_lsdyna(mesh, out);
  return out.str();
}

std::string read_error(const std::string& text) {
  return testing::input_error_message([&] { read_text(text); }, "read_lsdyna:\n" + text);
}

// Whole numbers right-aligned in fields of `width`.
std::string ints(const std::vector<long long>& values, int width = 8) {
  std::string line;
  for (long long v : values) {
    const std::string t = std::to_string(v);
    line += std::string(static_cast<std::size_t>(width) - t.size(), ' ') + t;
  }
  return line + "\n";
}

std::string node(long long id, const char* x, const char* y, const char* z, const char* rest = "") {
  const auto field = [](const char* v) { return std::string(16 - std::string(v).size(), ' ') + v; };
  const std::string t = std::to_string(id);
  return std::string(8 - t.size(), ' ') + t + field(x) + field(y) + field(z) + rest + "\n";
}

// A *NODE card in the long layout: every field 20 columns wide, on one line.
std::string long_node(long long id, const char* x, const char* y, const char* z, const char* rest = "") {
  const auto field = [](const char* v) { return std::string(20 - std::string(v).size(), ' ') + v; };
  return ints({id}, 20).substr(0, 20) + field(x) + field(y) + field(z) + rest + "\n";
}

// Four tets around node 5, in parts 1 and 2; node 5 is the only one inside.
const std::string kNodes = "*NODE\n$#   nid               x               y               z      tc      rc\n" +
                           node(1, "0.0", "0.0", "0.0") + node(2, "1.0", "0.0", "0.0") +
                           node(3, "0.0", "1.0", "0.0") + node(4, "0.0", "0.0", "1.0") +
                           node(5, "0.3", "0.2", "0.1");
const std::string kSolids = "*ELEMENT_SOLID\n" + ints({11, 1, 5, 2, 3, 4, 4, 4, 4, 4}) +
                            ints({12, 1, 1, 5, 3, 4, 4, 4, 4, 4}) + ints({13, 2, 1, 2, 5, 4, 4, 4, 4, 4}) +
                            ints({14, 2, 1, 2, 3, 5, 5, 5, 5, 5});
const std::string kStar = "*KEYWORD\n*TITLE\nstar\n" + kNodes + kSolids + "*END\n";

std::string with(const std::string& cards) { return "*KEYWORD\n" + kNodes + kSolids + cards + "*END\n"; }

bool node5_pinned(const std::string& cards) {
  const TetMesh mesh = read_text(with(cards));
  return !mesh.fixed.empty() && mesh.fixed[4] == 1;
}

// The same four tets in the long layout, which "*KEYWORD LONG=Y" asks for.
const std::string kLongNodes =
    "*NODE\n$#               nid                   x                   y                   z                  tc"
    "                  rc\n" +
    long_node(1, "0.0", "0.0", "0.0") + long_node(2, "1.0", "0.0", "0.0") + long_node(3, "0.0", "1.0", "0.0") +
    long_node(4, "0.0", "0.0", "1.0") + long_node(5, "0.3", "0.2", "0.1");
const std::string kLongSolids = "*ELEMENT_SOLID\n" + ints({11, 1, 5, 2, 3, 4, 4, 4, 4, 4}, 20) +
                                ints({12, 1, 1, 5, 3, 4, 4, 4, 4, 4}, 20) + ints({13, 2, 1, 2, 5, 4, 4, 4, 4, 4}, 20) +
                                ints({14, 2, 1, 2, 3, 5, 5, 5, 5, 5}, 20);

std::string with_long(const std::string& cards) {
  return "*KEYWORD LONG=Y\n" + kLongNodes + kLongSolids + cards + "*END\n";
}

bool long_node5_pinned(const std::string& cards) {
  const TetMesh mesh = read_text(with_long(cards));
  return !mesh.fixed.empty() && mesh.fixed[4] == 1;
}

TEST(LsdynaFormat, NamesAndExtensions) {
  EXPECT_EQ(parse_format("lsdyna"), MeshFormat::Lsdyna);
  EXPECT_EQ(parse_format("k"), MeshFormat::Lsdyna);
  for (const char* path : {"car.k", "car.key", "CAR.DYN"}) EXPECT_EQ(format_from_path(path), MeshFormat::Lsdyna);
  EXPECT_STREQ(format_name(MeshFormat::Lsdyna), "lsdyna");
}

TEST(LsdynaCards, KeywordsAndFields) {
  using namespace lsdyna;
  const Keyword plain = keyword_of("*node");
  EXPECT_EQ(plain.name, "NODE");
  EXPECT_FALSE(plain.marked);
  const Keyword i10 = keyword_of("*NODE %");
  EXPECT_EQ(i10.name, "NODE");
  EXPECT_EQ(i10.layout, Layout::I10);
  EXPECT_EQ(keyword_of("*ELEMENT_SOLID+").layout, Layout::Long);
  EXPECT_EQ(keyword_of("*KEYWORD 100m I10=Y").rest, "100m I10=Y");
  const Card fixed = card_of("       7             1.5          -2.5e3", node_widths(Layout::Standard));
  ASSERT_EQ(fixed.fields.size(), 3u);
  EXPECT_EQ(fixed[0], "7");
  EXPECT_EQ(fixed[2], "-2.5e3");
  EXPECT_EQ(fixed[3], "");
  EXPECT_FALSE(fixed.free);
  const Card free = card_of("7, 1.5 ,,3", node_widths(Layout::Standard));
  EXPECT_TRUE(free.free);
  EXPECT_EQ(free[1], "1.5");
  EXPECT_EQ(free[2], "");
  EXPECT_EQ(free[3], "3");
  long long v = -1;
  for (const char* whole : {"  3", "3.", "3.0", "+3"}) {
    EXPECT_TRUE(int_field(whole, v)) << whole;
    EXPECT_EQ(v, 3);
  }
  EXPECT_TRUE(int_field("", v));
  EXPECT_EQ(v, 0);
  for (const char* bad : {"3.5", "x", "&nid", "1e40"}) EXPECT_FALSE(int_field(bad, v)) << bad;
  double r = -1;
  EXPECT_TRUE(real_field(" 1.5D-3", r));
  EXPECT_DOUBLE_EQ(r, 1.5e-3);
  EXPECT_TRUE(real_field("", r));
  EXPECT_EQ(r, 0.0);
  EXPECT_FALSE(real_field("&x", r));
  EXPECT_FALSE(real_field("nan", r));
  // A coordinate fills 16 columns after a blank, exactly where it fits,
  // with a digit before its point and a sign before its exponent's digits
  // (readers written in C read ".5" as garbage and "1.5E2" as 1.5).
  for (const double value : {0.1, -9.5456041617964971, 1e-300, -1.7976931348623157e308, 123456789.0, 1.5e20,
                             -0.123456789012345, 100.00000000000001, 4.9e-324}) {
    const std::string f = coordinate_field(value);
    ASSERT_EQ(f.size(), 16u) << value;
    EXPECT_EQ(f[0], ' ') << value;
    const std::string_view text = trimmed(f);
    EXPECT_TRUE(std::isdigit(static_cast<unsigned char>(text[text[0] == '-' ? 1 : 0]))) << f;
    if (const std::size_t e = text.find('E'); e != std::string_view::npos) {
      EXPECT_TRUE(text[e + 1] == '+' || text[e + 1] == '-') << f;
    }
    double back = 0;
    ASSERT_TRUE(real_field(f, back)) << f;
    // 12 significant digits or more for sizes from 0.1 to 1e12 (lsdyna_cards.hpp).
    const double digits = std::abs(value) >= 0.1 && std::abs(value) < 1e12 ? 5e-12 : 5e-8;
    EXPECT_LE(std::abs(back - value), digits * std::abs(value)) << f;
  }
  EXPECT_EQ(coordinate_field(0.25), "            0.25");
  EXPECT_EQ(coordinate_field(1.5e20), "         1.5E+20");
  EXPECT_EQ(coordinate_field(-2.5e-7), "         -2.5E-7");
  EXPECT_EQ(coordinate_field(100.00000000000001), "            100.");
  EXPECT_EQ(coordinate_field(-1.0 / 3.0), " -0.333333333333");
  EXPECT_EQ(free_coordinate(0.1), "0.1");
  EXPECT_EQ(free_coordinate(-1.0 / 3.0), "-0.333333333333");
  // In the long layout's 20 columns a double's shortest exact form fits but
  // for some with three-digit exponents, which keep 12 significant digits.
  EXPECT_EQ(node_widths(Layout::Long), (std::vector<int>(6, 20)));
  EXPECT_EQ(element_widths(Layout::Long), (std::vector<int>(10, 20)));
  EXPECT_EQ(wide_widths(Layout::Long), (std::vector<int>(8, 20)));
  EXPECT_EQ(wide_widths(Layout::I10), (std::vector<int>(8, 10)));
  EXPECT_EQ(coordinate_field(-1.0 / 3.0, 20), " -0.3333333333333333");
  EXPECT_EQ(coordinate_field(1.5e20, 20), "             1.5E+20");
  EXPECT_EQ(free_coordinate(-1.0 / 3.0, 20), "-0.3333333333333333");
  for (const double value : {0.1, -9.5456041617964971, 1e-300, 123456789.0, -0.123456789012345, 100.00000000000001,
                             4.9e-324, -1.7976931348623157e308}) {
    const std::string f = coordinate_field(value, 20);
    ASSERT_EQ(f.size(), 20u) << value;
    EXPECT_EQ(f[0], ' ') << value;
    double back = 0;
    ASSERT_TRUE(real_field(f, back)) << f;
    if (std::abs(value) < 1e300) {
      EXPECT_EQ(back, value) << f;
    } else {
      EXPECT_LE(std::abs(back - value), 5e-12 * std::abs(value)) << f;
    }
  }
  EXPECT_EQ(std::string(layout_mark(Layout::Long)) + layout_mark(Layout::I10) + layout_mark(Layout::Standard), "+%-");
  EXPECT_STREQ(layout_name(Layout::Long), "long");
}

TEST(LsdynaRead, NodesTetsPartsAndIds) {
  const TetMesh mesh = read_text(kStar);
  EXPECT_EQ(mesh.num_nodes(), 5u);
  EXPECT_EQ(mesh.num_tets(), 4u);
  EXPECT_EQ(mesh.extras.node_tags, (std::vector<long long>{1, 2, 3, 4, 5}));
  EXPECT_EQ(mesh.extras.tet_element_tags, (std::vector<long long>{11, 12, 13, 14}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{1, 1, 2, 2}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{4, 1, 2, 3, 0, 4, 2, 3, 0, 1, 4, 3, 0, 1, 2, 4}));
  EXPECT_TRUE(mesh.fixed.empty());
  EXPECT_DOUBLE_EQ(mesh.xyz[12], 0.3);
  EXPECT_TRUE(mesh.extras.read_notes.empty());
}

// A deck that opens with *KEYWORD and lacks *END reads as it is, with a
// note: a deck cut short on a card's end looks just so. An included file
// needs no *END of its own.
TEST(LsdynaRead, ADeckWithoutEndIsNoted) {
  const std::string cut = kStar.substr(0, kStar.find("*END"));
  const TetMesh mesh = read_text(cut);
  EXPECT_EQ(mesh.num_tets(), 4u);
  EXPECT_EQ(mesh.extras.read_notes,
            std::vector<std::string>{"the deck has *KEYWORD but ends without *END, as a deck cut short would: check "
                                     "that its last cards are all there"});
  EXPECT_TRUE(read_text(cut.substr(cut.find("*TITLE"))).extras.read_notes.empty());
}

TEST(LsdynaRead, EveryFormOfTet) {
  const std::vector<std::string> forms = {
      ints({1, 7, 1, 2, 3, 4, 4, 4, 4, 4}),  // LS-DYNA's
      ints({1, 7, 1, 2, 3, 3, 4, 4, 4, 4}),  // a brick's corners collapsed
      ints({1, 7, 1, 2, 3, 4, 0, 0, 0, 0}),
      ints({1, 7, 1, 2, 3, 4}),               // N5..N8 blank
      ints({1, 7}) + ints({1, 2, 3, 4}),      // two cards
      "1,7,1,2,3,4,4,4,4,4\n",                // free format
  };
  const std::string nodes = "*NODE\n" + node(1, "0", "0", "0") + node(2, "1", "0", "0") + node(3, "0", "1", "0") +
                            node(4, "0", "0", "1");
  for (const std::string& form : forms) {
    const TetMesh mesh = read_text(nodes + "*ELEMENT_SOLID\n" + form);
    ASSERT_EQ(mesh.num_tets(), 1u) << form;
    EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3})) << form;
    EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{7})) << form;
  }
  // The I10 layout, asked by the keyword or by *KEYWORD.
  const auto node10 = [](long long id, const char* x, const char* y, const char* z) {
    return ints({id}, 10).substr(0, 10) + node(0, x, y, z).substr(8);
  };
  const std::string i10_nodes = node10(1, "0", "0", "0") + node10(2, "1", "0", "0") + node10(3, "0", "1", "0") +
                                node10(4, "0", "0", "1");
  const TetMesh i10 =
      read_text("*NODE %\n" + i10_nodes + "*ELEMENT_SOLID %\n" + ints({1, 1234567890, 1, 2, 3, 4, 4, 4, 4, 4}, 10));
  EXPECT_EQ(i10.extras.tet_tags, (std::vector<int>{1234567890}));
  EXPECT_EQ(i10.tets, (std::vector<index_t>{0, 1, 2, 3}));
  EXPECT_EQ(read_text("*KEYWORD I10=Y\n*NODE\n" + i10_nodes + "*ELEMENT_SOLID\n" +
                      ints({1, 3, 1, 2, 3, 4, 4, 4, 4, 4}, 10))
                .num_tets(),
            1u);
  // 10-node tets: the midside nodes in kTetEdges order on the second card.
  const TetMesh ten = read_text(nodes + node(5, ".5", "0", "0") + node(6, ".5", ".5", "0") + node(7, "0", ".5", "0") +
                                node(8, "0", "0", ".5") + node(9, ".5", "0", ".5") + node(10, "0", ".5", ".5") +
                                "*ELEMENT_SOLID\n" + ints({1, 7}) + ints({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
  EXPECT_EQ(ten.tets, (std::vector<index_t>{0, 1, 2, 3}));
  EXPECT_EQ(ten.midsides, (std::vector<index_t>{4, 5, 6, 7, 8, 9}));
  EXPECT_NE(read_error(nodes + node(5, ".5", "0", "0") + node(6, ".5", ".5", "0") + node(7, "0", ".5", "0") +
                       node(8, "0", "0", ".5") + node(9, ".5", "0", ".5") + node(10, "0", ".5", ".5") +
                       "*ELEMENT_SOLID\n" + ints({1, 7}) + ints({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}) +
                       ints({2, 7, 1, 2, 3, 4, 4, 4, 4, 4}))
                .find("t.k:"),
            std::string::npos);
}

TEST(LsdynaRead, LeftHandedTetsAreInverted) {
  // LS-DYNA takes a solid's nodes in one order: a left-handed tet is
  // inverted, which smoothing may untangle, not a tet to turn round.
  const TetMesh mesh = read_text("*NODE\n" + node(1, "0", "0", "0") + node(2, "1", "0", "0") + node(3, "0", "1", "0") +
                                 node(4, "0", "0", "1") + "*ELEMENT_SOLID\n" + ints({1, 1, 1, 3, 2, 4, 4, 4, 4, 4}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 2, 1, 3}));
  EXPECT_TRUE(mesh.extras.read_notes.empty());
}

TEST(LsdynaRead, BlankCardsAreCards) {
  // A blank set title, and a blank thickness card, are cards.
  EXPECT_TRUE(node5_pinned("*SET_NODE_LIST_TITLE\n\n" + ints({1}, 10) + ints({5}, 10)));
  EXPECT_TRUE(node5_pinned("*ELEMENT_SHELL_THICKNESS\n" + ints({21, 3, 1, 2, 3, 3}) + "\n" +
                           ints({22, 3, 2, 3, 5, 5}) + "\n"));
  // Keywords with a SET word in them name sets; OFFSET is none.
  EXPECT_TRUE(read_text(with("*LOAD_NODE_SET\n1,1,1\n")).extras.read_notes.empty());
  EXPECT_EQ(read_text(with("*ELEMENT_INERTIA_OFFSET\n" + ints({1, 5}))).extras.read_notes.size(), 1u);
  EXPECT_EQ(read_text(with("*SET_NODE_GENERAL\n" + ints({1}, 10) + "PART,1\n")).extras.read_notes.size(), 1u);
}

TEST(LsdynaRead, OtherSolidsPassThroughRightHanded) {
  // A unit cube's corners (LS-DYNA's brick order: N1..N4 below, N5..N8 above).
  std::string nodes = "*NODE\n";
  const char* at[8][3] = {{"0", "0", "0"}, {"1", "0", "0"}, {"1", "1", "0"}, {"0", "1", "0"},
                          {"0", "0", "1"}, {"1", "0", "1"}, {"1", "1", "1"}, {"0", "1", "1"}};
  for (int i = 0; i < 8; ++i) nodes += node(i + 1, at[i][0], at[i][1], at[i][2]);
  nodes += node(9, ".5", "0", "1") + node(10, ".5", "1", "1");  // a wedge's ridge
  const std::string solids = "*ELEMENT_SOLID\n" + ints({1, 1, 1, 2, 3, 4, 5, 6, 7, 8}) +  // brick
                             ints({2, 2, 1, 2, 3, 4, 9, 9, 10, 10}) +                   // wedge
                             ints({3, 3, 1, 2, 3, 4, 9, 9, 9, 9}) +                     // pyramid
                             ints({4, 4, 1, 2, 4, 5, 5, 5, 5, 5}) +                     // a tet
                             ints({5, 5, 1, 2, 3, 1, 5, 6, 7, 5});                      // no shape: pins
  const TetMesh mesh = read_text(nodes + solids);
  ASSERT_EQ(mesh.extras.blocks.size(), 3u);
  const auto point = [&](std::int32_t n) {
    return Vec3<double>{mesh.xyz[3 * n], mesh.xyz[3 * n + 1], mesh.xyz[3 * n + 2]};
  };
  for (const PassThroughBlock& b : mesh.extras.blocks) {
    ASSERT_EQ(b.element_tags.size(), 1u) << b.kind;
    const std::vector<std::int32_t>& c = b.connectivity;
    // The first face's corners and a corner off it make a right-handed tet.
    const std::size_t off = b.kind == "wedge" ? 3 : 4;
    EXPECT_GT(signed_volume6(point(c[0]), point(c[1]), point(c[2]), point(c[off])), 0.0) << b.kind;
  }
  EXPECT_EQ(mesh.extras.blocks[1].kind, "wedge");
  EXPECT_EQ(mesh.extras.blocks[1].connectivity, (std::vector<std::int32_t>{0, 8, 1, 3, 9, 2}));
  EXPECT_EQ(mesh.extras.blocks[2].tags, (std::vector<int>{3}));
  // The solid without a shape pins its nodes, and other formats note it.
  EXPECT_EQ(mesh.fixed[6], 1);
  const std::vector<std::string> notes = output_losses(mesh, "out.vtu");
  EXPECT_NE(std::find_if(notes.begin(), notes.end(),
                         [](const std::string& n) { return n.find("ELEMENT_SOLID (8-node)") != std::string::npos; }),
            notes.end());
  // A new deck writes the shapes back in LS-DYNA's forms.
  TetMesh copy = mesh;
  copy.extras.raw_sections.clear();
  const TetMesh back = read_text(write_text(copy));
  ASSERT_EQ(back.extras.blocks.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(back.extras.blocks[i].kind, mesh.extras.blocks[i].kind);
    EXPECT_EQ(back.extras.blocks[i].connectivity, mesh.extras.blocks[i].connectivity);
  }
}

TEST(LsdynaRead, ConstraintsSetsLoadsAndElementsPin) {
  EXPECT_FALSE(node5_pinned(""));
  EXPECT_FALSE(node5_pinned("*SET_NODE_LIST\n" + ints({1}, 10) + ints({1, 2, 3}, 10)));
  EXPECT_TRUE(node5_pinned("*SET_NODE_LIST_TITLE\nfixed\n" + ints({1}, 10) + ints({1, 2, 0, 5}, 10)));
  EXPECT_TRUE(node5_pinned("*SET_NODE_LIST_GENERATE\n" + ints({1}, 10) + ints({4, 6}, 10)));
  EXPECT_TRUE(node5_pinned("*SET_SEGMENT\n" + ints({1}, 10) + ints({1, 2, 5, 5}, 10)));
  EXPECT_TRUE(node5_pinned("*BOUNDARY_SPC_NODE\n" + ints({5, 0, 1, 1, 1}, 10)));
  EXPECT_TRUE(node5_pinned("*boundary_prescribed_motion_node\n5,1,2,3\n"));
  EXPECT_TRUE(node5_pinned("*LOAD_NODE_POINT\n" + ints({5, 3, 1}, 10)));
  EXPECT_TRUE(node5_pinned("*INITIAL_VELOCITY_NODE\n" + ints({5}, 10)));
  EXPECT_TRUE(node5_pinned("*CONSTRAINED_EXTRA_NODES_NODE\n" + ints({1, 5}, 10)));
  EXPECT_TRUE(node5_pinned("*DATABASE_HISTORY_NODE\n" + ints({1, 2, 3, 4, 5}, 10)));
  EXPECT_TRUE(node5_pinned("*ELEMENT_SHELL\n" + ints({21, 3, 1, 2, 5, 5})));
  EXPECT_TRUE(node5_pinned("*ELEMENT_SHELL_THICKNESS\n" + ints({21, 3, 1, 2, 3, 3}) + "0.1,0.1,0.1,0.1\n" +
                           ints({22, 3, 2, 3, 5, 5}) + "0.1,0.1,0.1,0.1\n"));
  EXPECT_TRUE(node5_pinned("*ELEMENT_BEAM\n" + ints({31, 4, 1, 2, 5})));
  EXPECT_TRUE(node5_pinned("*ELEMENT_MASS\n" + ints({41, 5}, 8)));
  EXPECT_TRUE(node5_pinned("*ELEMENT_DISCRETE\n" + ints({41, 6, 5, 1})));
  // A constraint on the node card itself.
  std::string constrained = with("");
  constrained.replace(constrained.find(node(5, "0.3", "0.2", "0.1")), node(5, "0.3", "0.2", "0.1").size(),
                      node(5, "0.3", "0.2", "0.1", "       7       0"));
  EXPECT_EQ(read_text(constrained).fixed[4], 1);
  // Shells and beams pass through with their PIDs.
  const TetMesh mesh = read_text(with("*ELEMENT_SHELL\n" + ints({21, 3, 1, 2, 3, 3}) + ints({22, 3, 1, 2, 3, 4}) +
                                      "*ELEMENT_BEAM\n" + ints({31, 4, 1, 2})));
  ASSERT_EQ(mesh.extras.blocks.size(), 3u);
  EXPECT_EQ(mesh.extras.blocks[0].kind, "triangle");
  EXPECT_EQ(mesh.extras.blocks[1].kind, "quad");
  EXPECT_EQ(mesh.extras.blocks[2].kind, "line");
  EXPECT_EQ(mesh.extras.blocks[2].tags, (std::vector<int>{4}));
  // Keywords that name nodes and are not read are noted.
  const TetMesh noted = read_text(with("*CONSTRAINED_LINEAR_GLOBAL\n" + ints({1}, 10) + ints({5, 1, 1}, 10)));
  ASSERT_EQ(noted.extras.read_notes.size(), 1u);
  EXPECT_NE(noted.extras.read_notes[0].find("CONSTRAINED_LINEAR_GLOBAL keywords are not read"), std::string::npos);
}

TEST(LsdynaRead, PartHeadingsNameRegions) {
  const TetMesh mesh =
      read_text(with("*PART\nrock mass\n" + ints({1, 1, 1}, 10) + "*PART\n\n" + ints({2, 1, 1}, 10) +
                     "*PART_CONTACT\ntunnel lining\n" + ints({4}, 10) + ints({0}, 10) +
                     // Cards of other kinds: no heading, no PID card (a name for
                     // part 2 here would come first).
                     "*PART_SENSOR\n" + ints({1, 7, 1}, 10) + ints({2, 8, 1}, 10) + "*PART_DUPLICATE\nPART" +
                     ints({1, 0, 1000}, 10) + "*PART_INERTIA_CONTACT\nbolt\n" + ints({2}, 10)));
  const std::string* names = raw_section(mesh.extras, "$PhysicalNames");
  ASSERT_NE(names, nullptr);
  const std::map<int, std::string> solids = physical_names_of(*names, 3);
  EXPECT_EQ(solids, (std::map<int, std::string>{{1, "rock mass"}, {2, "bolt"}}));
}

// The long layout ("*KEYWORD LONG=Y", or '+' after a keyword): every field
// narrower than 20 columns is 20 wide, and a card stays on one line.
TEST(LsdynaLong, ReadsAsTheStandardLayoutDoes) {
  const TetMesh standard = read_text(with("*PART\nrock\n" + ints({1, 1, 1}, 10)));
  const TetMesh wide = read_text(with_long("*PART\nrock\n" + ints({1, 1, 1}, 20)));
  EXPECT_EQ(wide.xyz, standard.xyz);
  EXPECT_EQ(wide.tets, standard.tets);
  EXPECT_EQ(wide.extras.tet_tags, standard.extras.tet_tags);
  EXPECT_EQ(wide.extras.node_tags, standard.extras.node_tags);
  EXPECT_EQ(wide.extras.tet_element_tags, standard.extras.tet_element_tags);
  const std::string* names = raw_section(wide.extras, "$PhysicalNames");
  ASSERT_NE(names, nullptr);
  EXPECT_EQ(physical_names_of(*names, 3), (std::map<int, std::string>{{1, "rock"}}));
  EXPECT_TRUE(wide.fixed.empty());
  // Ids past the standard layout's 8 digits, and the forms of a solid: two
  // cards (EID PID, then N1..N10), free format, an option's cards.
  const std::string nodes = "*NODE +\n" + long_node(123456789012, "0", "0", "0") + long_node(2, "1", "0", "0") +
                            long_node(3, "0", "1", "0") + long_node(4, "0", "0", "1");
  const std::vector<std::string> forms = {
      "*ELEMENT_SOLID +\n" + ints({1, 2000000000, 123456789012, 2, 3, 4, 4, 4, 4, 4}, 20),
      "*ELEMENT_SOLID +\n" + ints({1, 2000000000}, 20) + ints({123456789012, 2, 3, 4}, 20),
      "*ELEMENT_SOLID+\n1,2000000000,123456789012,2,3,4\n",
      "*ELEMENT_SOLID_ORTHO +\n" + ints({1, 2000000000, 123456789012, 2, 3, 4, 4, 4, 4, 4}, 20) +
          "                 1.0                 0.0                 0.0\n"
          "                 0.0                 1.0                 0.0\n",
  };
  for (const std::string& form : forms) {
    const TetMesh mesh = read_text(nodes + form);
    ASSERT_EQ(mesh.num_tets(), 1u) << form;
    EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3})) << form;
    EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{2000000000})) << form;
    EXPECT_EQ(mesh.extras.node_tags[0], 123456789012) << form;
  }
  // 10-node tets on their second card of 200 columns.
  const TetMesh ten =
      read_text(nodes + long_node(5, ".5", "0", "0") + long_node(6, ".5", ".5", "0") + long_node(7, "0", ".5", "0") +
                long_node(8, "0", "0", ".5") + long_node(9, ".5", "0", ".5") + long_node(10, "0", ".5", ".5") +
                "*ELEMENT_SOLID +\n" + ints({1, 7}, 20) + ints({123456789012, 2, 3, 4, 5, 6, 7, 8, 9, 10}, 20));
  EXPECT_EQ(ten.midsides, (std::vector<index_t>{4, 5, 6, 7, 8, 9}));
}

TEST(LsdynaLong, SetsLoadsConstraintsAndElementsPin) {
  EXPECT_FALSE(long_node5_pinned(""));
  EXPECT_FALSE(long_node5_pinned("*SET_NODE_LIST\n" + ints({1}, 20) + ints({1, 2, 3}, 20)));
  // Node 5 in the fifth field, past the standard layout's 80 columns.
  EXPECT_TRUE(long_node5_pinned("*SET_NODE_LIST_TITLE\nfixed\n" + ints({1}, 20) + ints({1, 2, 0, 4, 5}, 20)));
  EXPECT_TRUE(long_node5_pinned("*SET_NODE_LIST_GENERATE\n" + ints({1}, 20) + ints({1, 1, 5, 5}, 20)));
  EXPECT_TRUE(long_node5_pinned("*SET_SEGMENT\n" + ints({1}, 20) + ints({1, 2, 3, 5}, 20)));
  EXPECT_TRUE(long_node5_pinned("*BOUNDARY_SPC_NODE\n" + ints({5, 0, 1, 1, 1}, 20)));
  EXPECT_TRUE(long_node5_pinned("*BOUNDARY_PRESCRIBED_MOTION_NODE\n" + ints({5, 1, 2, 3}, 20)));
  EXPECT_TRUE(long_node5_pinned("*LOAD_NODE_POINT\n" + ints({5, 3, 1}, 20)));
  EXPECT_TRUE(long_node5_pinned("*INITIAL_VELOCITY_NODE\n" + ints({5}, 20)));
  EXPECT_TRUE(long_node5_pinned("*CONSTRAINED_EXTRA_NODES_NODE\n" + ints({1, 5}, 20)));
  EXPECT_TRUE(long_node5_pinned("*CONSTRAINED_SPOTWELD\n" + ints({1, 5}, 20)));
  EXPECT_TRUE(long_node5_pinned("*DATABASE_HISTORY_NODE\n" + ints({1, 2, 3, 4, 5}, 20)));
  EXPECT_TRUE(long_node5_pinned("*ELEMENT_SHELL\n" + ints({21, 3, 1, 2, 5, 5}, 20)));
  EXPECT_TRUE(long_node5_pinned("*ELEMENT_BEAM\n" + ints({31, 4, 1, 2, 5}, 20)));
  EXPECT_TRUE(long_node5_pinned("*ELEMENT_MASS\n" + ints({41, 5}, 20)));
  EXPECT_TRUE(long_node5_pinned("*ELEMENT_DISCRETE\n" + ints({41, 6, 5, 1}, 20)));
  EXPECT_TRUE(long_node5_pinned("*ELEMENT_TSHELL\n" + ints({41, 6, 1, 2, 3, 5, 1, 2, 3, 5}, 20)));
  std::string constrained = with_long("");
  const std::string free_node = long_node(5, "0.3", "0.2", "0.1");
  constrained.replace(constrained.find(free_node), free_node.size(),
                      long_node(5, "0.3", "0.2", "0.1", "                   7                   0"));
  EXPECT_EQ(read_text(constrained).fixed[4], 1);
}

TEST(LsdynaLong, MixesWithTheOtherLayouts) {
  // '+' in a standard deck, '-' and '%' in a long one: each keyword's cards
  // in its own layout.
  const TetMesh plain = read_text(kStar);
  const TetMesh long_nodes = read_text("*KEYWORD\n*NODE +" + kLongNodes.substr(5) + kSolids + "*END\n");
  EXPECT_EQ(long_nodes.xyz, plain.xyz);
  EXPECT_EQ(long_nodes.tets, plain.tets);
  const TetMesh standard_nodes = read_text("*KEYWORD LONG=Y\n*NODE -" + kNodes.substr(5) + kLongSolids +
                                           "*ELEMENT_SOLID %\n" + ints({15, 3, 1, 2, 3, 5, 5, 5, 5, 5}, 10) +
                                           "*SET_NODE_LIST\n" + ints({1}, 20) + ints({1, 5}, 20) + "*END\n");
  EXPECT_EQ(standard_nodes.xyz, plain.xyz);
  EXPECT_EQ(standard_nodes.num_tets(), 5u);
  EXPECT_EQ(standard_nodes.extras.tet_tags.back(), 3);
  ASSERT_EQ(standard_nodes.fixed.size(), 5u);
  EXPECT_EQ(standard_nodes.fixed[4], 1);
  // "*KEYWORD I10=Y LONG=Y" reads 20 columns: ids fit them.
  EXPECT_EQ(read_text("*KEYWORD I10=Y LONG=Y\n" + kLongNodes + kLongSolids).xyz, plain.xyz);
}

TEST(LsdynaLong, WrittenBackWithOnlyMovedCoordinatesChanged) {
  const std::string tail = "                   0                   7  after the card\n";
  const std::string deck = "*KEYWORD LONG=Y\n$ a comment\n*NODE\n" + long_node(1, "0.0", "0.0", "0.0") +
                           long_node(2, "1.0", "0.0", "0.0", tail.substr(0, tail.size() - 1).c_str()) +
                           long_node(3, "0.0", "1.0", "0.0") + "$# a comment among the nodes\n" +
                           long_node(4, "0.0", "0.0", "1.0") + "5,0.3,0.2,0.1,0,0\n" + kLongSolids +
                           "*MAT_ELASTIC\n1,7.8e-9,210000.,0.3\n*NODE -\n" + node(6, "2", "2", "2") + "*END\nafter\n";
  TetMesh mesh = read_text(deck);
  ASSERT_EQ(mesh.num_nodes(), 6u);
  EXPECT_EQ(write_text(mesh), deck);
  // Node 2's z, in 20 columns: its NID, x, y, TC, RC and what follows as read.
  mesh.xyz[5] = -1.0 / 3.0;
  std::string expected = deck;
  const std::string before = long_node(2, "1.0", "0.0", "0.0");
  const std::size_t at = expected.find(before.substr(0, 80));
  ASSERT_NE(at, std::string::npos);
  expected.replace(at + 60, 20, " -0.3333333333333333");
  EXPECT_EQ(write_text(mesh), expected);
  EXPECT_EQ(read_text(expected).xyz, mesh.xyz);  // 20 columns hold it exactly
  // A free-format card, in as many characters as 20 columns hold.
  mesh = read_text(deck);
  mesh.xyz[13] = 1.0 / 3.0;
  expected = deck;
  expected.replace(expected.find("5,0.3,0.2"), 9, "5,0.3,0.3333333333333333");
  EXPECT_EQ(write_text(mesh), expected);
  // The standard node among them keeps its 16 columns.
  mesh = read_text(deck);
  mesh.xyz[15] = 1.0 / 3.0;
  expected = deck;
  expected.replace(expected.find(node(6, "2", "2", "2")), node(6, "2", "2", "2").size(),
                   node(6, "0.3333333333333", "2", "2"));
  EXPECT_EQ(write_text(mesh), expected);
}

TEST(LsdynaLong, ErrorsNameFileAndLine) {
  // A card cut short: its solid lacks nodes, its node set ends where the
  // standard layout's card would.
  EXPECT_EQ(read_error(with_long("*ELEMENT_SOLID\n" + ints({15, 1, 1, 2, 3}, 20))),
            "t.k:15: solid element 15 leaves node N4 blank or 0, which names no node (a card cut short?)");
  EXPECT_EQ(read_error(with_long("*ELEMENT_SOLID\n" + ints({15, 1}, 20) + ints({1, 2, 3, 5, 1, 2, 3, 4, 5}, 20))),
            "t.k:16: solid element 15 leaves node N10 blank or 0, which names no node (a card cut short?)");
  EXPECT_EQ(read_error(with_long("*ELEMENT_SOLID\n" + ints({15, 1}, 20))),
            "t.k:16: *ELEMENT_SOLID: the element before this line lacks some of its cards");
  // Fields that are no numbers, standard cards under a long keyword among
  // them.
  EXPECT_EQ(read_error("*NODE +\n" + long_node(1, "x", "0", "0")),
            "t.k:2: node 1: expected a finite coordinate, found 'x'");
  EXPECT_EQ(read_error("*NODE +\n" + long_node(1, "0", "0", "0", "                  &t")),
            "t.k:2: node 1: expected its constraints TC and RC as whole numbers, found '&t'");
  EXPECT_EQ(read_error("*NODE +\n" + node(1, "1.5", "0", "0")),
            "t.k:2: node 1: expected a finite coordinate, found '1.5               0'");
  EXPECT_EQ(read_error(with_long("*SET_NODE_LIST\n" + ints({1}, 20) + ints({1, 5}, 10))),
            "t.k:16: expected a node id, a positive whole number, found '1         5'");
  EXPECT_EQ(read_error(with_long("*ELEMENT_SOLID\n" + ints({15, 1, 1, 2, 3, 5, 5, 5, 5, 5}))),
            "t.k:15: expected an element id (EID), a positive whole number, found '15       1'");
  EXPECT_EQ(read_error(with_long("*PART\nbig\n" + ints({3000000000LL}, 20))),
            "t.k:16: part id 3000000000 is past 2,147,483,647, the largest region tag");
}

TEST(LsdynaWrite, KeptDeckChangesOnlyMovedNodes) {
  const std::string deck = "*KEYWORD\n$ a comment\n*NODE\n" + node(1, "0.0", "0.0", "0.0") +
                           node(2, "1.0", "0.0", "0.0", "       0       7") + node(3, "0.0", "1.0", "0.0") +
                           "$# a comment among the nodes\n" + node(4, "0.0", "0.0", "1.0") +
                           "5,0.3,0.2,0.1,0,0\n" + kSolids + "*MAT_ELASTIC\n1,7.8e-9,210000.,0.3\n*END\nafter\n";
  TetMesh mesh = read_text(deck);
  EXPECT_EQ(write_text(mesh), deck);
  mesh.xyz[12] = 0.25;  // node 5's x, in free format
  mesh.xyz[13] = 1.0 / 3.0;
  std::string expected = deck;
  expected.replace(expected.find("5,0.3,0.2"), 9, "5,0.25,0.3333333333333");
  EXPECT_EQ(write_text(mesh), expected);
  mesh = read_text(deck);
  mesh.xyz[5] = -1.0 / 3.0;  // node 2's z: x and y keep their text, TC and RC stay
  expected = deck;
  const std::string before = node(2, "1.0", "0.0", "0.0", "       0       7");
  expected.replace(expected.find(before), before.size(),
                   node(2, "1.0", "0.0", "-0.333333333333", "       0       7"));
  EXPECT_EQ(write_text(mesh), expected);
  // A mesh that is no longer the deck's is refused.
  mesh.tets.resize(12);
  EXPECT_THROW(write_text(mesh), OutputError);
}

TEST(LsdynaWrite, NewDecksReadBack) {
  TetMesh mesh = testing::cube_grid(2, 0.1);
  mesh.extras.tet_tags.assign(mesh.num_tets(), 3);
  mesh.extras.tet_tags[0] = -2;  // no PID: renumbered
  mesh.extras.raw_sections.emplace_back("$PhysicalNames", "1\n3 3 \"clay\"\n");
  mesh.fixed.assign(mesh.num_nodes(), 0);
  mesh.fixed[13] = 1;  // the middle node
  const std::string text = write_text(mesh);
  EXPECT_NE(text.find("*PART\n$# title\nclay\n"), std::string::npos);
  EXPECT_NE(text.find("TETSMOOTH_PINNED"), std::string::npos);
  const TetMesh back = read_text(text);
  EXPECT_EQ(back.tets, mesh.tets);
  for (std::size_t i = 0; i < mesh.xyz.size(); ++i) EXPECT_NEAR(back.xyz[i], mesh.xyz[i], 1e-12);
  EXPECT_EQ(back.extras.tet_tags[1], 3);
  EXPECT_EQ(back.extras.tet_tags[0], lsdyna_region_ids(mesh).renumbered().at(-2));
  ASSERT_EQ(back.fixed.size(), mesh.num_nodes());
  EXPECT_EQ(back.fixed[13], 1);
  EXPECT_EQ(std::count(back.fixed.begin(), back.fixed.end(), 1), 1);
  // 10-node tets, on two cards.
  const TetMesh ten = testing::with_midsides(testing::cube_grid(1));
  const TetMesh ten_back = read_text(write_text(ten));
  EXPECT_EQ(ten_back.tets, ten.tets);
  EXPECT_EQ(ten_back.midsides, ten.midsides);
  // Pass-through elements other than solids, shells and beams are left out.
  TetMesh points = testing::cube_grid(1);
  points.extras.blocks.push_back(PassThroughBlock{"vertex", 1, {0}, {}, {}, {}});
  const std::vector<std::string> notes = output_losses(points, "out.k");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find("1 vertex will not be written"), std::string::npos);
}

// A part takes one section: shells and beams that share a region tag with
// solids (beams with shells) get parts of their own, headed by their own
// physical names, with a note.
TEST(LsdynaWrite, ShellsAndBeamsOfASolidsTagGetTheirOwnParts) {
  TetMesh mesh = testing::cube_grid(1);
  mesh.extras.tet_tags.assign(mesh.num_tets(), 1);
  mesh.extras.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 1, 2, 1, 2, 3}, {1, 2}, {}, {}});
  mesh.extras.blocks.push_back(PassThroughBlock{"line", 2, {0, 1}, {2}, {}, {}});
  mesh.extras.raw_sections.emplace_back("$PhysicalNames", "3\n3 1 \"rock\"\n2 1 \"top\"\n1 2 \"edge\"\n");
  const RegionIds pids = lsdyna_region_ids(mesh);
  EXPECT_EQ(pids.of(3, 1), 1);
  EXPECT_EQ(pids.of(2, 2), 2);
  EXPECT_EQ(pids.of(2, 1), 3);  // above the largest in use
  EXPECT_EQ(pids.of(1, 2), 4);
  EXPECT_EQ(pids.split(), (std::map<std::pair<int, int>, long long>{{{2, 1}, 3}, {{1, 2}, 4}}));
  const std::string text = write_text(mesh);
  for (const char* part : {"*PART\n$# title\nrock\n$#     pid     secid       mid\n         1\n",
                           "*PART\n$# title\n\n$#     pid     secid       mid\n         2\n",
                           "*PART\n$# title\ntop\n$#     pid     secid       mid\n         3\n",
                           "*PART\n$# title\nedge\n$#     pid     secid       mid\n         4\n"})
    EXPECT_NE(text.find(part), std::string::npos) << part;
  const TetMesh back = read_text(text);
  ASSERT_EQ(back.extras.blocks.size(), 2u);
  EXPECT_EQ(back.extras.blocks[0].tags, (std::vector<int>{3, 2}));
  EXPECT_EQ(back.extras.blocks[1].tags, (std::vector<int>{4}));
  const std::vector<std::string> notes = output_losses(mesh, "out.k");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0],
            "elements of several dimensions in one region get PIDs of their own (shells of region 1 as PID "
            "3, lines of region 2 as PID 4): an LS-DYNA part takes one section (solid, shell or beam)");
  // Nastran's PIDs the same way.
  EXPECT_EQ(nastran_region_ids(mesh).split(), pids.split());
}

TEST(LsdynaIo, IncludedFilesAreReadInPlaceAndWrittenInline) {
  testing::ScratchDir dir("lsdyna_include");
  std::filesystem::create_directory(dir.file("mesh"));
  std::ofstream(dir.file("mesh/nodes.k")) << kNodes;
  std::ofstream(dir.file("main.k")) << "*KEYWORD\n*INCLUDE\nmesh/nod +\nes.k\n" << kSolids << "*END\n";
  const TetMesh mesh = read_lsdyna_file(dir.file("main.k"));
  EXPECT_EQ(mesh.num_nodes(), 5u);
  EXPECT_EQ(write_text(mesh), "*KEYWORD\n" + kNodes + kSolids + "*END\n");
  const std::vector<std::string> notes = output_losses(mesh, "out.k");
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], "the *INCLUDE files (" + dir.file("mesh/nodes.k") + ") will be written inline, in the one output deck");
  // An included file's *END ends that file alone, and stays out of the
  // deck written.
  std::ofstream(dir.file("mesh/nodes.k")) << "*KEYWORD\n" << kNodes << "*END\nnot read\n";
  const TetMesh ended = read_lsdyna_file(dir.file("main.k"));
  EXPECT_EQ(ended.num_tets(), 4u);
  EXPECT_EQ(write_text(ended), "*KEYWORD\n$*KEYWORD\n" + kNodes + kSolids + "*END\n");
  // An included file's layout: its *INCLUDE's mark, or its own *KEYWORD,
  // which holds in that file alone. Written inline, its keywords carry it.
  std::string i10_nodes = "*NODE\n";
  for (std::size_t at = kNodes.find("\n", kNodes.find("\n") + 1) + 1; at < kNodes.size();
       at = kNodes.find('\n', at) + 1)
    i10_nodes += "  " + kNodes.substr(at, kNodes.find('\n', at) + 1 - at);  // ids in 10 columns
  const std::string i10_written = "*NODE %\n" + i10_nodes.substr(6);
  std::ofstream(dir.file("mesh/nodes.k")) << i10_nodes;
  std::ofstream(dir.file("main.k")) << "*KEYWORD\n*INCLUDE %\nmesh/nodes.k\n" << kSolids << "*END\n";
  const TetMesh marked = read_lsdyna_file(dir.file("main.k"));
  EXPECT_EQ(marked.num_tets(), 4u);
  EXPECT_EQ(write_text(marked), "*KEYWORD\n" + i10_written + kSolids + "*END\n");
  EXPECT_EQ(read_text(write_text(marked)).xyz, marked.xyz);
  // The file's own "*KEYWORD I10=Y" agrees (Oasys PRIMER writes both).
  std::ofstream(dir.file("mesh/nodes.k")) << "*KEYWORD I10=Y\n" << i10_nodes;
  const TetMesh own = read_lsdyna_file(dir.file("main.k"));
  EXPECT_EQ(own.num_tets(), 4u);
  EXPECT_EQ(write_text(own), "*KEYWORD\n$*KEYWORD I10=Y\n" + i10_written + kSolids + "*END\n");
  // Without the mark LS-DYNA would read the file in the deck's layout.
  std::ofstream(dir.file("main.k")) << "*KEYWORD\n*INCLUDE\nmesh/nodes.k\n" << kSolids << "*END\n";
  EXPECT_EQ(testing::input_error_message([&] { read_lsdyna_file(dir.file("main.k")); }, "main.k"),
            dir.file("mesh/nodes.k") +
                ":1: an included file's *KEYWORD sets no layout in LS-DYNA, and this file is "
                "read in the standard layout: mark its *INCLUDE (\"*INCLUDE %\") for a file "
                "in the I10 layout");
  std::ofstream(dir.file("mesh/nodes.k")) << "*KEYWORD\n" << kNodes << "*END\n";
  std::ofstream(dir.file("main.k")) << "*KEYWORD I10=Y\n*INCLUDE -\nmesh/nodes.k\n*ELEMENT_SOLID -\n"
                                    << kSolids.substr(kSolids.find('\n') + 1) << "*END\n";
  EXPECT_EQ(write_text(read_lsdyna_file(dir.file("main.k"))), "*KEYWORD I10=Y\n$*KEYWORD\n" + std::string("*NODE -") +
                                                                  kNodes.substr(5) + "*ELEMENT_SOLID -\n" +
                                                                  kSolids.substr(kSolids.find('\n') + 1) + "*END\n");
  // Back from a file that includes another in its own layout, the next file
  // named under the first *INCLUDE takes that *INCLUDE's layout again.
  std::ofstream(dir.file("mesh/part.k")) << "*INCLUDE -\nmesh/empty.k\n";
  std::ofstream(dir.file("mesh/empty.k")) << "$ nothing\n";
  std::ofstream(dir.file("mesh/nodes.k")) << i10_nodes;
  std::ofstream(dir.file("main.k")) << "*KEYWORD\n*INCLUDE %\nmesh/part.k\nmesh/nodes.k\n" << kSolids << "*END\n";
  EXPECT_EQ(write_text(read_lsdyna_file(dir.file("main.k"))),
            "*KEYWORD\n$ nothing\n" + i10_written + kSolids + "*END\n");
  // An included *KEYWORD_ID's card goes with it into a comment, and no
  // further line of the deck.
  std::ofstream(dir.file("mesh/part.k")) << "*KEYWORD_ID\nmy model\n";
  std::ofstream(dir.file("main.k")) << "*KEYWORD\n*INCLUDE %\nmesh/part.k\n\nmesh/nodes.k\n" << kSolids << "*END\n";
  EXPECT_EQ(write_text(read_lsdyna_file(dir.file("main.k"))),
            "*KEYWORD\n$*KEYWORD_ID\n$my model\n\n" + i10_written + kSolids + "*END\n");
  // "*INCLUDE +" names files in the long layout, whose keywords are written
  // with its mark; a file of the long layout in a standard deck otherwise
  // asks for that mark.
  std::ofstream(dir.file("mesh/nodes.k")) << kLongNodes;
  std::ofstream(dir.file("main.k")) << "*KEYWORD\n*INCLUDE +\nmesh/nodes.k\n" << kSolids << "*END\n";
  const TetMesh long_included = read_lsdyna_file(dir.file("main.k"));
  EXPECT_EQ(long_included.xyz, mesh.xyz);
  EXPECT_EQ(write_text(long_included), "*KEYWORD\n*NODE +" + kLongNodes.substr(5) + kSolids + "*END\n");
  EXPECT_EQ(read_text(write_text(long_included)).xyz, mesh.xyz);
  std::ofstream(dir.file("mesh/part.k")) << "*KEYWORD LONG=Y\n";
  std::ofstream(dir.file("main.k")) << "*KEYWORD\n*INCLUDE\nmesh/part.k\n" << kNodes << kSolids << "*END\n";
  EXPECT_EQ(testing::input_error_message([&] { read_lsdyna_file(dir.file("main.k")); }, "main.k"),
            dir.file("mesh/part.k") +
                ":1: an included file's *KEYWORD sets no layout in LS-DYNA, and this file is read in the standard "
                "layout: mark its *INCLUDE (\"*INCLUDE +\") for a file in the long layout");
  // A long deck's standard file.
  std::ofstream(dir.file("mesh/nodes.k")) << kNodes;
  std::ofstream(dir.file("main.k")) << "*KEYWORD LONG=Y\n*INCLUDE -\nmesh/nodes.k\n" << kLongSolids << "*END\n";
  EXPECT_EQ(write_text(read_lsdyna_file(dir.file("main.k"))),
            "*KEYWORD LONG=Y\n*NODE -" + kNodes.substr(5) + kLongSolids + "*END\n");
  std::ofstream(dir.file("main.k")) << "*KEYWORD\n*INCLUDE\nmesh/nod +\nes.k\n" << kSolids << "*END\n";
  std::ofstream(dir.file("mesh/nodes.k")) << kNodes << node(5, "1", "1", "1");
  EXPECT_EQ(testing::input_error_message([&] { read_lsdyna_file(dir.file("main.k")); }, "main.k"),
            dir.file("mesh/nodes.k") + ":8: node 5 is defined a second time");
}

TEST(LsdynaRead, ErrorsNameFileAndLine) {
  for (const char* asked : {"LONG=S", "LONG=K"})
    EXPECT_EQ(read_error(std::string("*KEYWORD ") + asked + "\n" + kNodes + kSolids),
              std::string("t.k:1: *KEYWORD ") + asked +
                  " is not read: tetsmooth reads LONG=Y (every field 20 columns wide), the standard layout and "
                  "I10=Y; save the deck in one of those");
  EXPECT_NE(read_error(with("*NODE_TRANSFORM\n1,2\n")).find("*NODE_TRANSFORM moves or merges nodes"),
            std::string::npos);
  EXPECT_NE(read_error(with("*INCLUDE_PATH\n/tmp\n")).find("*INCLUDE_PATH is not read"), std::string::npos);
  EXPECT_NE(read_error(with("*ELEMENT_SOLID_H20\n")).find("*ELEMENT_SOLID_H20 is not read"), std::string::npos);
  EXPECT_EQ(read_error("*NODE\n" + node(1, "x", "0", "0")), "t.k:2: node 1: expected a finite coordinate, found 'x'");
  EXPECT_EQ(read_error("*NODE\n&nid,0,0,0\n"), "t.k:2: expected a node id (NID), a positive whole number, found '&nid'");
  EXPECT_EQ(read_error(with("*ELEMENT_SOLID\n" + ints({15, 1, 1, 2, 3, 9, 9, 9, 9, 9}))),
            "t.k:15: solid element 15 names node 9, which no *NODE defines");
  // A blank node field names no node: a card cut short is refused, not dropped.
  EXPECT_EQ(read_error(with("*ELEMENT_SOLID\n" + ints({15, 1, 1, 2, 3}))),
            "t.k:15: solid element 15 leaves node N4 blank or 0, which names no node (a card cut short?)");
  EXPECT_EQ(read_error(with("*ELEMENT_SOLID\n" + ints({15, 1, 3}))),
            "t.k:15: solid element 15 leaves node N2 blank or 0, which names no node (a card cut short?)");
  EXPECT_EQ(read_error(with("*ELEMENT_SOLID\n" + ints({15, 1}) + ints({1, 2, 3, 5, 1, 2, 3, 4, 5}))),
            "t.k:16: solid element 15 leaves node N10 blank or 0, which names no node (a card cut short?)");
  EXPECT_EQ(read_error(with("*ELEMENT_SOLID\n" + ints({15, 1, 1, 2, 3, 4, 5, 0, 6, 6}))),
            "t.k:15: solid element 15 leaves node N6 blank or 0, which names no node (a card cut short?)");
  EXPECT_EQ(read_error(with("*ELEMENT_SOLID\n" + ints({14, 1, 1, 2, 3, 5, 5, 5, 5, 5}))),
            "t.k:15: solid element 14 is defined a second time");
  EXPECT_EQ(read_error(with("*SET_NODE_LIST\n" + ints({1}, 10) + ints({77}, 10))),
            "t.k:16: *SET_NODE_LIST names node 77, which no *NODE defines");
  EXPECT_EQ(read_error(with("*ELEMENT_SOLID\n" + ints({15, 1}))), "t.k:16: *ELEMENT_SOLID: the element before this line lacks some of its cards");
  EXPECT_EQ(read_error("*NODE\n" + node(1, "0", "0", "0")), "t.k: no tets in *ELEMENT_SOLID: a volume mesh of tets is needed");
  EXPECT_EQ(read_error("*KEYWORD\n"), "t.k: no *NODE cards: not an LS-DYNA mesh");
  EXPECT_EQ(read_error(with("*PART\nbig\n" + ints({3000000000LL}, 10))),
            "t.k:16: part id 3000000000 is past 2,147,483,647, the largest region tag");
}

}  // namespace
}  // namespace tetsmooth
