// Second-order tets in the files that hold them: round trips through every
// MSH flavour, VTU and legacy VTK (with 3-node lines and 6-node triangles
// passed through) and TetGen; Gmsh's node order of the 10-node tet against
// VTK's, and TetGen's as libtet writes it; files mixing 4- and 10-node tets
// refused; and the formats without second-order tets (Medit, .tsm)
// refusing to write them.
#include <gtest/gtest.h>

#include <tetgen.h>

#include <cstdint>
#include <algorithm>
#include <cmath>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "input_error.hpp"
#include "mesh/errors.hpp"
#include "mesh/io/gmsh_io.hpp"
#include "mesh/io/medit_io.hpp"
#include "mesh/io/mesh_io.hpp"
#include "mesh/io/tetgen_io.hpp"
#include "mesh/io/tsm_cache.hpp"
#include "mesh/io/vtk_legacy.hpp"
#include "mesh/io/vtu_io.hpp"
#include "mesh/io/writable_check.hpp"
#include "mesh/topology.hpp"
#include "support/scratch_dir.hpp"
#include "support/test_meshes.hpp"

namespace tetsmooth {
namespace {

// A jittered second-order grid with one of its boundary faces as a 6-node
// triangle and one boundary edge as a 3-node line, their nodes pinned as a
// reader pins them.
TetMesh second_order_mesh() {
  TetMesh mesh = testing::with_midsides(testing::cube_grid(2, 0.2));
  // Tet 0's face opposite corner 3 and its edge (0, 1), with their midside
  // nodes in Gmsh's (and VTK's) order: corners, then edges (0,1), (1,2), (2,0).
  const index_t* v = &mesh.tets[0];
  const index_t* m = &mesh.midsides[0];
  mesh.extras.blocks.push_back(PassThroughBlock{"triangle6", 6, {v[0], v[1], v[2], m[0], m[1], m[2]}, {}, {}, {}});
  mesh.extras.blocks.push_back(PassThroughBlock{"line3", 3, {v[0], v[1], m[0]}, {}, {}, {}});
  mesh.fixed.assign(mesh.num_nodes(), 0);
  mark_element_nodes(mesh.extras.blocks, mesh.fixed);
  return mesh;
}

void expect_same_geometry(const TetMesh& back, const TetMesh& mesh, const std::string& format) {
  EXPECT_EQ(back.xyz, mesh.xyz) << format;
  EXPECT_EQ(back.tets, mesh.tets) << format;
  EXPECT_EQ(back.midsides, mesh.midsides) << format;
  EXPECT_EQ(back.fixed, mesh.fixed) << format;
  ASSERT_EQ(back.extras.blocks.size(), mesh.extras.blocks.size()) << format;
  for (std::size_t b = 0; b < mesh.extras.blocks.size(); ++b) {
    EXPECT_EQ(back.extras.blocks[b].kind, mesh.extras.blocks[b].kind) << format;
    EXPECT_EQ(back.extras.blocks[b].connectivity, mesh.extras.blocks[b].connectivity) << format;
  }
}

using Writer = std::function<void(const TetMesh&, std::ostream&)>;
using Reader = std::function<TetMesh(std::istream&, const std::string&)>;

TetMesh through(const TetMesh& mesh, const Writer& write, const Reader& read) {
  std::stringstream file;
  write(mesh, file);
  return read(file, "second-order");
}

TEST(SecondOrderIo, RoundTripsThroughMshVtuAndVtk) {
  const TetMesh mesh = second_order_mesh();
  for (const MshFlavour flavour : {MshFlavour::V41Ascii, MshFlavour::V41Binary, MshFlavour::V22Ascii})
    expect_same_geometry(
        through(mesh, [&](const TetMesh& m, std::ostream& out) { write_gmsh(m, out, flavour, {}); }, read_gmsh),
        mesh, "msh " + std::to_string(static_cast<int>(flavour)));
  expect_same_geometry(through(mesh, [](const TetMesh& m, std::ostream& out) { write_vtu(m, out, {}); }, read_vtu),
                       mesh, "vtu");
  expect_same_geometry(through(mesh, [](const TetMesh& m, std::ostream& out) { write_vtk(m, out, {}); }, read_vtk),
                       mesh, "vtk");
  // TetGen holds tets only: the blocks and pins stay behind.
  // Its region attribute follows the ten nodes.
  TetMesh tets_only = mesh;
  tets_only.extras.blocks.clear();
  tets_only.fixed.clear();
  for (std::size_t t = 0; t < tets_only.num_tets(); ++t)
    tets_only.extras.tet_tags.push_back(static_cast<int>(t % 3) + 7);
  std::stringstream node, ele;
  write_tetgen_node(tets_only, node);
  write_tetgen_ele(tets_only, ele);
  const TetMesh back = read_tetgen(node, "m.node", ele, "m.ele");
  expect_same_geometry(back, tets_only, "tetgen");
  EXPECT_EQ(back.extras.tet_tags, tets_only.extras.tet_tags);
}

// TetGen's -o2 files as libtet itself writes them (save_nodes and
// save_elements) read with every midside node on its own edge.
TEST(SecondOrderIo, TetGenOrderIsLibtets) {
  tetgenio in, out;
  in.numberofpoints = 60;
  in.pointlist = new REAL[3 * 60];  // tetgenio frees it
  std::uint64_t state = 12345;
  for (int i = 0; i < 3 * 60; ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    in.pointlist[i] = static_cast<double>(state >> 40) / static_cast<double>(1ULL << 24);
  }
  char switches[] = "Qo2";
  tetrahedralize(switches, &in, &out);
  ASSERT_EQ(out.numberofcorners, 10);
  const testing::ScratchDir dir("tetgen-o2");
  std::string base = (dir.path() / "o2").string();
  out.save_nodes(base.data());
  out.save_elements(base.data());
  const TetMesh mesh = read_tetgen(base + ".ele");
  ASSERT_EQ(mesh.num_tets(), static_cast<std::size_t>(out.numberoftetrahedra));
  ASSERT_EQ(mesh.midsides.size(), 6 * mesh.num_tets());
  EXPECT_LT(testing::largest_midside_offset(mesh), 1e-12);
}

// One 10-node tet over the unit corners with node tags 1..10 in the order
// the format gives them, nodes 5..10 at the midpoints of `edges` (pairs of
// corner tags).
std::string nodes_at(const std::vector<std::pair<int, int>>& edges, bool msh) {
  const double corner[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::ostringstream s;
  for (int k = 0; k < 10; ++k) {
    double p[3];
    for (int c = 0; c < 3; ++c)
      p[c] = k < 4 ? corner[k][c] : 0.5 * (corner[edges[k - 4].first - 1][c] + corner[edges[k - 4].second - 1][c]);
    if (msh) s << k + 1 << ' ';
    s << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  return s.str();
}

// Where each midside node lies, as the corners (0-based) of its edge.
void expect_midsides_on_their_edges(const TetMesh& mesh) {
  ASSERT_EQ(mesh.midsides.size(), 6u);
  for (int e = 0; e < 6; ++e) {
    const auto m = static_cast<std::size_t>(mesh.midsides[static_cast<std::size_t>(e)]);
    const auto a = static_cast<std::size_t>(mesh.tets[static_cast<std::size_t>(kTetEdges[e][0])]);
    const auto b = static_cast<std::size_t>(mesh.tets[static_cast<std::size_t>(kTetEdges[e][1])]);
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(mesh.xyz[3 * m + c], 0.5 * (mesh.xyz[3 * a + c] + mesh.xyz[3 * b + c])) << "edge " << e;
  }
}

// Gmsh's 10-node tet: edges (1,2), (2,3), (3,1), (4,1), (4,3), (4,2) in its
// 1-based corners (gmsh.model.mesh.getElementProperties(11) gives them).
const std::vector<std::pair<int, int>> kGmshEdges{{1, 2}, {2, 3}, {3, 1}, {4, 1}, {4, 3}, {4, 2}};
// VTK's quadratic tetra: the last two the other way round.
const std::vector<std::pair<int, int>> kVtkEdges{{1, 2}, {2, 3}, {3, 1}, {4, 1}, {4, 2}, {4, 3}};

TEST(SecondOrderIo, GmshTet10NodeOrderIsGmsh) {
  const std::string v41 = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 10 1 10\n3 1 0 10\n1\n2\n3\n4\n5\n6\n7\n"
                          "8\n9\n10\n" + nodes_at(kGmshEdges, false) +
                          "$EndNodes\n$Elements\n1 1 1 1\n3 1 11 1\n1 1 2 3 4 5 6 7 8 9 10\n$EndElements\n";
  std::istringstream in41(v41);
  expect_midsides_on_their_edges(read_gmsh(in41, "v41.msh"));
  const std::string v22 = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n10\n" + nodes_at(kGmshEdges, true) +
                          "$EndNodes\n$Elements\n1\n1 11 2 1 1 1 2 3 4 5 6 7 8 9 10\n$EndElements\n";
  std::istringstream in22(v22);
  const TetMesh mesh = read_gmsh(in22, "v22.msh");
  expect_midsides_on_their_edges(mesh);
  // And written back in Gmsh's order: the element line of MSH 2.2 as read.
  std::ostringstream out;
  write_gmsh(mesh, out, MshFlavour::V22Ascii, {});
  EXPECT_NE(out.str().find(" 1 2 3 4 5 6 7 8 9 10\n"), std::string::npos) << out.str();
}

TEST(SecondOrderIo, VtkQuadraticTetraNodeOrderIsVtk) {
  const std::string vtk = "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 10 double\n" +
                          nodes_at(kVtkEdges, false) + "CELLS 1 11\n10 0 1 2 3 4 5 6 7 8 9\nCELL_TYPES 1\n24\n";
  std::istringstream in(vtk);
  const TetMesh mesh = read_vtk(in, "t.vtk");
  expect_midsides_on_their_edges(mesh);
  std::ostringstream out;
  write_vtk(mesh, out, {});
  EXPECT_NE(out.str().find("10 0 1 2 3 4 5 6 7 8 9\n"), std::string::npos) << out.str();
}

TEST(SecondOrderIo, FilesMixingFourAndTenNodeTetsAreRefused) {
  const std::string msh = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n11\n" + nodes_at(kGmshEdges, true) +
                          "11 1 1 1\n$EndNodes\n$Elements\n2\n1 11 2 1 1 1 2 3 4 5 6 7 8 9 10\n"
                          "2 4 2 1 1 2 3 4 11\n$EndElements\n";
  std::istringstream in_msh(msh);
  const std::string msh_error = testing::input_error_message([&] { read_gmsh(in_msh, "mixed.msh"); }, "mixed msh");
  // Named at the line of the first tet of the other kind.
  EXPECT_NE(msh_error.find("mixed.msh:21: a 4-node tet after 10-node ones"), std::string::npos) << msh_error;

  const std::string vtk = "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 11 double\n" +
                          nodes_at(kVtkEdges, false) + "1 1 1\nCELLS 2 16\n4 1 2 3 10\n10 0 1 2 3 4 5 6 7 8 9\n" +
                          "CELL_TYPES 2\n10\n24\n";
  std::istringstream in_vtk(vtk);
  const std::string vtk_error = testing::input_error_message([&] { read_vtk(in_vtk, "mixed.vtk"); }, "mixed vtk");
  EXPECT_NE(vtk_error.find("cell 1: a 10-node tet after 4-node ones"), std::string::npos) << vtk_error;
}

// A hand-written -o2 pair (tests/data/tetgen_order2.*), also a fuzzing seed.
TEST(SecondOrderIo, TetGenFixtureReadsWithItsMidsides) {
  const TetMesh mesh = read_tetgen(testing::data_path("tetgen_order2.ele"));
  ASSERT_EQ(mesh.num_tets(), 1u);
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3}));
  // kTetEdges order: (0,1) node 7, (1,2) node 8, (0,2) node 10, (0,3) node 6,
  // (1,3) node 9, (2,3) node 5 (1-based in the file).
  EXPECT_EQ(mesh.midsides, (std::vector<index_t>{6, 7, 9, 5, 8, 4}));
  EXPECT_EQ(testing::largest_midside_offset(mesh), 0);
}

// TetGen keeps the tets in the .ele file: a bad midside node is named there.
TEST(SecondOrderIo, TetGenMidsideErrorsNameTheEleFile) {
  TetMesh mesh = testing::with_midsides(testing::cube_grid(2, 0.2));
  mesh.midsides[0] = mesh.tets[5];
  std::stringstream node, ele;
  write_tetgen_node(mesh, node);
  write_tetgen_ele(mesh, ele);
  const std::string msg =
      testing::input_error_message([&] { read_tetgen(node, "m.node", ele, "m.ele"); }, "a midside corner");
  EXPECT_EQ(msg.rfind("m.ele: node ", 0), 0u) << msg;
  EXPECT_NE(msg.find("is also a corner of tet"), std::string::npos) << msg;
}

TEST(SecondOrderIo, OtherHigherOrderTypesAreStillRefusedByName) {
  const std::string msh = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n10\n" + nodes_at(kGmshEdges, true) +
                          "$EndNodes\n$Elements\n1\n1 16 2 1 1 1 2 3 4 5 6 7 8\n$EndElements\n";
  std::istringstream in(msh);
  const std::string msg = testing::input_error_message([&] { read_gmsh(in, "q.msh"); }, "an 8-node quad");
  EXPECT_NE(msg.find("8-node quadrangle"), std::string::npos) << msg;
  EXPECT_NE(msg.find("10-node tetrahedra, 6-node triangles and 3-node lines are read"), std::string::npos) << msg;
}

// The fixture's 6-node triangles lie on its boundary: their midside nodes
// stay with their corners whatever the format keeps of the pins, so TetGen
// output, which keeps none, loses no pin that matters.
TEST(SecondOrderIo, BoundaryMidsideNodesAreNoLostPins) {
  const TetMesh mesh = read_mesh(testing::data_path("gmsh_order2_41.msh"));
  ASSERT_FALSE(mesh.fixed.empty());
  for (const std::string& note : output_losses(mesh, "out.node"))
    EXPECT_EQ(note.find("pinned node"), std::string::npos) << note;
  // A pinned midside node inside the mesh would be lost.
  TetMesh inner = mesh;
  const std::vector<std::uint8_t> boundary = find_boundary_nodes(inner.tets, inner.num_nodes(), 1, inner.midsides);
  const auto free_midside = std::find_if(inner.midsides.begin(), inner.midsides.end(), [&](index_t m) {
    return !boundary[static_cast<std::size_t>(m)];
  });
  ASSERT_NE(free_midside, inner.midsides.end());
  inner.fixed[static_cast<std::size_t>(*free_midside)] = 1;
  const std::vector<std::string> notes = output_losses(inner, "out.node");
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
    return n.find("1 pinned node will not be pinned") != std::string::npos;
  })) << (notes.empty() ? "" : notes.front());
}

TEST(SecondOrderIo, FormatsWithoutSecondOrderTetsRefuseToWriteThem) {
  const TetMesh mesh = testing::with_midsides(testing::cube_grid(2, 0.2));
  const std::vector<std::pair<std::string, Writer>> writers{{"Medit", write_medit}, {".tsm", write_cache}};
  for (const auto& [name, write] : writers) {
    std::ostringstream out;
    try {
      write(mesh, out);
      ADD_FAILURE() << name << " wrote a second-order mesh";
    } catch (const OutputError& e) {
      EXPECT_NE(std::string(e.what()).find(name + " output holds 4-node tets only"), std::string::npos) << e.what();
    }
  }
  for (const char* path : {"out.mesh", "out.tsm"}) EXPECT_THROW(check_writable(mesh, path), OutputError) << path;
  for (const char* path : {"out.msh", "out.vtu", "out.vtk", "out.node"})
    EXPECT_NO_THROW(check_writable(mesh, path)) << path;
}

}  // namespace
}  // namespace tetsmooth
