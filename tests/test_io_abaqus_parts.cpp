// Abaqus decks with parts and an assembly (abaqus_io.hpp): instances placed
// by translation and rotation, smoothed as the flat deck of the same
// bodies, written back with only the moved nodes' lines changed (in part
// coordinates), pins through every way a deck names a part's node, and the
// structures that are refused, with file:line.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "abaqus_text.hpp"
#include "kernels/smoother.hpp"
#include "mesh/io/abaqus_io.hpp"
#include "mesh/io/number_text.hpp"
#include "support/test_meshes.hpp"

namespace tetsmooth {
namespace {

using testing::abaqus_read_error;
using testing::read_abaqus_text;
using testing::write_abaqus_text;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

SmoothOptions serial() {
  SmoothOptions o;
  o.threads = 1;
  o.max_iterations = 10;
  return o;
}

// Node lines as the writer writes them, so that a node that does not move
// comes back byte for byte.
std::string node_line(long long id, const double* xyz) {
  std::ostringstream out;
  out << id;
  for (int c = 0; c < 3; ++c) {
    out << ", ";
    put_real(out, xyz[c]);
  }
  return out.str() + "\n";
}

// Two jittered lattices: Soil where its part puts it, Pile translated by
// (4, 0, 0) and turned 90 degrees about the vertical axis through (4, 0, 0)
// (right-handed: x goes to y).
const TetMesh kSoil = testing::cube_grid(3, 0.3, 5), kPile = testing::cube_grid(3, 0.3, 9);
constexpr std::array<double, 3> kShift{4, 0, 0};

std::array<double, 3> pile_in_assembly(const double* p) {
  const double x = p[0] + kShift[0] - 4, y = p[1] + kShift[1];
  return {4 - y, x, p[2] + kShift[2]};
}

std::string part_text(const std::string& name, const TetMesh& mesh, const std::string& extra) {
  std::string text = "*Part, name=" + name + "\n*Node\n";
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) text += node_line(static_cast<long long>(i) + 1, &mesh.xyz[3 * i]);
  text += "*Element, type=C3D4, elset=" + name + "Body\n";
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) {
    text += std::to_string(t + 1);
    for (int k = 0; k < 4; ++k) text += ", " + std::to_string(mesh.tets[4 * t + static_cast<std::size_t>(k)] + 1);
    text += "\n";
  }
  return text + extra + "*Solid Section, elset=" + name + "Body, material=Rock\n,\n*End Part\n";
}

// `pins`: lines after the assembly's instances and after it.
// `between`: lines between the two parts.
std::string parts_deck(const std::string& part_sets = "", const std::string& assembly = "",
                       const std::string& model = "", const std::string& between = "") {
  return "*Heading\n two bodies\n" + part_text("Soil", kSoil, "") + between + part_text("Pile", kPile, part_sets) +
         "*Assembly, name=Assembly\n*Instance, name=Soil-1, part=Soil\n*End Instance\n"
         "*Instance, name=Pile-1, part=Pile\n 4., 0., 0.\n 4., 0., 0., 4., 0., 1., 90.\n*End Instance\n" +
         assembly + "*End Assembly\n*Material, name=Rock\n*Elastic\n1e9, 0.3\n" + model;
}

// The nodes that smoothing moves, by index.
std::vector<std::size_t> moved(const TetMesh& before, const TetMesh& after) {
  std::vector<std::size_t> nodes;
  for (std::size_t i = 0; i < before.num_nodes(); ++i)
    if (!std::equal(&before.xyz[3 * i], &before.xyz[3 * i + 3], &after.xyz[3 * i])) nodes.push_back(i);
  return nodes;
}

TEST(AbaqusParts, InstancesArePlacedAndSmoothAsTheFlatDeck) {
  const TetMesh parts = read_abaqus_text(parts_deck());
  ASSERT_EQ(parts.num_nodes(), kSoil.num_nodes() + kPile.num_nodes());
  ASSERT_EQ(parts.num_tets(), kSoil.num_tets() + kPile.num_tets());
  // Soil stays where its part is, bit for bit (no placement); Pile is
  // translated, then turned.
  EXPECT_TRUE(std::equal(kSoil.xyz.begin(), kSoil.xyz.end(), parts.xyz.begin()));
  for (std::size_t i = 0; i < kPile.num_nodes(); ++i) {
    const std::array<double, 3> want = pile_in_assembly(&kPile.xyz[3 * i]);
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(parts.xyz[3 * (kSoil.num_nodes() + i) + static_cast<std::size_t>(c)], want[c], 1e-12);
  }
  // Each (part, section) is a region, named after both.
  EXPECT_EQ(parts.extras.tet_tags.front(), 1);
  EXPECT_EQ(parts.extras.tet_tags.back(), 2);
  EXPECT_NE(write_abaqus_text(parts).find("*End Assembly"), std::string::npos);

  // The same bodies as a flat deck, at the assembly's coordinates.
  std::string flat = "*Heading\n*Node\n";
  for (std::size_t i = 0; i < parts.num_nodes(); ++i)
    flat += node_line(static_cast<long long>(i) + 1, &parts.xyz[3 * i]);
  flat += "*Element, type=C3D4, elset=Soil\n";
  for (std::size_t t = 0; t < parts.num_tets(); ++t) {
    if (t == kSoil.num_tets()) flat += "*Element, type=C3D4, elset=Pile\n";
    flat += std::to_string(t + 1);
    for (int k = 0; k < 4; ++k) flat += ", " + std::to_string(parts.tets[4 * t + static_cast<std::size_t>(k)] + 1);
    flat += "\n";
  }
  TetMesh flat_mesh = read_abaqus_text(flat), parts_mesh = parts;
  ASSERT_EQ(flat_mesh.tets, parts_mesh.tets);
  smooth(flat_mesh, serial(), Device::Cpu);
  smooth(parts_mesh, serial(), Device::Cpu);
  ASSERT_FALSE(moved(parts, parts_mesh).empty());
  EXPECT_EQ(flat_mesh.xyz, parts_mesh.xyz);  // node for node, bit for bit
}

TEST(AbaqusParts, WrittenBackWithOnlyMovedNodesInPartCoordinates) {
  const std::string deck = parts_deck();
  const TetMesh read = read_abaqus_text(deck);
  TetMesh smoothed = read;
  smooth(smoothed, serial(), Device::Cpu);
  const std::vector<std::size_t> nodes = moved(read, smoothed);
  ASSERT_FALSE(nodes.empty());
  const std::vector<std::string> in = lines_of(deck), out = lines_of(write_abaqus_text(smoothed));
  ASSERT_EQ(in.size(), out.size());
  // Node i's line: the heading and part header (4 lines) before Soil's
  // nodes; Soil's elements, section and part lines, and Pile's header
  // before Pile's.
  const std::size_t soil_first = 4, pile_first = 4 + kSoil.num_nodes() + 1 + kSoil.num_tets() + 3 + 2;
  std::set<std::size_t> changed;
  for (std::size_t l = 0; l < in.size(); ++l)
    if (in[l] != out[l]) changed.insert(l);
  std::set<std::size_t> expected;
  for (std::size_t i : nodes) {
    const bool soil = i < kSoil.num_nodes();
    const std::size_t line = soil ? soil_first + i : pile_first + i - kSoil.num_nodes();
    expected.insert(line);
    // The line holds the node's part coordinates: placed, they are where
    // smoothing moved it.
    std::istringstream fields(out[line]);
    long long id = 0;
    std::array<double, 3> part{};
    char comma = 0;
    fields >> id >> comma >> part[0] >> comma >> part[1] >> comma >> part[2];
    EXPECT_EQ(id, static_cast<long long>(soil ? i : i - kSoil.num_nodes()) + 1);
    const std::array<double, 3> at = soil ? part : pile_in_assembly(part.data());
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(at[c], smoothed.xyz[3 * i + static_cast<std::size_t>(c)], 1e-12) << out[line];
  }
  EXPECT_EQ(changed, expected);
  // Read again, the deck gives the smoothed positions.
  const TetMesh again = read_abaqus_text(write_abaqus_text(smoothed));
  for (std::size_t k = 0; k < again.xyz.size(); ++k) EXPECT_NEAR(again.xyz[k], smoothed.xyz[k], 1e-12);
}

TEST(AbaqusParts, PinsThroughEveryFormOfReference) {
  TetMesh free_mesh = read_abaqus_text(parts_deck());
  const TetMesh before = free_mesh;
  smooth(free_mesh, serial(), Device::Cpu);
  std::vector<std::size_t> soil, pile;  // moved nodes of each instance, by their part's number
  for (std::size_t i : moved(before, free_mesh))
    (i < kSoil.num_nodes() ? soil : pile).push_back(i < kSoil.num_nodes() ? i + 1 : i + 1 - kSoil.num_nodes());
  ASSERT_GE(soil.size(), 3u);
  ASSERT_GE(pile.size(), 4u);
  const auto n = [](std::size_t id) { return std::to_string(id); };
  const std::string part_sets = "*Nset, nset=Head\n" + n(pile[0]) + "\n";
  const std::string assembly = "*Nset, nset=Anchor, instance=Pile-1\n" + n(pile[1]) +
                               "\n*Nset, nset=Inner, instance=Soil-1\n" + n(soil[1]) +
                               "\n*Nset, nset=Outer\nInner, Pile-1." + n(pile[2]) +
                               "\n*Nset, nset=Watched, instance=Pile-1\n" + n(pile[3]) + "\n";
  const std::string model = "*Step\n*Static\n*Boundary\nSoil-1." + n(soil[0]) + ", 1, 3\nPile-1.Head, ENCASTRE\n" +
                            "Anchor, 1\n*Cload\nOuter, 2, 1e3\n*Node Print, nset=Watched\nU\n*End Step\n";
  TetMesh pinned = read_abaqus_text(parts_deck(part_sets, assembly, model));
  ASSERT_EQ(pinned.fixed.size(), pinned.num_nodes());
  const std::size_t off = kSoil.num_nodes();
  for (std::size_t i : {soil[0] - 1, soil[1] - 1, off + pile[0] - 1, off + pile[1] - 1, off + pile[2] - 1})
    EXPECT_EQ(pinned.fixed[i], 1) << i;
  EXPECT_EQ(pinned.fixed[off + pile[3] - 1], 0);  // output only
  const TetMesh pinned_before = pinned;
  smooth(pinned, serial(), Device::Cpu);
  for (std::size_t i : {soil[0] - 1, soil[1] - 1, off + pile[0] - 1, off + pile[1] - 1, off + pile[2] - 1})
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(pinned.xyz[3 * i + static_cast<std::size_t>(c)],
                pinned_before.xyz[3 * i + static_cast<std::size_t>(c)]);
}

TEST(AbaqusParts, APartWithoutInstanceIsNoBodyAndKeepsItsLines) {
  // Between the two parts, one that no instance places, with the only
  // surface elements of the deck, sets and a section of its own.
  const std::string spare =
      part_text("Spare", testing::cube_grid(1), "*Element, type=S3, elset=Skin\n7, 1, 2, 3\n*Nset, nset=Corner\n1\n");
  const std::string deck = parts_deck("", "", "", spare);
  const TetMesh with = read_abaqus_text(deck), without = read_abaqus_text(parts_deck());
  EXPECT_EQ(with.xyz, without.xyz);  // Pile still placed, after the part that left
  EXPECT_EQ(with.tets, without.tets);
  EXPECT_EQ(with.extras.tet_tags, without.extras.tet_tags);
  EXPECT_EQ(with.extras.node_tags, without.extras.node_tags);
  EXPECT_EQ(with.extras.tet_element_tags, without.extras.tet_element_tags);
  EXPECT_TRUE(with.extras.blocks.empty());
  EXPECT_EQ(write_abaqus_text(with), deck);  // every line, the part's among them
  TetMesh smoothed = with;
  smooth(smoothed, serial(), Device::Cpu);
  const std::string out = write_abaqus_text(smoothed);
  EXPECT_NE(out.find(spare), std::string::npos);
  EXPECT_NE(out, deck);
}

TEST(AbaqusParts, ReferencePointsOfTheAssemblyStayAndPin) {
  // Abaqus/CAE writes a reference point as a node of the assembly, in a
  // set that constraints and boundary conditions name, with its number.
  const std::string deck =
      parts_deck("", "*Node\n1, 9., 9., 9.\n*Nset, nset=RP-1\n 1,\n", "*Boundary\nRP-1, ENCASTRE\n1, 1\n");
  TetMesh mesh = read_abaqus_text(deck);
  ASSERT_EQ(mesh.num_nodes(), kSoil.num_nodes() + kPile.num_nodes() + 1);
  EXPECT_EQ(mesh.xyz.back(), 9.0);
  ASSERT_FALSE(mesh.fixed.empty());
  EXPECT_EQ(mesh.fixed.back(), 1);
  smooth(mesh, serial(), Device::Cpu);
  const std::vector<std::string> in = lines_of(deck), out = lines_of(write_abaqus_text(mesh));
  ASSERT_EQ(in.size(), out.size());
  const auto rp = std::find(in.begin(), in.end(), "1, 9., 9., 9.") - in.begin();
  EXPECT_EQ(out[static_cast<std::size_t>(rp)], "1, 9, 9, 9");  // written anew, as every node line
}

TEST(AbaqusParts, PartsWithTheSameNumbersConvertRenumbered) {
  const TetMesh mesh = read_abaqus_text(parts_deck());
  // Both parts number their nodes and elements 1, 2, ...: kept as the
  // file's (the deck writes them back), but not distinct across the mesh.
  EXPECT_EQ(mesh.extras.node_tags.front(), 1);
  EXPECT_EQ(mesh.extras.node_tags[kSoil.num_nodes()], 1);
  EXPECT_EQ(abaqus_numbers_lost(mesh), "");  // its own deck keeps them
}

TEST(AbaqusParts, RefusedStructuresNameTheLine) {
  const std::string deck = parts_deck();
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string text = deck;
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
  };
  // The line numbers of the assembly's lines.
  const std::vector<std::string> lines = lines_of(deck);
  const auto line_of = [&](const std::string& text, std::size_t after = 0) {
    for (std::size_t l = 0; l < lines.size(); ++l)
      if (lines[l] == text) return "t.inp:" + std::to_string(l + 1 + after) + ": ";
    ADD_FAILURE() << text;
    return std::string();
  };
  const std::string assembly = line_of("*Assembly, name=Assembly"), pile = line_of("*Instance, name=Pile-1, part=Pile");
  const std::string end_assembly = line_of("*End Assembly");
  const struct {
    std::string from, to, message;
  } cases[] = {
      {"*Instance, name=Pile-1, part=Pile\n", "*Instance, name=Pile-1, part=Soil\n",
       pile + "part Soil is instanced a second time (first by instance Soil-1, t.inp:"},
      {"*Instance, name=Pile-1, part=Pile\n", "*Instance, name=Pile-1, part=Rock\n",
       pile + "*INSTANCE of part Rock, which no *PART above defines"},
      {"*Instance, name=Pile-1, part=Pile\n", "*Instance, name=Pile-1\n", pile + "*INSTANCE without PART="},
      {"*End Assembly\n", "*Element, type=C3D4\n1, 1, 2, 3, 4\n*End Assembly\n",
       end_assembly + "*ELEMENT inside *ASSEMBLY (elements of the assembly itself) is not read"},
      {"*End Assembly\n", "*Part, name=Extra\n*End Assembly\n", end_assembly + "*PART inside *ASSEMBLY is not read"},
      {"*End Assembly\n", "*Assembly\n", end_assembly + "a second *ASSEMBLY (or one inside another) is not read"},
      {" 4., 0., 0.\n", " 4., 0., 0.\n*Node\n1, 0, 0, 0\n",
       line_of(" 4., 0., 0., 4., 0., 1., 90.") + "*NODE inside *INSTANCE is not read"},
      {" 4., 0., 0., 4., 0., 1., 90.\n", " 4., 0., 0., 4., 0., 0., 90.\n",
       pile + "instance Pile-1: the rotation axis needs two different points"},
      {" 4., 0., 0., 4., 0., 1., 90.\n", " 4., 0., 0., 4., 0., 1.\n",
       pile + "instance Pile-1: a rotation line is 'ax, ay, az, bx, by, bz, angle' (7 fields, not 6)"},
      {"*End Assembly\n", "", assembly + "*ASSEMBLY without *END ASSEMBLY"},
      {"*End Assembly\n", "*Nset, nset=X\n7\n*End Assembly\n*Boundary\nX, 1\n",
       end_assembly + "node set X lists node 7, which the deck does not define"},
      {"*End Assembly\n", "*Nset, nset=X, instance=Nope\n7\n*End Assembly\n",
       end_assembly + "*NSET, INSTANCE=Nope: no *INSTANCE above has that name"},
      {"*Material", "*Boundary\n7, 1\n*Material",
       "node 7 is not defined (outside parts, a number names a node of the assembly; a part's node is named through "
       "its instance: Instance.number)"},
      {"*Material", "*Boundary\nPile-1.Top, 1\n*Material", "no node set PILE/TOP is defined"},
      {"*Material", "*Boundary\nPile-1.100000, 1\n*Material", "node Pile-1.100000 is not defined"},
  };
  for (const auto& c : cases) {
    const std::string message = abaqus_read_error(replaced(c.from, c.to));
    EXPECT_NE(message.find(c.message), std::string::npos) << "expected: " << c.message << "\ngot: " << message;
  }
  // A part without *END PART, and *NODE outside parts once there are some.
  EXPECT_NE(abaqus_read_error("*Part, name=A\n*Node\n1, 0, 0, 0\n").find("t.inp:1: *PART without *END PART"),
            std::string::npos);
  EXPECT_NE(
      abaqus_read_error("*Part, name=A\n*Node\n1, 0, 0, 0\n*End Part\n").find("t.inp:1: no part has an *INSTANCE"),
      std::string::npos);
  EXPECT_NE(abaqus_read_error(deck + "*Node\n1, 0, 0, 0\n").find("*NODE outside *PART in a deck with parts"),
            std::string::npos);
  EXPECT_NE(abaqus_read_error("*Node\n1, 0, 0, 0\n" + deck).find("*PART after nodes outside parts"), std::string::npos);
}

}  // namespace
}  // namespace tetsmooth
