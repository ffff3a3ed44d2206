// VTU (XML) and legacy VTK: round trips that keep tets, pass-through blocks,
// tags and fixed nodes; every VTU data encoding the reader claims; fields on
// write; and errors naming file:line or the byte offset.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "mesh/errors.hpp"
#include "mesh/io/vtk_legacy.hpp"
#include "mesh/io/vtu_io.hpp"
#include "support/test_meshes.hpp"
#include "input_error.hpp"

namespace tetsmooth {
namespace {

// A cube fan with two boundary triangles (tagged), a line and a vertex
// passed through, per-tet tags and fixed nodes as a reader would set them.
TetMesh decorated_mesh() {
  TetMesh mesh = testing::cube_with_centre(0.41, 0.53, 0.47);
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) mesh.extras.tet_tags.push_back(100 + static_cast<int>(t));
  mesh.extras.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 2, 3, 0, 3, 1}, {1, 2}, {}});
  mesh.extras.blocks.push_back(PassThroughBlock{"line", 2, {4, 5}, {}, {}});
  mesh.extras.blocks.push_back(PassThroughBlock{"vertex", 1, {7}, {}, {}});
  mesh.fixed = {1, 1, 1, 1, 1, 1, 1, 1, 0};
  return mesh;
}

void expect_same_mesh(const TetMesh& back, const TetMesh& mesh) {
  EXPECT_EQ(back.xyz, mesh.xyz);
  EXPECT_EQ(back.tets, mesh.tets);
  EXPECT_EQ(back.extras.tet_tags, mesh.extras.tet_tags);
  EXPECT_EQ(back.fixed, mesh.fixed);
  ASSERT_EQ(back.extras.blocks.size(), mesh.extras.blocks.size());
  for (std::size_t b = 0; b < mesh.extras.blocks.size(); ++b) {
    const PassThroughBlock& x = back.extras.blocks[b];
    const PassThroughBlock& y = mesh.extras.blocks[b];
    EXPECT_EQ(x.kind, y.kind);
    EXPECT_EQ(x.nodes_per_element, y.nodes_per_element);
    EXPECT_EQ(x.connectivity, y.connectivity);
    // Untagged blocks of a tagged mesh come back with tag 0.
    EXPECT_EQ(x.tags, y.tags.empty() ? std::vector<int>(y.connectivity.size() / y.nodes_per_element, 0) : y.tags);
  }
}

template <class Read>
std::string read_error(Read read, const std::string& text, const std::string& source) {
  std::istringstream in(text);
  return testing::input_error_message([&] { read(in, source); }, "the reader:\n" + text.substr(0, 2000));
}

std::string vtu_error(const std::string& text) { return read_error(read_vtu, text, "mesh.vtu"); }
std::string vtk_error(const std::string& text) { return read_error(read_vtk, text, "mesh.vtk"); }

std::string file_text(const char* name) {
  std::ifstream in(testing::data_path(name), std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? s : s.replace(at, from.size(), to);
}

// Float64 values of the appended array `name` in a file this writer made
// (UInt64 byte count, little-endian data, raw encoding).
std::vector<double> appended_doubles(const std::string& text, const std::string& name) {
  const std::size_t decl = text.find("Name=\"" + name + "\"");
  const std::size_t off = text.find("offset=\"", decl);
  const std::size_t data = text.find('_', text.find("<AppendedData")) + 1 + std::stoull(text.substr(off + 8));
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, text.data() + data, 8);  // the test hosts are little-endian
  std::vector<double> values(bytes / 8);
  std::memcpy(values.data(), text.data() + data + 8, bytes);
  return values;
}

TEST(Vtu, RoundTripKeepsTetsBlocksTagsAndFixedNodes) {
  const TetMesh mesh = decorated_mesh();
  std::ostringstream out;
  write_vtu(mesh, out, {});
  std::istringstream in(out.str());
  expect_same_mesh(read_vtu(in, "mesh.vtu"), mesh);
}

TEST(Vtu, RoundTripOfAJitteredGridIsBitExact) {
  const TetMesh mesh = testing::cube_grid(4, 0.3);
  std::ostringstream out;
  write_vtu(mesh, out, {});
  std::istringstream in(out.str());
  const TetMesh back = read_vtu(in, "grid.vtu");
  EXPECT_EQ(back.xyz, mesh.xyz);
  EXPECT_EQ(back.tets, mesh.tets);
  EXPECT_TRUE(back.extras.blocks.empty());
  EXPECT_TRUE(back.fixed.empty());
}

TEST(Vtu, WritesTheDocumentedArrayTypes) {
  std::ostringstream out;
  write_vtu(decorated_mesh(), out, {});
  const std::string text = out.str();
  EXPECT_NE(text.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(text.find("<DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\""), std::string::npos);
  EXPECT_NE(text.find("type=\"Int32\" Name=\"connectivity\""), std::string::npos);
  EXPECT_NE(text.find("type=\"Int64\" Name=\"offsets\""), std::string::npos);
  EXPECT_NE(text.find("type=\"UInt8\" Name=\"types\""), std::string::npos);
  EXPECT_NE(text.find("<AppendedData encoding=\"raw\">"), std::string::npos);
}

TEST(Vtu, FieldsGoToPointAndCellDataWithNaNOnPassThroughCells) {
  const TetMesh mesh = decorated_mesh();
  MeshFields fields;
  std::vector<double> node_values, tet_values;
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) node_values.push_back(0.5 * static_cast<double>(i));
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) tet_values.push_back(-static_cast<double>(t));
  fields.node_scalars.emplace_back("height", node_values);
  fields.tet_scalars.emplace_back("q<tet>", tet_values);
  std::ostringstream out;
  write_vtu(mesh, out, fields);
  const std::string text = out.str();
  EXPECT_LT(text.find("<PointData>"), text.find("Name=\"height\""));
  EXPECT_LT(text.find("<CellData>"), text.find("Name=\"q&lt;tet&gt;\""));
  EXPECT_EQ(appended_doubles(text, "height"), node_values);
  const std::vector<double> cells = appended_doubles(text, "q&lt;tet&gt;");
  ASSERT_EQ(cells.size(), mesh.num_tets() + 4);  // 2 triangles, a line and a vertex
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) EXPECT_EQ(cells[t], tet_values[t]);
  for (std::size_t c = mesh.num_tets(); c < cells.size(); ++c) EXPECT_TRUE(std::isnan(cells[c]));
}

TEST(Vtu, RejectsFieldsOfTheWrongSize) {
  MeshFields fields;
  fields.node_scalars.emplace_back("short", std::vector<double>(3, 0.0));
  std::ostringstream out;
  EXPECT_THROW(write_vtu(testing::regular_tet(), out, fields), std::invalid_argument);
}

TEST(Vtu, ReadsEveryEncoding) {
  for (const char* name : {"vtu_ascii.vtu", "vtu_base64.vtu", "vtu_appended_base64.vtu", "vtu_bigendian_raw.vtu"}) {
    SCOPED_TRACE(name);
    const TetMesh mesh = read_vtu_file(testing::data_path(name));
    EXPECT_EQ(mesh.xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}));
    EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3, 1, 2, 3, 4}));
    ASSERT_GE(mesh.extras.blocks.size(), 1u);
    EXPECT_EQ(mesh.extras.blocks[0].kind, "triangle");
    EXPECT_EQ(mesh.fixed.size(), 5u);
  }
}

TEST(Vtu, AsciiFixtureKeepsTagsAndLines) {
  const TetMesh mesh = read_vtu_file(testing::data_path("vtu_ascii.vtu"));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{7, -3}));
  ASSERT_EQ(mesh.extras.blocks.size(), 2u);
  EXPECT_EQ(mesh.extras.blocks[0].connectivity, (std::vector<index_t>{0, 1, 2}));
  EXPECT_EQ(mesh.extras.blocks[0].tags, (std::vector<int>{2}));
  EXPECT_EQ(mesh.extras.blocks[1].kind, "line");
  EXPECT_EQ(mesh.extras.blocks[1].connectivity, (std::vector<index_t>{0, 3}));
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{1, 1, 1, 1, 0}));
}

TEST(VtuErrors, CompressedFilesAreRejectedClearly) {
  const std::string text = replaced(file_text("vtu_base64.vtu"), "header_type=\"UInt32\"",
                                    "header_type=\"UInt32\" compressor=\"vtkZLibDataCompressor\"");
  const std::string msg = vtu_error(text);
  EXPECT_NE(msg.find("mesh.vtu:3"), std::string::npos) << msg;
  EXPECT_NE(msg.find("compressed"), std::string::npos) << msg;
}

TEST(VtuErrors, TruncatedAppendedDataNamesTheByteOffset) {
  std::ostringstream out;
  write_vtu(testing::cube_with_centre(), out, {});
  const std::string text = out.str();
  const std::string msg = vtu_error(text.substr(0, text.size() - 200));
  EXPECT_NE(msg.find("mesh.vtu, byte "), std::string::npos) << msg;
  EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;
}

TEST(VtuErrors, BadAsciiValueNamesTheLine) {
  const std::string msg = vtu_error(replaced(file_text("vtu_ascii.vtu"), "0 0 1  1 1 1", "0 0 1  1 one 1"));
  EXPECT_NE(msg.find("mesh.vtu:22"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'one'"), std::string::npos) << msg;
}

TEST(VtuErrors, WrongValueCount) {
  const std::string msg = vtu_error(replaced(file_text("vtu_ascii.vtu"), "10 10 5 3", "10 10 5"));
  EXPECT_NE(msg.find("types holds 3 values, expected 4"), std::string::npos) << msg;
}

TEST(VtuErrors, UnsupportedCellTypeIsNamed) {
  const std::string msg = vtu_error(replaced(file_text("vtu_ascii.vtu"), "10 10 5 3", "10 12 5 3"));
  EXPECT_NE(msg.find("cell 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("hexahedron"), std::string::npos) << msg;
}

TEST(VtuErrors, NodeIndexOutOfRange) {
  const std::string msg = vtu_error(replaced(file_text("vtu_ascii.vtu"), "1 2 3 4\n", "1 2 3 5\n"));
  EXPECT_NE(msg.find("cell 1: node 5 out of range"), std::string::npos) << msg;
}

TEST(VtuErrors, StructuralProblems) {
  const std::string ascii = file_text("vtu_ascii.vtu");
  EXPECT_NE(vtu_error(replaced(ascii, "UnstructuredGrid\" version", "PolyData\" version")).find("not UnstructuredGrid"),
            std::string::npos);
  EXPECT_NE(vtu_error(replaced(ascii, "Name=\"offsets\"", "Name=\"offset\"")).find("no Cells offsets array"),
            std::string::npos);
  EXPECT_NE(vtu_error(replaced(ascii, "type=\"Int64\" Name=\"connectivity\"", "type=\"Float32\" Name=\"connectivity\""))
                .find("integer type"),
            std::string::npos);
  EXPECT_NE(vtu_error(replaced(ascii, "</Piece>", "</Piece><Piece NumberOfPoints=\"0\" NumberOfCells=\"0\"></Piece>"))
                .find("several pieces"),
            std::string::npos);
  EXPECT_NE(vtu_error(replaced(ascii, "</Points>", "</Cells>")).find("does not match"), std::string::npos);
  EXPECT_NE(vtu_error("just text").find("empty file"), std::string::npos);
  EXPECT_NE(
      vtu_error(replaced(ascii, "NumberOfPoints=\"5\"", "NumberOfPoints=\"99999999999\"")).find("more than the file"),
      std::string::npos);
}

TEST(VtuErrors, AppendedOffsetBeyondTheFile) {
  const std::string text = replaced(file_text("vtu_bigendian_raw.vtu"), "offset=\"0\"", "offset=\"900000\"");
  EXPECT_NE(vtu_error(text).find("beyond the end"), std::string::npos);
}

TEST(VtuErrors, BadBase64) {
  const std::string text = replaced(file_text("vtu_base64.vtu"), "LAAAAA==", "LAA*AA==");
  const std::string msg = vtu_error(text);
  EXPECT_NE(msg.find("mesh.vtu:13"), std::string::npos) << msg;
  EXPECT_NE(msg.find("base64"), std::string::npos) << msg;
}

TEST(LegacyVtk, RoundTripKeepsTetsBlocksTagsAndFixedNodes) {
  const TetMesh mesh = decorated_mesh();
  std::ostringstream out;
  write_vtk(mesh, out, {});
  std::istringstream in(out.str());
  expect_same_mesh(read_vtk(in, "mesh.vtk"), mesh);
}

TEST(LegacyVtk, RoundTripOfAJitteredGridIsExact) {
  const TetMesh mesh = testing::cube_grid(4, 0.3);
  std::ostringstream out;
  write_vtk(mesh, out, {});
  std::istringstream in(out.str());
  const TetMesh back = read_vtk(in, "grid.vtk");
  EXPECT_EQ(back.xyz, mesh.xyz);  // shortest round-trip decimal form
  EXPECT_EQ(back.tets, mesh.tets);
}

TEST(LegacyVtk, WritesFieldsAsScalars) {
  const TetMesh mesh = decorated_mesh();
  MeshFields fields;
  fields.node_scalars.emplace_back("node value", std::vector<double>(mesh.num_nodes(), 2.5));
  fields.tet_scalars.emplace_back("quality", std::vector<double>(mesh.num_tets(), 0.75));
  std::ostringstream out;
  write_vtk(mesh, out, fields);
  const std::string text = out.str();
  EXPECT_EQ(text.rfind("# vtk DataFile Version 4.2\n", 0), 0u);
  EXPECT_NE(text.find("CELL_DATA 16\nSCALARS quality double 1\nLOOKUP_TABLE default\n0.75\n"), std::string::npos);
  EXPECT_NE(text.find("0.75\nnan\nnan\nnan\nnan\nSCALARS tetsmooth:tag int 1"), std::string::npos);
  EXPECT_NE(text.find("POINT_DATA 9\nSCALARS node%20value double 1"), std::string::npos);
  std::istringstream in(text);  // and the reader skips them
  EXPECT_EQ(read_vtk(in, "mesh.vtk").tets, mesh.tets);
}

TEST(LegacyVtk, ReadsVersion51WithFieldDataAndMetadata) {
  const TetMesh mesh = read_vtk_file(testing::data_path("vtk_v51.vtk"));
  EXPECT_EQ(mesh.xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3, 1, 2, 3, 4}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{5, 6}));
  ASSERT_EQ(mesh.extras.blocks.size(), 1u);
  EXPECT_EQ(mesh.extras.blocks[0].kind, "vertex");
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{0, 0, 0, 0, 1}));
}

TEST(LegacyVtkErrors, BinaryAndOtherDatasetsAreRejected) {
  const std::string v51 = file_text("vtk_v51.vtk");
  EXPECT_NE(vtk_error(replaced(v51, "ASCII", "BINARY")).find("mesh.vtk:3: binary legacy VTK"), std::string::npos);
  EXPECT_NE(vtk_error(replaced(v51, "UNSTRUCTURED_GRID", "POLYDATA")).find("mesh.vtk:4: DATASET POLYDATA"),
            std::string::npos);
  EXPECT_NE(vtk_error("hello\n").find("mesh.vtk:1: not a legacy VTK file"), std::string::npos);
}

TEST(LegacyVtkErrors, BadTokensNameTheLine) {
  const std::string v51 = file_text("vtk_v51.vtk");
  const std::string msg = vtk_error(replaced(v51, "0 0 1 1 1 1", "0 0 1 1 1 x"));
  EXPECT_NE(msg.find("mesh.vtk:10"), std::string::npos) << msg;
  EXPECT_NE(vtk_error(replaced(v51, "TIME 1 1 double\n0.25\n", "TIME 1 1 double\n")).find("mesh.vtk:"),
            std::string::npos);
  EXPECT_NE(vtk_error(replaced(v51, "VECTORS flow", "BLOBS flow")).find("unknown keyword 'BLOBS'"), std::string::npos);
}

TEST(LegacyVtkErrors, InconsistentCells) {
  const std::string v42 =
      "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n"
      "0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 6\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
  EXPECT_NE(vtk_error(v42).find("mesh.vtk:8: CELLS declared 6 values, the cells hold 5"), std::string::npos);
  EXPECT_NE(
      vtk_error(replaced(replaced(v42, "CELLS 1 6", "CELLS 1 5"), "CELL_TYPES 1\n10\n", "")).find("no CELL_TYPES"),
      std::string::npos);
  EXPECT_NE(vtk_error(replaced(replaced(v42, "CELLS 1 6", "CELLS 1 5"), "CELL_TYPES 1\n10", "CELL_TYPES 1\n5"))
                .find("mesh.vtk:9: cell 0: triangle with 4 nodes"),
            std::string::npos);
}

}  // namespace
}  // namespace tetsmooth
