// Medit .mesh: references, pass-through elements, RequiredVertices and
// Corners as fixed nodes, repeated sections, exact round trips, and errors
// naming file:line.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

#include "mesh/errors.hpp"
#include "mesh/io/gmsh_io.hpp"
#include "mesh/io/medit_io.hpp"
#include "mesh/io/vtk_legacy.hpp"
#include "mesh/io/vtu_io.hpp"
#include "support/scratch_dir.hpp"
#include "support/test_meshes.hpp"
#include "input_error.hpp"

namespace tetsmooth {
namespace {

TetMesh read_text(const std::string& text) {
  std::istringstream in(text);
  return read_medit(in, "t.mesh");
}

std::string write_text(const TetMesh& mesh) {
  std::ostringstream out;
  write_medit(mesh, out);
  return out.str();
}

std::string read_error(const std::string& text) {
  return testing::input_error_message([&] { read_text(text); }, "read_medit:\n" + text);
}

// Lines 3-8 the vertices, 9-11 the tet, 12 End.
const char* kMinimal =
    "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
    "Tetrahedra\n1\n1 2 3 4 0\nEnd\n";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

TEST(MeditIo, ReadsReferencesBlocksAndPinnedVertices) {
  const TetMesh mesh = read_medit_file(testing::data_path("medit_bipyramid.mesh"));
  ASSERT_EQ(mesh.num_nodes(), 5u);
  EXPECT_EQ(mesh.xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0.3, 0.3, -1}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3, 0, 2, 1, 4}));
  EXPECT_EQ(mesh.extras.node_markers, (std::vector<int>{0, 1, 1, 2, 0}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{7, 8}));
  ASSERT_EQ(mesh.extras.blocks.size(), 2u);
  EXPECT_EQ(mesh.extras.blocks[0].kind, "triangle");  // spelt "triangles" in the file
  EXPECT_EQ(mesh.extras.blocks[0].connectivity, (std::vector<index_t>{1, 2, 3}));
  EXPECT_EQ(mesh.extras.blocks[0].tags, (std::vector<int>{3}));
  EXPECT_EQ(mesh.extras.blocks[1].kind, "line");
  EXPECT_EQ(mesh.extras.blocks[1].connectivity, (std::vector<index_t>{1, 2}));
  EXPECT_EQ(mesh.extras.corner_nodes, (std::vector<std::int32_t>{3}));
  EXPECT_EQ(mesh.extras.required_nodes, (std::vector<std::int32_t>{4}));
  // Node 4 is pinned only by RequiredVertices, node 3 by the triangle and
  // the corner; node 0 is free.
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{0, 1, 1, 1, 1}));
  ASSERT_EQ(mesh.extras.raw_sections.size(), 1u);
  EXPECT_EQ(mesh.extras.raw_sections[0], (std::pair<std::string, std::string>{"Ridges", "1\n1\n"}));
}

TEST(MeditIo, RoundTripKeepsEverything) {
  const TetMesh mesh = read_medit_file(testing::data_path("medit_bipyramid.mesh"));
  const TetMesh back = read_text(write_text(mesh));
  EXPECT_EQ(back.xyz, mesh.xyz);
  EXPECT_EQ(back.tets, mesh.tets);
  EXPECT_EQ(back.extras.node_markers, mesh.extras.node_markers);
  EXPECT_EQ(back.extras.tet_tags, mesh.extras.tet_tags);
  EXPECT_EQ(back.extras.corner_nodes, mesh.extras.corner_nodes);
  EXPECT_EQ(back.extras.required_nodes, mesh.extras.required_nodes);
  EXPECT_EQ(back.extras.raw_sections, mesh.extras.raw_sections);
  EXPECT_EQ(back.fixed, mesh.fixed);
  ASSERT_EQ(back.extras.blocks.size(), mesh.extras.blocks.size());
  for (std::size_t i = 0; i < mesh.extras.blocks.size(); ++i) {
    EXPECT_EQ(back.extras.blocks[i].kind, mesh.extras.blocks[i].kind);
    EXPECT_EQ(back.extras.blocks[i].connectivity, mesh.extras.blocks[i].connectivity);
    EXPECT_EQ(back.extras.blocks[i].tags, mesh.extras.blocks[i].tags);
  }
}

TEST(MeditIo, CoordinatesRoundTripExactly) {
  const TetMesh mesh = testing::cube_grid(3, 0.3);  // jittered: full mantissas
  const TetMesh back = read_text(write_text(mesh));
  EXPECT_EQ(back.xyz, mesh.xyz);
  EXPECT_EQ(back.tets, mesh.tets);
  EXPECT_EQ(back.extras.node_markers, std::vector<int>(mesh.num_nodes(), 0));
  EXPECT_EQ(back.extras.tet_tags, std::vector<int>(mesh.num_tets(), 0));
  EXPECT_TRUE(back.fixed.empty()) << "no node is pinned";
}

// Medit has no point elements: Gmsh points become RequiredVertices, so
// they stay pinned; physical tags become references.
TEST(MeditIo, GmshPointsBecomeRequiredVertices) {
  const TetMesh gmsh = read_gmsh_file(testing::data_path("gmsh_sparse41.msh"));
  const TetMesh back = read_text(write_text(gmsh));
  EXPECT_EQ(back.xyz, gmsh.xyz);
  EXPECT_EQ(back.tets, gmsh.tets);
  EXPECT_EQ(back.extras.tet_tags, gmsh.extras.tet_tags);
  EXPECT_EQ(back.extras.required_nodes, (std::vector<std::int32_t>{0}));
  ASSERT_EQ(back.extras.blocks.size(), 1u);
  EXPECT_EQ(back.extras.blocks[0].connectivity, gmsh.extras.blocks[1].connectivity);
  EXPECT_EQ(back.extras.blocks[0].tags, gmsh.extras.blocks[1].tags);
  EXPECT_EQ(back.fixed, gmsh.fixed);
}

// Identifier and Geometry hold one string each: kept and written back after
// Dimension, whatever section they followed.
TEST(MeditIo, StringSectionsAreKept) {
  const TetMesh mesh = read_text(
      replaced(replaced(kMinimal, "Vertices\n", "Identifier\n\"slope   model, v2\"\nVertices\n"), "End\n",
               "Geometry\nsupport.mesh\nEnd\n"));
  EXPECT_EQ(mesh.num_tets(), 1u);
  ASSERT_EQ(mesh.extras.raw_sections.size(), 2u);
  EXPECT_EQ(mesh.extras.raw_sections[0],
            (std::pair<std::string, std::string>{"Identifier", "\"slope model, v2\"\n"}));
  EXPECT_EQ(mesh.extras.raw_sections[1], (std::pair<std::string, std::string>{"Geometry", "support.mesh\n"}));
  const std::string text = write_text(mesh);
  EXPECT_EQ(text.substr(0, text.find("\nVertices")),
            "MeshVersionFormatted 2\n\nDimension 3\n\nIdentifier\n\"slope model, v2\"\n\nGeometry\nsupport.mesh\n");
  EXPECT_EQ(read_text(text).extras.raw_sections, mesh.extras.raw_sections);
  const std::string open = read_error(replaced(kMinimal, "End\n", "Identifier \"no end\nEnd\n"));
  EXPECT_NE(open.find("expected the closing quote of the string"), std::string::npos) << open;
}

// meshio writes one section per cell block (per Gmsh entity): sections of
// one kind are read as one, in file order, each element with its reference,
// and written back as one.
TEST(MeditIo, RepeatedElementSectionsAreReadAsOne) {
  const TetMesh mesh = read_text(
      "MeshVersionFormatted 2\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n0.3 0.3 -1 0\n"
      "Triangles\n1\n2 3 4 101\nTetrahedra\n1\n1 2 3 4 10\nEdges\n1\n2 3 5\nTriangles\n0\n"
      "Triangles\n2\n1 2 4 102\n1 3 2 103\nTETRAHEDRA\n1\n1 3 2 5 11\nEdges\n1\n3 4 6\nEnd\n");
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3, 0, 2, 1, 4}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{10, 11}));
  ASSERT_EQ(mesh.extras.blocks.size(), 2u);
  EXPECT_EQ(mesh.extras.blocks[0].kind, "triangle");
  EXPECT_EQ(mesh.extras.blocks[0].connectivity, (std::vector<index_t>{1, 2, 3, 0, 1, 3, 0, 2, 1}));
  EXPECT_EQ(mesh.extras.blocks[0].tags, (std::vector<int>{101, 102, 103}));
  EXPECT_EQ(mesh.extras.blocks[1].kind, "line");
  EXPECT_EQ(mesh.extras.blocks[1].connectivity, (std::vector<index_t>{1, 2, 2, 3}));
  EXPECT_EQ(mesh.extras.blocks[1].tags, (std::vector<int>{5, 6}));
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{1, 1, 1, 1, 0}));

  const std::string text = write_text(mesh);
  EXPECT_EQ(occurrences(text, "\nTetrahedra\n"), 1u) << text;
  EXPECT_EQ(occurrences(text, "\nTriangles\n"), 1u) << text;
  EXPECT_EQ(occurrences(text, "\nEdges\n"), 1u) << text;
  const TetMesh back = read_text(text);
  EXPECT_EQ(back.tets, mesh.tets);
  EXPECT_EQ(back.extras.tet_tags, mesh.extras.tet_tags);
  ASSERT_EQ(back.extras.blocks.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(back.extras.blocks[i].kind, mesh.extras.blocks[i].kind);
    EXPECT_EQ(back.extras.blocks[i].connectivity, mesh.extras.blocks[i].connectivity);
    EXPECT_EQ(back.extras.blocks[i].tags, mesh.extras.blocks[i].tags);
  }
}

// RequiredVertices and Corners append too; a vertex listed twice, in one
// section or two, is kept once.
TEST(MeditIo, RepeatedVertexListsAppend) {
  const TetMesh mesh = read_text(replaced(
      kMinimal, "End\n", "RequiredVertices\n2\n1 2\nCorners\n1\n3\nRequiredVertices\n3\n2 4 4\nCorners 1 3\nEnd\n"));
  EXPECT_EQ(mesh.extras.required_nodes, (std::vector<std::int32_t>{0, 1, 3}));
  EXPECT_EQ(mesh.extras.corner_nodes, (std::vector<std::int32_t>{2}));
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{1, 1, 1, 1}));
  const std::string text = write_text(mesh);
  EXPECT_EQ(occurrences(text, "\nRequiredVertices\n"), 1u) << text;
  EXPECT_EQ(occurrences(text, "\nCorners\n"), 1u) << text;
  const TetMesh back = read_text(text);
  EXPECT_EQ(back.extras.required_nodes, mesh.extras.required_nodes);
  EXPECT_EQ(back.extras.corner_nodes, mesh.extras.corner_nodes);
  EXPECT_EQ(back.fixed, mesh.fixed);
}

// Corners pin their vertices as RequiredVertices do, on their own: here
// no other section pins a node. Written back, they stay Corners (not
// RequiredVertices too) and stay pinned.
TEST(MeditIo, CornersAloneFixTheirVertices) {
  const TetMesh mesh = read_text(replaced(kMinimal, "End\n", "Corners\n2\n4 2\nEnd\n"));
  EXPECT_EQ(mesh.extras.corner_nodes, (std::vector<std::int32_t>{3, 1}));
  EXPECT_TRUE(mesh.extras.required_nodes.empty());
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{0, 1, 0, 1}));
  const TetMesh back = read_text(write_text(mesh));
  EXPECT_EQ(back.extras.corner_nodes, mesh.extras.corner_nodes);
  EXPECT_TRUE(back.extras.required_nodes.empty());
  EXPECT_EQ(back.fixed, mesh.fixed);
}

struct BadText {
  const char* from;
  const char* to;
  const char* where;
  const char* what;
};

TEST(MeditIo, BadInputNamesFileAndLine) {
  const BadText cases[] = {
      {"1 2 3 4 0\n", "1 2 3 5 0\n", "t.mesh:11:", "vertex index 5 is outside 1..4"},
      {"1 2 3 4 0\n", "0 2 3 4 0\n", "t.mesh:11:", "vertex index 0 is outside 1..4"},
      {"1 0 0 0\n", "nan 0 0 0\n", "t.mesh:6:", "non-finite vertex coordinate"},
      {"0 1 0 0\n", "0 inf 0 0\n", "t.mesh:7:", "non-finite vertex coordinate"},
      {"End\n", "Foo 1\nEnd\n", "t.mesh:12:", "unknown or unsupported Medit keyword 'Foo'"},
      // File text is echoed escaped and cut short: a control byte, a long keyword.
      {"End\n", "F\x1doo 1\nEnd\n", "t.mesh:12:", "unknown or unsupported Medit keyword 'F\\x1doo'"},
      {"End\n", "Foooooooooooooooooooooooooooooooooooooooooooooo 1\nEnd\n", "t.mesh:12:",
       "keyword 'Fooooooooooooooooooooooooooooooooooooooo...'"},
      {"Vertices\n4\n", "Vertices\n3\n", "t.mesh:8:", "unexpected number '0' where a keyword belongs"},
      {"Tetrahedra\n1\n", "Tetrahedra\n2\n", "t.mesh:12:", "expected an integer vertex index, found 'End'"},
      {"Tetrahedra\n1\n1 2 3 4 0\n", "Tetrahedra\n0\n", "t.mesh:11:", "no Tetrahedra"},
      {"Dimension 3", "Dimension 2", "t.mesh:2:", "only 3-D meshes are read"},
      {"MeshVersionFormatted 2", "MeshVersionFormatted 9", "t.mesh:1:", "unsupported MeshVersionFormatted 9"},
      {"MeshVersionFormatted 2\n", "Vertices\n", "t.mesh:1:", "not a Medit mesh"},
      {"Vertices\n4\n", "Tetrahedra\n1\n1 2 3 4 0\nVertices\n4\n", "t.mesh:3:", "Tetrahedra before Vertices"},
      {"End\n", "Vertices 0\nEnd\n", "t.mesh:12:",
       "a second Vertices section: the elements' vertex indices would be ambiguous"},
      {"End\n", "Dimension 3\nEnd\n", "t.mesh:12:", "a second Dimension section: the header comes once"},
      {"End\n", "Identifier a\nIdentifier b\nEnd\n", "t.mesh:13:",
       "a second Identifier section: only element sections, RequiredVertices and Corners may repeat"},
      {"Vertices\n4\n", "Corners\n1\n1\nVertices\n4\n", "t.mesh:3:", "Corners before Vertices"},
      {"1 2 3 4 0\n", "1 2 3 4 0.5\n", "t.mesh:11:", "expected an integer tetrahedron reference, found '0.5'"},
  };
  for (const BadText& c : cases) {
    const std::string message = read_error(replaced(kMinimal, c.from, c.to));
    EXPECT_NE(message.find(c.where), std::string::npos) << message;
    EXPECT_NE(message.find(c.what), std::string::npos) << message;
  }
  const std::string text = kMinimal;
  const std::string truncated = read_error(text.substr(0, text.find("1 2 3 4 0")));
  EXPECT_NE(truncated.find("t.mesh:10: unexpected end of file, expected vertex index"), std::string::npos) << truncated;
}

TEST(MeditIo, WriterRefusesWhatMeditCannotHold) {
  TetMesh mesh = testing::regular_tet();
  PassThroughBlock polygon;
  polygon.kind = "polygon";
  polygon.nodes_per_element = 5;
  polygon.connectivity = {0, 1, 2, 3, 0};
  mesh.extras.blocks.push_back(polygon);
  EXPECT_THROW(write_text(mesh), OutputError);
  EXPECT_THROW(write_text(TetMesh{}), OutputError);
}

TEST(MeditIo, FileWriterReplacesTargetOrThrows) {
  const testing::ScratchDir dir("medit");
  const TetMesh mesh = testing::cube_grid(2);
  const std::string path = dir.file("out.mesh");
  write_medit_file(mesh, path);
  EXPECT_EQ(read_medit_file(path).xyz, mesh.xyz);
  EXPECT_THROW(write_medit_file(mesh, dir.file("missing/out.mesh")), OutputError);
}

// An empty element section leaves no block behind, so a format that has no
// place for its kind (VTK: no hexahedra here) still takes the mesh.
TEST(MeditIo, EmptyElementSectionMakesNoBlock) {
  const TetMesh mesh = read_text(
      "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n"
      "Tetrahedra\n1\n1 2 3 4 1\nHexahedra\n0\nEnd\n");
  EXPECT_TRUE(mesh.extras.blocks.empty());
  EXPECT_TRUE(mesh.fixed.empty());
  std::ostringstream vtu, vtk;
  write_vtu(mesh, vtu, {});
  write_vtk(mesh, vtk, {});
  std::istringstream in(vtu.str());
  EXPECT_EQ(read_vtu(in, "m.vtu").tets, mesh.tets);
}

// A node pinned by nothing Medit has a section for (a VTU's tetsmooth:fixed,
// say) goes out as a RequiredVertices entry, so the pin survives a round trip.
TEST(MeditIo, PinnedNodesWithoutElementsBecomeRequiredVertices) {
  TetMesh mesh = testing::cube_grid(2);
  mesh.fixed.assign(mesh.num_nodes(), 0);
  mesh.fixed[5] = 1;
  const TetMesh back = read_text(write_text(mesh));
  EXPECT_EQ(back.extras.required_nodes, (std::vector<std::int32_t>{5}));
  EXPECT_EQ(back.fixed, mesh.fixed);
}

// Node index num_nodes() is one past the last node: refused before writing,
// whether a tet, a vertex list or a pass-through element names it.
TEST(MeditIo, WriterRefusesNodeIndexOnePastTheEnd) {
  const TetMesh good = testing::regular_tet();
  const auto n = static_cast<index_t>(good.num_nodes());
  TetMesh tet = good;
  tet.tets[3] = n;
  EXPECT_THROW(write_text(tet), OutputError);
  TetMesh required = good;
  required.extras.required_nodes = {n};
  EXPECT_THROW(write_text(required), OutputError);
  TetMesh edge = good;
  edge.extras.blocks.push_back(PassThroughBlock{"line", 2, {0, n}, {}, {}, {}});
  EXPECT_THROW(write_text(edge), OutputError);
}

// A leading '+' is accepted as Fortran-style writers emit it, but "+-1" and
// "++1" are not numbers.
TEST(MeditIo, DoubledSignsAreNotNumbers) {
  EXPECT_EQ(read_text(replaced(kMinimal, "1 2 3 4 0", "1 2 3 4 +7")).extras.tet_tags, (std::vector<int>{7}));
  for (const char* bad : {"+-7", "++7"}) {
    const std::string message = read_error(replaced(kMinimal, "1 2 3 4 0", std::string("1 2 3 4 ") + bad));
    EXPECT_NE(message.find(std::string("t.mesh:11: expected an integer tetrahedron reference, found '") + bad + "'"),
              std::string::npos)
        << message;
  }
}

// Sections kept verbatim are checked first: an index of an annotating
// section is 1-based, a vector component finite.
TEST(MeditIo, KeptSectionsRefuseZeroIndicesAndNonFiniteValues) {
  const BadText cases[] = {
      {"End\n", "Ridges\n1\n0\nEnd\n", "t.mesh:14:", "expected a positive index, found '0'"},
      {"End\n", "Normals\n1\n0 inf 1\nEnd\n", "t.mesh:14:", "expected a finite number, found 'inf'"},
  };
  for (const BadText& c : cases) {
    const std::string message = read_error(replaced(kMinimal, c.from, c.to));
    EXPECT_NE(message.find(c.where), std::string::npos) << message;
    EXPECT_NE(message.find(c.what), std::string::npos) << message;
  }
}

// A quoted string that starts with a space begins with the token '"': the
// quote alone opens the string, it does not close it.
TEST(MeditIo, StringOpeningWithALoneQuoteReadsOnToItsClose) {
  const TetMesh mesh = read_text(replaced(kMinimal, "Vertices\n", "Identifier\n\" spaced name\"\nVertices\n"));
  ASSERT_EQ(mesh.extras.raw_sections.size(), 1u);
  EXPECT_EQ(mesh.extras.raw_sections[0], (std::pair<std::string, std::string>{"Identifier", "\" spaced name\"\n"}));
}

// A block whose nodes per element are not its kind's would be written out
// of step with the section's element size.
TEST(MeditIo, WriterRefusesABlockOfTheWrongElementSize) {
  TetMesh mesh = testing::regular_tet();
  mesh.extras.blocks.push_back(PassThroughBlock{"triangle", 4, {0, 1, 2, 3}, {}, {}, {}});
  EXPECT_THROW(write_text(mesh), OutputError);
}

// Versions 1 to 4 differ only in binary widths; a negative count is refused
// where it stands rather than read as a huge one.
TEST(MeditIo, UnknownVersionsAndNegativeCountsAreRefused) {
  const BadText cases[] = {
      {"MeshVersionFormatted 2", "MeshVersionFormatted 5", "t.mesh:1:", "unsupported MeshVersionFormatted 5"},
      {"Vertices\n4\n", "Vertices\n-4\n", "t.mesh:4:", "number of vertices -4 is out of range"},
  };
  for (const BadText& c : cases) {
    const std::string message = read_error(replaced(kMinimal, c.from, c.to));
    EXPECT_NE(message.find(c.where), std::string::npos) << message;
    EXPECT_NE(message.find(c.what), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace tetsmooth
