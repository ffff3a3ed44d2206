// VTU (XML) and legacy VTK: round trips that keep tets, pass-through blocks,
// tags and fixed nodes; every VTU data encoding the reader claims, zlib and
// LZMA compressed ones included; fields on write; region tags under other
// tools' array names and the notes on arrays not carried over; and errors
// naming file:line or the byte offset.
#include <gtest/gtest.h>
#include <lzma.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "input_error.hpp"
#include "mesh/errors.hpp"
#include "mesh/io/base64.hpp"
#include "mesh/io/inflate.hpp"
#include "mesh/io/mesh_io.hpp"
#include "mesh/io/vtk_cells.hpp"
#include "mesh/io/vtk_legacy.hpp"
#include "mesh/io/vtu_io.hpp"
#include "mesh/io/writable_check.hpp"
#include "mesh/io/xml_scan.hpp"
#include "mesh/region_interfaces.hpp"
#include "support/scratch_dir.hpp"
#include "support/test_meshes.hpp"

namespace tetsmooth {
namespace {

// A cube fan with two boundary triangles (tagged), a line and a vertex
// passed through, per-tet tags and fixed nodes as a reader would set them.
TetMesh decorated_mesh() {
  TetMesh mesh = testing::cube_with_centre(0.41, 0.53, 0.47);
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) mesh.extras.tet_tags.push_back(100 + static_cast<int>(t));
  mesh.extras.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 2, 3, 0, 3, 1}, {1, 2}, {}, {}});
  mesh.extras.blocks.push_back(PassThroughBlock{"line", 2, {4, 5}, {}, {}, {}});
  mesh.extras.blocks.push_back(PassThroughBlock{"vertex", 1, {7}, {}, {}, {}});
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

// Fixed nodes that no cell pins: no pass-through block at all (so only the
// tetsmooth:fixed array can fix them, on a mesh the cells left unfixed) and
// one node in no cell. Both formats keep them fixed, and only them.
TetMesh fixed_without_blocks() {
  TetMesh mesh = testing::cube_with_centre(0.41, 0.53, 0.47);
  mesh.xyz.insert(mesh.xyz.end(), {2, 2, 2});  // in no tet
  mesh.fixed.assign(mesh.num_nodes(), 0);
  mesh.fixed[2] = mesh.fixed[9] = 1;
  return mesh;
}

TEST(Vtu, FixedNodesOutsideAnyBlockRoundTrip) {
  const TetMesh mesh = fixed_without_blocks();
  std::ostringstream out;
  write_vtu(mesh, out, {});
  std::istringstream in(out.str());
  const TetMesh back = read_vtu(in, "mesh.vtu");
  EXPECT_TRUE(back.extras.blocks.empty());
  EXPECT_EQ(back.fixed, mesh.fixed);
}

TEST(LegacyVtk, FixedNodesOutsideAnyBlockRoundTrip) {
  const TetMesh mesh = fixed_without_blocks();
  std::ostringstream out;
  write_vtk(mesh, out, {});
  std::istringstream in(out.str());
  const TetMesh back = read_vtk(in, "mesh.vtk");
  EXPECT_TRUE(back.extras.blocks.empty());
  EXPECT_EQ(back.fixed, mesh.fixed);
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
  // vtu_*_meshio.vtu: as meshio 5 writes by default (zlib), and with LZMA
  // and UInt64 headers (tests/data/vtu_compressed_make.py).
  for (const char* name : {"vtu_ascii.vtu", "vtu_base64.vtu", "vtu_appended_base64.vtu", "vtu_bigendian_raw.vtu",
                           "vtu_zlib_meshio.vtu", "vtu_lzma_meshio.vtu"}) {
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

TEST(VtuErrors, OtherCompressorsAreRefusedByName) {
  for (const char* compressor : {"vtkLZ4DataCompressor", "vtkSomeNewDataCompressor"}) {
    SCOPED_TRACE(compressor);
    const std::string text = replaced(file_text("vtu_base64.vtu"), "header_type=\"UInt32\"",
                                      std::string("header_type=\"UInt32\" compressor=\"") + compressor + "\"");
    const std::string msg = vtu_error(text);
    EXPECT_EQ(msg.rfind(std::string("mesh.vtu:3: compressed VTU data (") + compressor + ") is not supported", 0), 0u)
        << msg;
    // What to do instead.
    EXPECT_NE(msg.find("vtkZLibDataCompressor"), std::string::npos) << msg;
    EXPECT_NE(msg.find("uncompressed"), std::string::npos) << msg;
  }
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
  const std::string msg = vtu_error(replaced(file_text("vtu_ascii.vtu"), "10 10 5 3", "10 25 5 3"));
  EXPECT_NE(msg.find("cell 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unsupported VTK cell type 25 (quadratic hexahedron)"), std::string::npos) << msg;
}

// Bricks, wedges and pyramids (from Gmsh, Abaqus, Nastran or FLAC3D files)
// pass through VTU and legacy VTK as VTK's cells 12, 13 and 14, their nodes
// in the order they came.
TEST(Vtu, HexahedraWedgesAndPyramidsRoundTrip) {
  TetMesh mesh = testing::cube_with_centre(0.41, 0.53, 0.47);
  mesh.extras.blocks.push_back(PassThroughBlock{"hexahedron", 8, {0, 1, 2, 3, 4, 5, 6, 7}, {3}, {}, {}});
  mesh.extras.blocks.push_back(PassThroughBlock{"wedge", 6, {0, 1, 2, 4, 5, 6, 1, 2, 3, 5, 6, 7}, {4, 5}, {}, {}});
  mesh.extras.blocks.push_back(PassThroughBlock{"pyramid", 5, {0, 1, 2, 3, 8}, {6}, {}, {}});
  mesh.fixed = {1, 1, 1, 1, 1, 1, 1, 1, 1};
  for (std::size_t t = 0; t < mesh.num_tets(); ++t) mesh.extras.tet_tags.push_back(1);
  std::ostringstream vtu, vtk;
  write_vtu(mesh, vtu, {});
  write_vtk(mesh, vtk, {});
  EXPECT_NE(vtk.str().find("\nCELL_TYPES 16\n10\n"), std::string::npos) << vtk.str();
  EXPECT_NE(vtk.str().find("\n12\n13\n13\n14\n"), std::string::npos) << vtk.str();
  // VTK winds a wedge's first triangle the other way: (0 1 2 | 4 5 6) is
  // written (0 2 1 | 4 6 5).
  EXPECT_NE(vtk.str().find("\n6 0 2 1 4 6 5\n"), std::string::npos) << vtk.str();
  std::istringstream vtu_in(vtu.str()), vtk_in(vtk.str());
  expect_same_mesh(read_vtu(vtu_in, "mesh.vtu"), mesh);
  expect_same_mesh(read_vtk(vtk_in, "mesh.vtk"), mesh);
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
  EXPECT_NE(vtu_error("just text").find("not a VTK XML file"), std::string::npos);
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

// RFC 4648's own examples, and groups padded after one character, which
// cannot encode a byte ("Q===" would otherwise decode to nothing and pass).
TEST(Base64, DecodesTheRfcExamplesAndRejectsPaddingAfterOneCharacter) {
  const auto decoded = [](std::string_view text) {
    std::vector<unsigned char> out;
    std::size_t bad_at = 0;
    EXPECT_TRUE(base64_decode(text, out, bad_at)) << text;
    return std::string(out.begin(), out.end());
  };
  EXPECT_EQ(decoded("Zg=="), "f");
  EXPECT_EQ(decoded("Zm8="), "fo");
  EXPECT_EQ(decoded("Zm9v"), "foo");
  EXPECT_EQ(decoded("Zm9v\nYmFy"), "foobar");
  std::vector<unsigned char> out;
  std::size_t bad_at = 0;
  EXPECT_FALSE(base64_decode("Zm9vQ===", out, bad_at));
  EXPECT_EQ(bad_at, 5u);
}

// Padding may close any group (VTK encodes a block's header apart from its
// data), but nothing may follow '=' inside a group, and a last group of two
// or three characters is cut short: both are corrupt data, not a shorter
// array.
TEST(Base64, RejectsDataAfterPaddingAndAnIncompleteLastGroup) {
  std::vector<unsigned char> out;
  std::size_t bad_at = 0;
  EXPECT_TRUE(base64_decode("Zg==Zm8=", out, bad_at));
  EXPECT_EQ(std::string(out.begin(), out.end()), "ffo");
  EXPECT_FALSE(base64_decode("Zg=v", out, bad_at));
  EXPECT_EQ(bad_at, 3u);
  for (const char* cut : {"Zm9vZm", "Zm9vZm9"}) {
    EXPECT_FALSE(base64_decode(cut, out, bad_at)) << cut;
    EXPECT_EQ(bad_at, 4u) << cut;
  }
}

// A zlib stream cut short is named as truncated, the usual cause (a file
// copied or downloaded in part), rather than as a size mismatch.
TEST(Inflate, TruncatedZlibStreamIsNamedAsSuch) {
  const std::string text(1000, 'x');
  std::vector<unsigned char> packed(compressBound(text.size()));
  uLongf size = packed.size();
  ASSERT_EQ(compress2(packed.data(), &size, reinterpret_cast<const Bytef*>(text.data()), text.size(), 9), Z_OK);
  std::vector<unsigned char> out;
  EXPECT_EQ(inflate_stream(Codec::Zlib, packed.data(), size, text.size(), out), "");
  EXPECT_EQ(std::string(out.begin(), out.end()), text);
  out.clear();
  EXPECT_EQ(inflate_stream(Codec::Zlib, packed.data(), size - 4, text.size(), out),
            "truncated: the zlib stream ends early");
}

// Bytes after the end of a stream are not part of it: a block's compressed
// size that runs past its stream is named, for either codec.
TEST(Inflate, BytesAfterTheStreamAreNamed) {
  const std::string text(1000, 'x');
  std::vector<unsigned char> zlib(compressBound(text.size()) + 4);
  uLongf zsize = zlib.size();
  ASSERT_EQ(compress2(zlib.data(), &zsize, reinterpret_cast<const Bytef*>(text.data()), text.size(), 9), Z_OK);
  std::vector<unsigned char> xz(lzma_stream_buffer_bound(text.size()) + 4);
  std::size_t xsize = 0;
  ASSERT_EQ(lzma_easy_buffer_encode(6, LZMA_CHECK_CRC64, nullptr, reinterpret_cast<const uint8_t*>(text.data()),
                                    text.size(), xz.data(), &xsize, xz.size() - 4),
            LZMA_OK);
  std::vector<unsigned char> out;
  EXPECT_EQ(inflate_stream(Codec::Zlib, zlib.data(), zsize + 3, text.size(), out),
            "3 bytes follow the end of the zlib stream");
  out.clear();
  EXPECT_EQ(inflate_stream(Codec::Xz, xz.data(), xsize + 1, text.size(), out),
            "1 byte follows the end of the xz stream");
}

// The header's size bounds what a stream may yield: a stream that yields
// more is stopped there (a small file must not expand without limit), and
// one that yields less is as wrong, for either codec.
TEST(Inflate, StreamsYieldExactlyTheSizeTheHeaderSays) {
  const std::string text(100000, 'x');
  std::vector<unsigned char> zlib(compressBound(text.size()));
  uLongf zsize = zlib.size();
  ASSERT_EQ(compress2(zlib.data(), &zsize, reinterpret_cast<const Bytef*>(text.data()), text.size(), 9), Z_OK);
  std::vector<unsigned char> xz(lzma_stream_buffer_bound(text.size()));
  std::size_t xsize = 0;
  ASSERT_EQ(lzma_easy_buffer_encode(6, LZMA_CHECK_CRC64, nullptr, reinterpret_cast<const uint8_t*>(text.data()),
                                    text.size(), xz.data(), &xsize, xz.size()),
            LZMA_OK);
  for (const auto& [codec, data, size] :
       {std::tuple{Codec::Zlib, zlib.data(), std::size_t{zsize}}, std::tuple{Codec::Xz, xz.data(), xsize}}) {
    std::vector<unsigned char> out;
    EXPECT_EQ(inflate_stream(codec, data, size, 10, out), "decompresses to more than the 10 bytes the header says");
    EXPECT_LE(out.size(), 11u);
    out.clear();
    EXPECT_EQ(inflate_stream(codec, data, size, 200000, out), "decompresses to 100000 bytes, the header says 200000");
  }
}

// Every reader validates what it returns (mesh/validate.hpp): a VTU with a
// non-finite coordinate is an input error, not a mesh that poisons the
// smoother's arithmetic.
TEST(VtuErrors, NonFiniteCoordinateIsRejected) {
  TetMesh mesh = testing::regular_tet();
  mesh.xyz[4] = std::numeric_limits<double>::quiet_NaN();
  std::ostringstream out;
  write_vtu(mesh, out, {});
  const std::string msg = vtu_error(out.str());
  EXPECT_NE(msg.find("node 1 has a non-finite coordinate y"), std::string::npos) << msg;
}

// A block holding more bytes than the piece declares is a file whose counts
// disagree: reading only the declared part would silently drop data.
TEST(VtuErrors, ABlockLargerThanTheDeclaredCountIsRejected) {
  TetMesh mesh = testing::regular_tet();
  mesh.xyz.insert(mesh.xyz.end(), {5, 5, 5});  // a fifth node, in no tet
  std::ostringstream out;
  write_vtu(mesh, out, {});
  const std::string msg = vtu_error(replaced(out.str(), "NumberOfPoints=\"5\"", "NumberOfPoints=\"4\""));
  EXPECT_NE(msg.find("block holds 120 bytes, expected 96"), std::string::npos) << msg;
}

// A negative count is named as such, not as a size beyond the file.
TEST(VtuErrors, NegativeCountsInThePieceAreNamed) {
  const std::string ascii = file_text("vtu_ascii.vtu");
  for (const char* attribute : {"NumberOfPoints", "NumberOfCells"}) {
    const std::string at = std::string(attribute) + "=\"";
    const std::size_t value = ascii.find(at) + at.size();
    std::string text = ascii;
    text.insert(value, "-");
    const std::string msg = vtu_error(text);
    EXPECT_NE(msg.find(std::string("missing or bad ") + attribute), std::string::npos) << msg;
  }
}

// The first tag of `text`, scanned as a reader would.
XmlTag first_tag(const std::string& text) {
  XmlScanner xml(text, "x.xml");
  XmlTag tag;
  EXPECT_TRUE(xml.next(tag)) << text;
  return tag;
}

// Names with XML's special characters survive a write and a scan: the writer
// escapes all five, and the scanner decodes them back.
TEST(XmlScan, EscapedAttributeValuesDecodeBack) {
  const std::string name = "a&b<c>d\"e'f&amp;";
  EXPECT_EQ(xml_escape(name), "a&amp;b&lt;c&gt;d&quot;e&apos;f&amp;amp;");
  const XmlTag tag = first_tag("<DataArray Name=\"" + xml_escape(name) + "\"/>");
  ASSERT_NE(tag.attribute("Name"), nullptr);
  EXPECT_EQ(*tag.attribute("Name"), name);
}

// Character references: a NUL is not an XML character, and a huge number is
// an input error naming the reference, not an exception from the number
// conversion (which the command line would report as an internal error).
TEST(XmlScan, BadCharacterReferencesAreInputErrors) {
  EXPECT_EQ(*first_tag("<X a=\"&#65;&#x42;\"/>").attribute("a"), "AB");
  for (const char* ref : {"&#0;", "&#x0;", "&#99999999999999999999;", "&#x110000;"}) {
    const std::string msg =
        testing::input_error_message([&] { first_tag(std::string("<X a=\"") + ref + "\"/>"); }, ref);
    EXPECT_NE(msg.find("bad character reference"), std::string::npos) << ref << ": " << msg;
  }
}

// Code points at the edges of UTF-8's 1-, 2-, 3- and 4-byte forms, and the
// shortest references, one decimal digit ("&#9;", a tab, is valid XML).
TEST(XmlScan, CharacterReferencesBecomeUtf8) {
  EXPECT_EQ(*first_tag("<X a=\"&#9;&#xA;\"/>").attribute("a"), "\t\n");
  EXPECT_EQ(*first_tag("<X a=\"&#x7F;&#x80;&#x7FF;&#x800;&#xFFFF;&#x10000;&#x10FFFF;\"/>").attribute("a"),
            "\x7F\xC2\x80\xDF\xBF\xE0\xA0\x80\xEF\xBF\xBF\xF0\x90\x80\x80\xF4\x8F\xBF\xBF");
}

// A value in single quotes may hold double quotes, and the other way round.
TEST(XmlScan, EitherQuoteDelimitsAValue) {
  const XmlTag tag = first_tag("<X a='say \"hi\"' b=\"it's\"/>");
  EXPECT_EQ(*tag.attribute("a"), "say \"hi\"");
  EXPECT_EQ(*tag.attribute("b"), "it's");
}

// An end tag carries no attributes: "</DataArray a=\"1\">" is malformed.
TEST(XmlScan, AttributesInAnEndTagAreAnError) {
  const std::string msg = testing::input_error_message([] { first_tag("</X a=\"1\">"); }, "end tag");
  EXPECT_NE(msg.find("unexpected characters in the end tag 'X'"), std::string::npos) << msg;
}

// An attribute needs a name: '<X ="1"/>' is malformed, not an attribute
// called "".
TEST(XmlScan, AnAttributeWithoutANameIsAnError) {
  const std::string msg = testing::input_error_message([] { first_tag("<X =\"1\"/>"); }, "nameless attribute");
  EXPECT_NE(msg.find("malformed attribute in element 'X'"), std::string::npos) << msg;
}

// A comment ends at "-->", not at the first '>' inside it (ParaView and
// hand-edited files put arbitrary text in comments).
TEST(XmlScan, CommentsMayHoldAngleBrackets) {
  const XmlTag tag = first_tag("<!-- a > b, <c> --><VTKFile type=\"UnstructuredGrid\">");
  EXPECT_EQ(tag.name, "VTKFile");
}

// Appended data start after '_'; without it the reader would take the first
// data byte for the marker and read every value one byte off.
TEST(VtuErrors, AppendedDataWithoutTheUnderscoreIsRejected) {
  std::ostringstream out;
  write_vtu(testing::regular_tet(), out, {});
  const std::string msg = vtu_error(replaced(out.str(), "\n   _", "\n   "));
  EXPECT_NE(msg.find("AppendedData must start with '_'"), std::string::npos) << msg;
}

// Inline base64 whose data stop short of what the block header says is
// truncated; the reader must not read past what was decoded.
TEST(VtuErrors, InlineBlockShorterThanItsHeaderIsTruncated) {
  const std::string msg = vtu_error(replaced(file_text("vtu_base64.vtu"), "AwAAAA==CgoF", "AwAAAA=="));
  EXPECT_NE(msg.find("truncated: the file ends inside the block of 3 bytes"), std::string::npos) << msg;
}

// Elements VTU cannot hold are refused before anything is written, and the
// refusal names the file the user asked for.
TEST(VtuErrors, UnwritableBlocksNameTheFileAndWriteNothing) {
  const testing::ScratchDir dir("vtu");
  const std::string path = dir.file("blocks.vtu");
  TetMesh mesh = testing::cube_with_centre();
  // An 8-node quad, which no reader passes through, stands for a kind VTU has
  // no cell type for here.
  mesh.extras.blocks.push_back(PassThroughBlock{"quad8", 8, {0, 1, 2, 3, 4, 5, 6, 7}, {}, {}, {}});
  try {
    write_vtu_file(mesh, path, {});
    ADD_FAILURE() << "an 8-node quad was written to VTU";
  } catch (const OutputError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write '" + path + "'"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

// Windows editors start UTF-8 files with a byte order mark; it is not
// content, and the file reads as without it.
TEST(Vtu, AUtf8ByteOrderMarkIsSkipped) {
  const std::string ascii = file_text("vtu_ascii.vtu");
  std::istringstream plain(ascii), marked("\xEF\xBB\xBF" + ascii);
  expect_same_mesh(read_vtu(marked, "mesh.vtu"), read_vtu(plain, "mesh.vtu"));
}

// A raw appended file cut inside the last block's byte count: the reader
// names the truncated header instead of reading a count past the end.
TEST(VtuErrors, FileCutInsideABlockHeaderIsTruncated) {
  std::ostringstream out;
  write_vtu(testing::regular_tet(), out, {});
  const std::string text = out.str();
  const std::size_t types = text.find("Name=\"types\"");
  const std::size_t offset_at = text.find("offset=\"", types) + 8;
  const std::size_t offset = std::stoul(text.substr(offset_at));
  const std::size_t data = text.find("\n   _") + 5;
  const std::string msg = vtu_error(text.substr(0, data + offset + 3));  // 3 of the 8 header bytes
  EXPECT_NE(msg.find("truncated block header"), std::string::npos) << msg;
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

// BINARY files are read: test_io_vtk_binary.cpp.
TEST(LegacyVtkErrors, OtherModesAndDatasetsAreRejected) {
  const std::string v51 = file_text("vtk_v51.vtk");
  EXPECT_NE(vtk_error(replaced(v51, "ASCII", "TEXT")).find("mesh.vtk:3: expected ASCII or BINARY, found 'TEXT'"),
            std::string::npos);
  EXPECT_NE(vtk_error(replaced(v51, "UNSTRUCTURED_GRID", "POLYDATA")).find("mesh.vtk:4: DATASET 'POLYDATA' is not supported"),
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

// Region tags under other names, and notes on the arrays not carried over -----

TetMesh vtu_from_text(const std::string& text) {
  std::istringstream in(text);
  return read_vtu(in, "mesh.vtu");
}

TetMesh vtk_from_text(const std::string& text) {
  std::istringstream in(text);
  return read_vtk(in, "mesh.vtk");
}

// "<source>:<line>:", the start of an error message naming the line of
// `text` where `needle` is.
std::string line_of(const std::string& text, const std::string& needle, const std::string& source) {
  const std::size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  return source + ":" + std::to_string(1 + std::count(text.begin(), text.begin() + at, '\n')) + ":";
}

// A CellData array for vtu_ascii.vtu's four cells (two tets, a triangle, a line).
std::string vtu_cell_array(const std::string& name, const std::string& values, const char* type = "Int32") {
  return std::string("<DataArray type=\"") + type + "\" Name=\"" + name + "\" format=\"ascii\">" + values +
         "</DataArray>\n";
}

// vtu_ascii.vtu with its CellData replaced by `arrays`.
std::string vtu_with_cell_data(const std::string& arrays) {
  const std::string text = file_text("vtu_ascii.vtu");
  const std::size_t begin = text.find("<CellData>") + std::strlen("<CellData>\n");
  const std::size_t end = text.find("</CellData>");
  return text.substr(0, begin) + arrays + text.substr(end);
}

// The tags of vtu_ascii.vtu's cells, and of vtk_v51.vtk's below, wherever
// a test has put them.
void expect_vtu_fixture_tags(const TetMesh& mesh) {
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{7, -3}));
  ASSERT_EQ(mesh.extras.blocks.size(), 2u);
  EXPECT_EQ(mesh.extras.blocks[0].tags, (std::vector<int>{2}));  // the triangle
  EXPECT_EQ(mesh.extras.blocks[1].tags, (std::vector<int>{0}));  // the line
}

void expect_vtk_fixture_tags(const TetMesh& mesh) {
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{5, 6}));
  ASSERT_EQ(mesh.extras.blocks.size(), 1u);
  EXPECT_EQ(mesh.extras.blocks[0].tags, (std::vector<int>{0}));  // the vertex
}

// The names of region tag arrays, in the order of preference documented in
// vtk_arrays.hpp and README.md.
const char* const kTagNames[] = {"tetsmooth:tag", "gmsh:physical", "medit:ref", "CellEntityIds"};

const std::string kTemperatureNote = "point data array 'temperature' is ignored and not written back";

TEST(VtkTagArrays, VtuTakesTagsUnderEveryKnownName) {
  for (const char* name : kTagNames) {
    SCOPED_TRACE(name);
    const TetMesh mesh = vtu_from_text(vtu_with_cell_data(vtu_cell_array(name, "7 -3 2 0")));
    expect_vtu_fixture_tags(mesh);
    EXPECT_EQ(mesh.extras.read_notes, std::vector<std::string>{kTemperatureNote});
  }
}

TEST(VtkTagArrays, LegacyVtkTakesTagsUnderEveryKnownName) {
  for (const char* name : kTagNames) {
    SCOPED_TRACE(name);
    const std::string text =
        replaced(file_text("vtk_v51.vtk"), "SCALARS tetsmooth:tag", std::string("SCALARS ") + name);
    expect_vtk_fixture_tags(vtk_from_text(text));
  }
}

// As meshio writes a Gmsh mesh: gmsh:physical, the region tags, and
// gmsh:geometrical, the entity tags, which keep volumes of one physical
// group apart; both Int32.
TEST(VtkTagArrays, VtuFromMeshioKeepsGmshPhysicalGroupsAndEntitiesOfTetsAndTriangles) {
  const std::string arrays =
      vtu_cell_array("gmsh:physical", "7 -3 2 0") + vtu_cell_array("gmsh:geometrical", "1 2 4 9");
  const TetMesh mesh = vtu_from_text(vtu_with_cell_data(arrays));
  expect_vtu_fixture_tags(mesh);
  EXPECT_EQ(mesh.extras.blocks[0].kind, "triangle");
  EXPECT_EQ(mesh.extras.tet_entity_tags, (std::vector<int>{1, 2}));
  EXPECT_EQ(mesh.extras.blocks[0].entity_tags, (std::vector<int>{4}));
  EXPECT_EQ(mesh.extras.blocks[1].entity_tags, (std::vector<int>{9}));
  EXPECT_EQ(mesh.extras.read_notes, std::vector<std::string>{kTemperatureNote});
  // Entity tags alone, and entity tags that are not whole numbers or do not
  // match the cells, as region tags are.
  const TetMesh alone = vtu_from_text(vtu_with_cell_data(vtu_cell_array("gmsh:geometrical", "1 2 4 9")));
  EXPECT_TRUE(alone.extras.tet_tags.empty());
  EXPECT_EQ(alone.extras.tet_entity_tags, (std::vector<int>{1, 2}));
  const std::string half = vtu_with_cell_data(vtu_cell_array("gmsh:geometrical", "1 2.5 4 9", "Float64"));
  EXPECT_NE(vtu_error(half).find("cell 1: gmsh:geometrical value 2.5 is not an integer"), std::string::npos)
      << vtu_error(half);
  const std::string short_array = vtu_with_cell_data(vtu_cell_array("gmsh:geometrical", "1 2 4"));
  EXPECT_NE(vtu_error(short_array).find("gmsh:geometrical"), std::string::npos) << vtu_error(short_array);
}

// What tetsmooth writes of entity tags, VTU and VTK read back: the tets',
// and the blocks' (0 for a block without them).
TEST(VtkTagArrays, EntityTagsRoundTripThroughVtuAndVtk) {
  TetMesh mesh = testing::cube_with_centre();
  mesh.extras.tet_entity_tags = {1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2};
  mesh.extras.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 2, 3, 0, 3, 1}, {}, {7, 8}, {}});
  mesh.extras.blocks.push_back(PassThroughBlock{"line", 2, {0, 1}, {}, {}, {}});
  for (MeshFormat format : {MeshFormat::Vtu, MeshFormat::Vtk}) {
    SCOPED_TRACE(format_name(format));
    std::ostringstream out;
    format == MeshFormat::Vtu ? write_vtu(mesh, out, {}) : write_vtk(mesh, out, {});
    const TetMesh back = format == MeshFormat::Vtu ? vtu_from_text(out.str()) : vtk_from_text(out.str());
    EXPECT_EQ(back.extras.tet_entity_tags, mesh.extras.tet_entity_tags);
    ASSERT_EQ(back.extras.blocks.size(), 2u);
    EXPECT_EQ(back.extras.blocks[0].entity_tags, (std::vector<int>{7, 8}));
    EXPECT_EQ(back.extras.blocks[1].entity_tags, (std::vector<int>{0}));
    EXPECT_TRUE(back.extras.tet_tags.empty());
  }
  // Entity tags on the blocks alone: the tets' read back as 0.
  TetMesh blocks_only = mesh;
  blocks_only.extras.tet_entity_tags.clear();
  std::ostringstream out;
  write_vtu(blocks_only, out, {});
  const TetMesh back = vtu_from_text(out.str());
  EXPECT_EQ(back.extras.tet_entity_tags, std::vector<int>(mesh.num_tets(), 0));
  ASSERT_EQ(back.extras.blocks.size(), 2u);
  EXPECT_EQ(back.extras.blocks[0].entity_tags, (std::vector<int>{7, 8}));
  // A mesh without entity tags gets no such array.
  std::ostringstream plain;
  write_vtu(testing::cube_with_centre(), plain, {});
  EXPECT_EQ(plain.str().find("gmsh:geometrical"), std::string::npos);
}

// Two tets and a triangle with their Gmsh tags as meshio writes them: cell
// data as FIELD arrays of CELL_DATA, not SCALARS.
const std::string kMeshioVtk =
    "# vtk DataFile Version 4.2\nmeshio\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n"
    "0 0 0 1 0 0 0 1 0 0 0 1 1 1 1\nCELLS 3 14\n4 0 1 2 3\n4 1 2 3 4\n3 0 1 2\nCELL_TYPES 3\n10\n10\n5\n"
    "POINT_DATA 5\nFIELD FieldData 1\ngmsh:dim_tags 3 5 vtktypeint64\n0 1 0 0 2 0 0 3 0 0 4 0 3 1 0\n"
    "CELL_DATA 3\nFIELD FieldData 2\ngmsh:physical 1 3 vtktypeint64\n7 8 3\n"
    "gmsh:geometrical 1 3 vtktypeint64\n1 1 6\n";

TEST(VtkTagArrays, LegacyVtkFromMeshioKeepsGmshPhysicalGroupsFromFieldData) {
  const std::string& text = kMeshioVtk;
  const TetMesh mesh = vtk_from_text(text);
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{7, 8}));
  EXPECT_EQ(mesh.extras.tet_entity_tags, (std::vector<int>{1, 1}));
  ASSERT_EQ(mesh.extras.blocks.size(), 1u);
  EXPECT_EQ(mesh.extras.blocks[0].kind, "triangle");
  EXPECT_EQ(mesh.extras.blocks[0].tags, (std::vector<int>{3}));
  EXPECT_EQ(mesh.extras.blocks[0].entity_tags, (std::vector<int>{6}));
  // gmsh:dim_tags, padded to 3 components as meshio writes legacy VTK: the
  // entity each node is classified on.
  EXPECT_EQ(mesh.extras.node_entity_dims, (std::vector<int>{0, 0, 0, 0, 3}));
  EXPECT_EQ(mesh.extras.node_entity_tags, (std::vector<int>{1, 2, 3, 4, 1}));
  EXPECT_TRUE(mesh.extras.read_notes.empty());
}

// vtu_ascii.vtu with a gmsh:dim_tags point array of `components` values a
// point (Int32, or `type`) in place of its temperature.
std::string vtu_with_dim_tags(const std::string& values, int components = 2, const char* type = "Int32") {
  const std::string text = file_text("vtu_ascii.vtu");
  const std::size_t begin = text.find("<PointData");
  const std::size_t end = text.find("</PointData>") + std::strlen("</PointData>");
  return text.substr(0, begin) + "<PointData><DataArray type=\"" + type +
         "\" Name=\"gmsh:dim_tags\" NumberOfComponents=\"" + std::to_string(components) + "\" format=\"ascii\">" +
         values + "</DataArray></PointData>" + text.substr(end);
}

// meshio keeps the entity each node of an MSH 4.1 file is classified on as
// gmsh:dim_tags, (dimension, tag) pairs: 2 components in VTU, padded to 3
// in legacy VTK. Read as MSH 4.1's classification; values that are no
// dimension, no whole tag, or a padding other than 0 are refused, naming
// the point.
TEST(VtkTagArrays, GmshDimTagsClassifyTheNodes) {
  const TetMesh mesh = vtu_from_text(vtu_with_dim_tags("0 1 1 4 2 7 3 1 3 1"));
  EXPECT_EQ(mesh.extras.node_entity_dims, (std::vector<int>{0, 1, 2, 3, 3}));
  EXPECT_EQ(mesh.extras.node_entity_tags, (std::vector<int>{1, 4, 7, 1, 1}));
  EXPECT_TRUE(mesh.extras.read_notes.empty());
  const TetMesh padded = vtu_from_text(vtu_with_dim_tags("0 1 0 1 4 0 2 7 0 3 1 0 3 1 0", 3));
  EXPECT_EQ(padded.extras.node_entity_dims, mesh.extras.node_entity_dims);
  EXPECT_EQ(padded.extras.node_entity_tags, mesh.extras.node_entity_tags);
  const struct {
    std::string text, message;
  } bad[] = {
      {vtu_with_dim_tags("0 1 1 4 4 7 3 1 3 1"), "point 2: gmsh:dim_tags value 4 is no dimension 0 to 3"},
      {vtu_with_dim_tags("0 1 1 4 2 7.5 3 1 3 1", 2, "Float64"),
       "point 2: gmsh:dim_tags value 7.5 is no whole entity tag in the range of int"},
      {vtu_with_dim_tags("0 1 0 1 4 0 2 7 1 3 1 0 3 1 0", 3), "point 2: gmsh:dim_tags value 1 in its third component"},
  };
  for (const auto& b : bad) EXPECT_NE(vtu_error(b.text).find(b.message), std::string::npos) << vtu_error(b.text);
  // With one component it is no classification: an array like any other.
  const TetMesh other = vtu_from_text(vtu_with_dim_tags("0 1 2 3 3", 1));
  EXPECT_TRUE(other.extras.node_entity_dims.empty());
  EXPECT_EQ(other.extras.read_notes,
            std::vector<std::string>{"point data array 'gmsh:dim_tags' is ignored and not written back"});
}

// A Gmsh mesh (tests/data/gmsh_layers_make.py) whose two volumes share one
// physical group and hold an embedded point, and meshio's VTU and VTK of
// it: read from any of the three, the same volumes and classification,
// and so the same 4 interface nodes and 1 point that stay in place.
TEST(VtkTagArrays, MeshioCopiesOfAGmshMeshKeepItsVolumesAndEmbeddedPoint) {
  const TetMesh msh = read_mesh(testing::data_path("gmsh_layers41.msh"));
  const std::vector<std::uint8_t> pinned = region_interface_nodes(msh);
  ASSERT_EQ(std::count(pinned.begin(), pinned.end(), kOnInterface), 4);
  ASSERT_EQ(std::count(pinned.begin(), pinned.end(), kOnGmshFeature), 1);
  for (const char* copy : {"vtu_meshio_gmsh.vtu", "vtk_meshio_gmsh.vtk"}) {
    SCOPED_TRACE(copy);
    const TetMesh m = read_mesh(testing::data_path(copy));
    ASSERT_EQ(m.xyz.size(), msh.xyz.size());
    for (std::size_t i = 0; i < m.xyz.size(); ++i)  // meshio's ASCII keeps 12 digits
      EXPECT_NEAR(m.xyz[i], msh.xyz[i], 1e-11) << "coordinate " << i;
    EXPECT_EQ(m.tets, msh.tets);
    EXPECT_EQ(m.extras.tet_tags, msh.extras.tet_tags);
    EXPECT_EQ(m.extras.tet_entity_tags, msh.extras.tet_entity_tags);
    EXPECT_EQ(m.extras.node_entity_dims, msh.extras.node_entity_dims);
    EXPECT_EQ(m.extras.node_entity_tags, msh.extras.node_entity_tags);
    EXPECT_EQ(region_interface_nodes(m), pinned);
  }
}

// The meshio copies name the points, curves and surfaces of the Gmsh mesh
// in gmsh:dim_tags alone (they hold tets only): MSH 4.1 written from them
// declares those entities, so the nodes come back classified as in the MSH
// file and the same nodes stay in place, with no warning of a loss.
TEST(VtkTagArrays, MeshioCopiesOfAGmshMeshGiveItsClassificationToMsh41) {
  const TetMesh msh = read_mesh(testing::data_path("gmsh_layers41.msh"));
  const testing::ScratchDir dir("vtk_to_msh41");
  for (const char* copy : {"vtu_meshio_gmsh.vtu", "vtk_meshio_gmsh.vtk"}) {
    SCOPED_TRACE(copy);
    const TetMesh m = read_mesh(testing::data_path(copy));
    ASSERT_TRUE(m.extras.blocks.empty());
    for (const std::string& loss : output_losses(m, "out.msh"))
      EXPECT_EQ(loss.find("Gmsh's entities keep in place"), std::string::npos) << loss;
    for (MeshFormat format : {MeshFormat::Msh41, MeshFormat::Msh41Binary}) {
      const std::string file = (dir.path() / "out.msh").string();
      write_mesh(m, file, format);
      const TetMesh back = read_mesh(file);
      EXPECT_EQ(back.extras.node_entity_dims, msh.extras.node_entity_dims);
      EXPECT_EQ(back.extras.node_entity_tags, msh.extras.node_entity_tags);
      EXPECT_EQ(region_interface_nodes(back), region_interface_nodes(msh));
    }
  }
}

TEST(VtkTagArrays, VtuPrefersTheEarlierNameWhereverItStands) {
  for (std::size_t preferred = 0; preferred < std::size(kTagNames); ++preferred) {
    for (std::size_t other = preferred + 1; other < std::size(kTagNames); ++other) {
      SCOPED_TRACE(std::string(kTagNames[preferred]) + " over " + kTagNames[other]);
      // The less preferred array comes first in the file.
      const std::string arrays =
          vtu_cell_array(kTagNames[other], "1 1 1 1") + vtu_cell_array(kTagNames[preferred], "7 -3 2 0");
      const TetMesh mesh = vtu_from_text(vtu_with_cell_data(arrays));
      expect_vtu_fixture_tags(mesh);
      EXPECT_EQ(mesh.extras.read_notes.back(),
                "cell data array '" + std::string(kTagNames[other]) + "' is ignored and not written back");
    }
  }
}

TEST(VtkTagArrays, LegacyVtkPrefersTheEarlierNameWhereverItStands) {
  const std::string v51 = file_text("vtk_v51.vtk");
  // CellEntityIds before tetsmooth:tag, as a FIELD array after it, and
  // gmsh:physical before medit:ref.
  const std::string before = replaced(v51, "CELL_DATA 3\n", "CELL_DATA 3\nSCALARS CellEntityIds int\n1 1 1\n");
  expect_vtk_fixture_tags(vtk_from_text(before));
  const std::string after = replaced(v51, "VECTORS flow", "FIELD f 1\ngmsh:physical 1 3 int\n1 1 1\nVECTORS flow");
  expect_vtk_fixture_tags(vtk_from_text(after));
  const std::string neither = replaced(replaced(v51, "SCALARS tetsmooth:tag", "SCALARS gmsh:physical"), "VECTORS flow",
                                       "SCALARS medit:ref int\n1 1 1\nVECTORS flow");
  const TetMesh mesh = vtk_from_text(neither);
  expect_vtk_fixture_tags(mesh);
  ASSERT_EQ(mesh.extras.read_notes.size(), 3u);  // point, cell and field data (TIME)
  EXPECT_EQ(mesh.extras.read_notes[1], "cell data arrays 'medit:ref', 'flow' are ignored and not written back");
}

TEST(VtkTagArrays, WholeNumbersOfAFloatingPointTypeAreTags) {
  const TetMesh vtu = vtu_from_text(vtu_with_cell_data(vtu_cell_array("CellEntityIds", "7.0 -3 2e0 0", "Float64")));
  expect_vtu_fixture_tags(vtu);
  const std::string v51 = file_text("vtk_v51.vtk");
  expect_vtk_fixture_tags(
      vtk_from_text(replaced(replaced(v51, "tetsmooth:tag int", "gmsh:physical double"), "5 6 0", "5.0 6 0")));
}

TEST(VtkTagArraysErrors, NonIntegerTagsNameTheFileTheArrayAndTheCell) {
  const std::string vtu = vtu_with_cell_data(vtu_cell_array("gmsh:physical", "7 -3.5 2 0", "Float32"));
  std::string msg = vtu_error(vtu);
  EXPECT_EQ(msg.rfind(line_of(vtu, "Name=\"gmsh:physical\"", "mesh.vtu"), 0), 0u) << msg;
  EXPECT_NE(msg.find("cell 1: gmsh:physical value -3.5 is not an integer"), std::string::npos) << msg;

  // In an integer-typed ascii array too, and NaN.
  msg = vtu_error(vtu_with_cell_data(vtu_cell_array("CellEntityIds", "7 -3 nan 0")));
  EXPECT_NE(msg.find("cell 2: CellEntityIds value nan is not an integer"), std::string::npos) << msg;

  const std::string vtk =
      replaced(replaced(file_text("vtk_v51.vtk"), "tetsmooth:tag int", "medit:ref float"), "5 6 0", "5 6 0.25");
  msg = vtk_error(vtk);
  EXPECT_EQ(msg.rfind(line_of(vtk, "SCALARS medit:ref", "mesh.vtk"), 0), 0u) << msg;
  EXPECT_NE(msg.find("cell 2: medit:ref value 0.25 is not an integer"), std::string::npos) << msg;
}

TEST(VtkTagArraysErrors, TagsOutsideTheRangeOfIntOrOfTheWrongCount) {
  std::string msg = vtu_error(vtu_with_cell_data(vtu_cell_array("CellEntityIds", "7 -3 4294967296 0", "Int64")));
  EXPECT_NE(msg.find("cell 2: CellEntityIds value 4294967296 is out of range"), std::string::npos) << msg;
  const std::string vtk = replaced(kMeshioVtk, "gmsh:physical 1 3 vtktypeint64\n7 8 3", "gmsh:physical 1 2 int\n7 8");
  msg = vtk_error(vtk);
  EXPECT_EQ(msg.rfind(line_of(vtk, "gmsh:physical", "mesh.vtk"), 0), 0u) << msg;
  EXPECT_NE(msg.find("gmsh:physical has 2 values for 3 cells"), std::string::npos) << msg;
}

TEST(VtkTagArrays, EveryArrayNotCarriedOverIsNotedOncePerKind) {
  // vtk_v51.vtk: a cell VECTORS array, and point SCALARS, NORMALS and FIELD
  // arrays; the dataset's own FIELD (TIME) is field data, noted last.
  const TetMesh vtk = read_vtk_file(testing::data_path("vtk_v51.vtk"));
  EXPECT_EQ(
      vtk.extras.read_notes,
      (std::vector<std::string>{"point data arrays 'pressure head', 'n', 'a', 'b' are ignored and not written back",
                                "cell data array 'flow' is ignored and not written back",
                                "field data array 'TIME' is ignored and not written back"}));
  // A tag or fixed-node array of the wrong kind or shape is an ordinary one.
  const std::string arrays = vtu_cell_array("tetsmooth:tag", "7 -3 2 0") +
                             vtu_cell_array("tetsmooth:fixed", "0 0 0 0") +
                             "<DataArray type=\"Int32\" Name=\"gmsh:physical\" NumberOfComponents=\"2\" "
                             "format=\"ascii\">1 1 1 1 1 1 1 1</DataArray>\n";
  const TetMesh vtu = vtu_from_text(vtu_with_cell_data(arrays));
  expect_vtu_fixture_tags(vtu);
  EXPECT_EQ(
      vtu.extras.read_notes,
      (std::vector<std::string>{
          kTemperatureNote, "cell data arrays 'tetsmooth:fixed', 'gmsh:physical' are ignored and not written back"}));
}

TEST(VtkTagArrays, BothReadersNoteTheSameArraysOfTheSameMesh) {
  const TetMesh mesh = decorated_mesh();
  MeshFields fields;
  fields.node_scalars.emplace_back("node value", std::vector<double>(mesh.num_nodes(), 1.0));
  fields.tet_scalars.emplace_back("stress", std::vector<double>(mesh.num_tets(), 2.0));
  fields.tet_scalars.emplace_back("strain", std::vector<double>(mesh.num_tets(), 3.0));
  const std::vector<std::string> notes{"point data array 'node value' is ignored and not written back",
                                       "cell data arrays 'stress', 'strain' are ignored and not written back"};
  std::ostringstream vtu, vtk;
  write_vtu(mesh, vtu, fields);
  write_vtk(mesh, vtk, fields);
  const TetMesh from_vtu = vtu_from_text(vtu.str());
  const TetMesh from_vtk = vtk_from_text(vtk.str());
  EXPECT_EQ(from_vtu.extras.read_notes, notes);
  EXPECT_EQ(from_vtk.extras.read_notes, notes);
  expect_same_mesh(from_vtu, mesh);
  expect_same_mesh(from_vtk, mesh);
}

TEST(VtkTagArrays, TheFieldsTetsmoothWritesAreNotNoted) {
  // The command line writes per-tet "quality" and per-node "boundary" with
  // every VTU/VTK file and computes them afresh on each write.
  const TetMesh mesh = decorated_mesh();
  MeshFields fields;
  fields.node_scalars.emplace_back("boundary", std::vector<double>(mesh.num_nodes(), 1.0));
  fields.tet_scalars.emplace_back("quality", std::vector<double>(mesh.num_tets(), 0.5));
  std::ostringstream vtu, vtk;
  write_vtu(mesh, vtu, fields);
  write_vtk(mesh, vtk, fields);
  EXPECT_TRUE(vtu_from_text(vtu.str()).extras.read_notes.empty());
  EXPECT_TRUE(vtk_from_text(vtk.str()).extras.read_notes.empty());
}

// Compressed VTU: files built here in the layout of mesh/io/vtu_blocks.hpp
// (zlib's compress2 and liblzma's xz encoder) from the arrays of a file that
// write_vtu made, and read back -----------------------------------------------

enum class VtuForm { Inline, InlineOneRun, AppendedRaw, AppendedBase64 };

struct Packing {
  VtuForm form = VtuForm::AppendedRaw;
  bool lzma = false;
  bool uint64_header = false;
  bool big_endian = false;
  std::size_t block_size = 32768;  // VTK's and meshio's
  bool zero_full_last = true;      // #p-size 0 for a full last block, as VTK writes; meshio writes its size

  std::size_t header_bytes() const { return uint64_header ? 8 : 4; }
};

std::string describe(const Packing& p) {
  const char* forms[] = {"inline", "inline, one base64 run", "appended raw", "appended base64"};
  return std::string(forms[static_cast<int>(p.form)]) + (p.lzma ? ", lzma" : ", zlib") +
         (p.uint64_header ? ", UInt64" : ", UInt32") + (p.big_endian ? ", big-endian" : ", little-endian") +
         ", blocks of " + std::to_string(p.block_size) + (p.zero_full_last ? "" : ", full last block sized");
}

std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* const kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    unsigned group = 0;
    for (std::size_t k = 0; k < 3; ++k) group = group << 8 | (k < n ? bytes[i + k] : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kAlphabet[group >> (18 - 6 * k) & 63] : '=';
  }
  return out;
}

std::vector<unsigned char> compress_block(const unsigned char* p, std::size_t n, bool lzma) {
  std::vector<unsigned char> out;
  if (lzma) {
    out.resize(lzma_stream_buffer_bound(n));
    std::size_t size = 0;
    EXPECT_EQ(lzma_easy_buffer_encode(6, LZMA_CHECK_CRC64, nullptr, p, n, out.data(), &size, out.size()), LZMA_OK);
    out.resize(size);
  } else {
    uLongf size = compressBound(n);
    out.resize(size);
    EXPECT_EQ(compress2(out.data(), &size, p, n, Z_DEFAULT_COMPRESSION), Z_OK);
    out.resize(size);
  }
  return out;
}

void put_item(std::vector<unsigned char>& out, std::uint64_t v, const Packing& p) {
  const std::size_t n = p.header_bytes();
  for (std::size_t i = 0; i < n; ++i)
    out.push_back(static_cast<unsigned char>(v >> 8 * (p.big_endian ? n - 1 - i : i)));
}

// One array's values compressed: the header, and the blocks one after another.
struct CompressedArray {
  std::vector<unsigned char> header, blocks;
};

CompressedArray compress_array(const std::vector<unsigned char>& values, const Packing& p) {
  CompressedArray c;
  const std::size_t n = values.size();
  const std::size_t blocks = (n + p.block_size - 1) / p.block_size;
  const std::size_t last = blocks == 0 ? 0 : n - (blocks - 1) * p.block_size;
  put_item(c.header, blocks, p);
  put_item(c.header, p.block_size, p);
  put_item(c.header, last == p.block_size && p.zero_full_last ? 0 : last, p);
  for (std::size_t b = 0; b < blocks; ++b) {
    const std::size_t begin = b * p.block_size;
    const std::vector<unsigned char> z =
        compress_block(values.data() + begin, std::min(p.block_size, n - begin), p.lzma);
    put_item(c.header, z.size(), p);
    c.blocks.insert(c.blocks.end(), z.begin(), z.end());
  }
  return c;
}

std::string attribute(const std::string& tag, const std::string& key) {
  const std::size_t at = tag.find(" " + key + "=\"") + key.size() + 3;
  return tag.substr(at, tag.find('"', at) - at);
}

// The values of an appended array of a file that write_vtu made (UInt64 byte
// count, little-endian), in the byte order `p` asks for.
std::vector<unsigned char> array_values(const std::string& plain, const std::string& tag, const Packing& p) {
  const std::size_t at = plain.find('_', plain.find("<AppendedData")) + 1 + std::stoull(attribute(tag, "offset"));
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, plain.data() + at, 8);  // the test hosts are little-endian
  std::vector<unsigned char> values(plain.begin() + at + 8, plain.begin() + at + 8 + bytes);
  const std::string type = attribute(tag, "type");
  const std::size_t size = type == "UInt8" ? 1 : type == "Int32" ? 4 : 8;  // what write_vtu uses
  if (p.big_endian)
    for (std::size_t i = 0; i < values.size(); i += size) std::reverse(values.begin() + i, values.begin() + i + size);
  return values;
}

// `plain`, a file that write_vtu made, with every array compressed as `p` says.
std::string compressed_vtu(const std::string& plain, const Packing& p) {
  std::string head = plain.substr(0, plain.find("  <AppendedData"));
  head = replaced(head, "byte_order=\"LittleEndian\" header_type=\"UInt64\"",
                  std::string("byte_order=\"") + (p.big_endian ? "BigEndian" : "LittleEndian") + "\" header_type=\"" +
                      (p.uint64_header ? "UInt64" : "UInt32") + "\" compressor=\"" +
                      (p.lzma ? "vtkLZMADataCompressor" : "vtkZLibDataCompressor") + "\"");
  std::string out, appended;
  std::size_t from = 0;
  for (std::size_t tag = head.find("<DataArray"); tag != std::string::npos; tag = head.find("<DataArray", tag + 1)) {
    const std::size_t close = head.find("/>", tag);
    const std::string decl = head.substr(tag, close - tag);
    const CompressedArray c = compress_array(array_values(plain, decl, p), p);
    out += head.substr(from, tag - from) + decl.substr(0, decl.find(" format="));
    from = close + 2;
    std::vector<unsigned char> both = c.header;
    both.insert(both.end(), c.blocks.begin(), c.blocks.end());
    switch (p.form) {
      case VtuForm::Inline:  // header and blocks base64-encoded separately, as VTK and meshio do
        out += " format=\"binary\">" + base64(c.header) + base64(c.blocks) + "</DataArray>";
        break;
      case VtuForm::InlineOneRun:
        out += " format=\"binary\">" + base64(both) + "</DataArray>";
        break;
      case VtuForm::AppendedRaw:
        out += " format=\"appended\" offset=\"" + std::to_string(appended.size()) + "\"/>";
        appended.append(both.begin(), both.end());
        break;
      case VtuForm::AppendedBase64:
        out += " format=\"appended\" offset=\"" + std::to_string(appended.size()) + "\"/>";
        appended += base64(c.header) + base64(c.blocks);
        break;
    }
  }
  out += head.substr(from);
  if (p.form == VtuForm::AppendedRaw || p.form == VtuForm::AppendedBase64)
    out += std::string("  <AppendedData encoding=\"") + (p.form == VtuForm::AppendedRaw ? "raw" : "base64") +
           "\">\n   _" + appended + "\n  </AppendedData>\n";
  return out + "</VTKFile>\n";
}

std::string vtu_text(const TetMesh& mesh) {
  std::ostringstream out;
  write_vtu(mesh, out, {});
  return out.str();
}

// Where the appended data of array `name` begin in `text`.
std::size_t appended_data_at(const std::string& text, const std::string& name) {
  const std::size_t decl = text.find("Name=\"" + name + "\"");
  const std::size_t off = text.find("offset=\"", decl);
  return text.find('_', text.find("<AppendedData")) + 1 + std::stoull(text.substr(off + 8));
}

// Header item i of the raw appended array whose data begin at `at`.
std::uint64_t header_item(const std::string& text, std::size_t at, std::size_t i, const Packing& p) {
  std::vector<unsigned char> bytes(text.begin() + at + i * p.header_bytes(),
                                   text.begin() + at + (i + 1) * p.header_bytes());
  if (p.big_endian) std::reverse(bytes.begin(), bytes.end());
  std::uint64_t v = 0;
  for (std::size_t k = bytes.size(); k-- > 0;) v = v << 8 | bytes[k];
  return v;
}

void set_header_item(std::string& text, std::size_t at, std::size_t i, std::uint64_t v, const Packing& p) {
  std::vector<unsigned char> bytes;
  put_item(bytes, v, p);
  std::copy(bytes.begin(), bytes.end(), text.begin() + at + i * p.header_bytes());
}

TEST(VtuCompressed, EveryFormHeaderTypeByteOrderAndCompressorReadsAsTheUncompressedFile) {
  const TetMesh mesh = decorated_mesh();
  const std::string plain = vtu_text(mesh);
  const TetMesh uncompressed = vtu_from_text(plain);
  for (const VtuForm form : {VtuForm::Inline, VtuForm::InlineOneRun, VtuForm::AppendedRaw, VtuForm::AppendedBase64})
    for (const bool lzma : {false, true})
      for (const bool uint64_header : {false, true})
        for (const bool big_endian : {false, true}) {
          // Blocks of 64 bytes: the points (216 bytes) and offsets (160) take several.
          const Packing p{form, lzma, uint64_header, big_endian, 64};
          SCOPED_TRACE(describe(p));
          const TetMesh back = vtu_from_text(compressed_vtu(plain, p));
          expect_same_mesh(back, mesh);
          expect_same_mesh(back, uncompressed);
        }
}

TEST(VtuCompressed, BlocksOfEverySizeIncludingFullLastBlocks) {
  const TetMesh mesh = decorated_mesh();
  const std::string plain = vtu_text(mesh);
  // 24 and 216 divide the points' 216 bytes (and 1 every array): the last
  // block is full, its #p-size 0 as VTK writes or the block size as meshio.
  for (const std::size_t block_size : {1, 7, 24, 64, 216, 32768})
    for (const bool zero_full_last : {true, false}) {
      Packing p;
      p.block_size = block_size;
      p.zero_full_last = zero_full_last;
      SCOPED_TRACE(describe(p));
      expect_same_mesh(vtu_from_text(compressed_vtu(plain, p)), mesh);
    }
}

TEST(VtuCompressed, ALargeMeshSpansSeveralBlocksOfTheDefaultSize) {
  const TetMesh mesh = testing::cube_grid(12, 0.3);
  ASSERT_GT(mesh.xyz.size() * sizeof(double), 32768u);
  const std::string plain = vtu_text(mesh);
  for (const bool lzma : {false, true})
    for (const VtuForm form : {VtuForm::Inline, VtuForm::AppendedRaw}) {
      Packing p;
      p.form = form;
      p.lzma = lzma;
      SCOPED_TRACE(describe(p));
      const std::string text = compressed_vtu(plain, p);
      EXPECT_LT(text.size(), plain.size());
      const TetMesh back = vtu_from_text(text);
      EXPECT_EQ(back.xyz, mesh.xyz);
      EXPECT_EQ(back.tets, mesh.tets);
    }
}

// The decorated mesh's points, zlib-compressed raw appended data in blocks of
// 64 bytes: 4 blocks, the last of 24 bytes.
struct CorruptibleVtu {
  explicit CorruptibleVtu(bool lzma = false) : packing{VtuForm::AppendedRaw, lzma, false, false, 64} {}

  Packing packing;
  std::string text = compressed_vtu(vtu_text(decorated_mesh()), packing);
  std::size_t points = appended_data_at(text, "Points");
  std::string points_at = "mesh.vtu, byte " + std::to_string(points) + ": Points: ";

  std::uint64_t item(std::size_t i) const { return header_item(text, points, i, packing); }
  void set_item(std::size_t i, std::uint64_t v) { set_header_item(text, points, i, v, packing); }
  // Where compressed block k (from 0) of the points begins.
  std::size_t block_at(std::size_t k) const {
    std::size_t at = points + (3 + item(0)) * packing.header_bytes();
    for (std::size_t b = 0; b < k; ++b) at += item(3 + b);
    return at;
  }
};

TEST(VtuCompressedErrors, TruncatedDataNameTheFileTheArrayAndTheBlock) {
  CorruptibleVtu v;
  ASSERT_EQ(v.item(0), 4u);
  // In raw appended data, only the last array (types) can run into the end.
  const std::size_t types = appended_data_at(v.text, "types");
  const std::string types_at = "mesh.vtu, byte " + std::to_string(types) + ": types: ";
  EXPECT_EQ(vtu_error(v.text.substr(0, types + 4 * 4 + 3)),
            types_at + "truncated: the file ends inside compressed block 1 of 1");
  EXPECT_EQ(vtu_error(v.text.substr(0, types + 6)), types_at + "truncated compression header");
  // A block count that the file cannot hold.
  v.set_item(0, 40);
  EXPECT_EQ(vtu_error(v.text.substr(0, v.points + 100)),
            v.points_at + "truncated: the compression header of 40 blocks runs past the end of the file");

  // Inline: the last base64 group of the points' data gone.
  Packing inline_packing;
  inline_packing.form = VtuForm::Inline;
  inline_packing.block_size = 64;
  const std::string text = compressed_vtu(vtu_text(decorated_mesh()), inline_packing);
  const std::size_t end = text.find("</DataArray>", text.find("Name=\"Points\""));
  const std::string msg = vtu_error(text.substr(0, end - 4) + text.substr(end));
  EXPECT_NE(msg.find("Points: truncated: the file ends inside compressed block 4 of 4"), std::string::npos) << msg;
}

TEST(VtuCompressedErrors, CorruptStreamsNameTheBlock) {
  CorruptibleVtu v;
  // The last byte of block 2 ends its Adler-32 checksum.
  v.text[v.block_at(2) - 1] ^= 0x55;
  EXPECT_EQ(vtu_error(v.text), v.points_at + "block 2 of 4: corrupt zlib data (incorrect data check)");

  for (std::size_t at = v.block_at(1); at + 1 < v.block_at(2); ++at) {  // anywhere in block 2: some complaint
    CorruptibleVtu w;
    w.text[at] ^= 0x55;
    EXPECT_EQ(vtu_error(w.text).rfind(w.points_at + "block 2 of 4: ", 0), 0u) << "byte " << at - v.block_at(1);
  }

  CorruptibleVtu x(true);
  const std::string clean = x.text;
  x.text[x.block_at(0)] ^= 0x55;  // the xz stream's magic
  EXPECT_EQ(vtu_error(x.text), x.points_at + "block 1 of 4: not an xz stream");
  x.text = clean;
  x.text[x.block_at(1) - 1] ^= 0x55;  // the footer's magic
  EXPECT_EQ(vtu_error(x.text), x.points_at + "block 1 of 4: corrupt xz data");
  for (std::size_t at = x.block_at(0) + 1; at + 1 < x.block_at(1); ++at) {  // anywhere: some complaint
    x.text = clean;
    x.text[at] ^= 0x55;
    EXPECT_EQ(vtu_error(x.text).rfind(x.points_at + "block 1 of 4: ", 0), 0u) << "byte " << at - x.block_at(0);
  }
}

TEST(VtuCompressedErrors, HeadersThatDisagreeWithTheDataOrTheFile) {
  const auto error_with = [](std::size_t i, std::uint64_t value) {
    CorruptibleVtu v;
    v.set_item(i, value);
    return vtu_error(v.text).substr(v.points_at.size());
  };
  EXPECT_EQ(error_with(0, 0xFFFFFFFF),
            "truncated: the compression header of 4294967295 blocks runs past the end of the file");
  EXPECT_EQ(error_with(0, 3), "the compressed blocks hold 152 bytes, expected 216 for 27 Float64 values");
  EXPECT_EQ(error_with(1, 0xFFFFFFFF),
            "the compressed blocks hold more than 216 bytes, expected 216 for 27 Float64 values");
  EXPECT_EQ(error_with(2, 65), "the last block's size 65 exceeds the block size 64");
  EXPECT_EQ(error_with(3, 0xFFFFFFF0), "truncated: the file ends inside compressed block 1 of 4");

  // Sizes that add up to the 216 bytes but split them otherwise.
  CorruptibleVtu v;
  v.set_item(1, 70);
  v.set_item(2, 6);
  EXPECT_EQ(vtu_error(v.text), v.points_at + "block 1 of 4: decompresses to 64 bytes, the header says 70");
  v.set_item(1, 60);
  v.set_item(2, 36);
  EXPECT_EQ(vtu_error(v.text), v.points_at + "block 1 of 4: decompresses to more than the 60 bytes the header says");

  // The last block one byte longer than its stream (the next array's first byte).
  CorruptibleVtu w;
  w.set_item(6, w.item(6) + 1);
  EXPECT_EQ(vtu_error(w.text), w.points_at + "block 4 of 4: 1 byte follows the end of the zlib stream");

  // Appended base64: the block count is read before the rest of the header
  // is decoded.
  Packing p;
  p.form = VtuForm::AppendedBase64;
  std::string text = compressed_vtu(vtu_text(decorated_mesh()), p);
  const std::size_t at = appended_data_at(text, "Points");
  text.replace(at, 8, base64({0xFF, 0xFF, 0xFF, 0xFF, 0, 0}));
  EXPECT_EQ(vtu_error(text), "mesh.vtu, byte " + std::to_string(at) +
                                 ": Points: the compression header's block count 4294967295 exceeds the file");
}

// Appended base64 blocks have no end of their own: a block header shorter
// than it declares (by its block count, or by header_type) decodes into the
// characters after it, and is refused rather than read past what it gave.
TEST(VtuErrors, AppendedBase64HeaderShorterThanItDeclaresIsRefused) {
  Packing p;
  p.form = VtuForm::AppendedBase64;
  std::string text = compressed_vtu(vtu_text(testing::regular_tet()), p);
  const std::size_t types = appended_data_at(text, "types");
  // 1 block (16 header bytes, 24 characters) made 2: 20 bytes are due, its
  // 24 characters and the next 4, the data's, give 19.
  const std::string compressed = text;
  text.replace(types, 8, base64({2, 0, 0, 0, 0x00, 0x80}));
  EXPECT_EQ(vtu_error(text),
            "mesh.vtu, byte " + std::to_string(types) + ": types: truncated block header: 19 of its 20 bytes");
  // Not even the block count: 2 bytes where its 4 are due.
  text = compressed;
  text.replace(types, 8, "AQ==AQ==");
  EXPECT_EQ(vtu_error(text),
            "mesh.vtu, byte " + std::to_string(types) + ": types: truncated block header: 2 of its 4 bytes");
  // UInt64 headers, the types' byte count in 4 bytes: 8 are due, 7 given.
  const std::string plain = file_text("vtu_appended_base64.vtu");
  const std::string short_header = replaced(plain, "AwAAAAAAAAA=CgoF", "AwAAAA==CgoF");
  EXPECT_EQ(vtu_error(short_header), "mesh.vtu, byte " + std::to_string(short_header.find("AwAAAA==")) +
                                         ": types: truncated block header: 7 of its 8 bytes");
  // A file that ends inside the header.
  const std::size_t cut = plain.find("AwAAAAAAAAA=") + 8;
  EXPECT_EQ(vtu_error(plain.substr(0, cut)),
            "mesh.vtu, byte " + std::to_string(cut - 8) + ": types: truncated block header: 6 of its 8 bytes");
}

TEST(VtuCompressedErrors, AHugeDeclaredSizeIsNotAllocatedBeforeTheDataYieldIt) {
  // 10^10 points (240 GB of Float64) in one block, as a header may say;
  // the file padded so that this many points pass the early bound.
  Packing p;
  p.uint64_header = true;
  std::string text = compressed_vtu(vtu_text(decorated_mesh()), p);
  const std::size_t points = appended_data_at(text, "Points");
  set_header_item(text, points, 1, 240000000000, p);  // #u-size
  set_header_item(text, points, 2, 0, p);             // the one block is full
  text = replaced(text, "NumberOfPoints=\"9\"", "NumberOfPoints=\"10000000000\"");
  const std::string padding = "<!--" + std::string(200000, '.') + "-->\n";
  text.insert(text.find("<VTKFile"), padding);
  const std::string msg = vtu_error(text);
  EXPECT_NE(msg.find("Points: block 1 of 1: decompresses to 216 bytes, the header says 240000000000"),
            std::string::npos)
      << msg;
}

// Data of the whole dataset (ParaView's TimeValue) has no place in the
// output: both readers name it, as they name other arrays they drop.
TEST(VtkTagArrays, FieldDataOfTheDatasetIsNoted) {
  const std::string vtu = replaced(file_text("vtu_ascii.vtu"), "<Piece",
                                   "<FieldData><DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
                                   "format=\"ascii\">0.5</DataArray></FieldData>\n<Piece");
  const TetMesh from_vtu = vtu_from_text(vtu);
  expect_vtu_fixture_tags(from_vtu);
  ASSERT_FALSE(from_vtu.extras.read_notes.empty());
  EXPECT_EQ(from_vtu.extras.read_notes.back(), "field data array 'TimeValue' is ignored and not written back");

  const std::string vtk = replaced(file_text("vtk_v51.vtk"), "FIELD FieldData 1\nTIME 1 1 double\n0.25\n",
                                   "FIELD FieldData 2\nTimeValue 1 1 double\n0.5\nCYCLE 1 1 int\n3\n");
  const TetMesh from_vtk = vtk_from_text(vtk);
  expect_vtk_fixture_tags(from_vtk);
  ASSERT_FALSE(from_vtk.extras.read_notes.empty());
  EXPECT_EQ(from_vtk.extras.read_notes.back(), "field data arrays 'TimeValue', 'CYCLE' are ignored and not written back");
}


// Positions of values at fault ----------------------------------------------
//
// A node index or offset is checked only once every section is read, long
// after its value: the message names the value's own line or byte, found
// again from the array's start, not the line the reader stands at.

const std::string kV42 =
    "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n"
    "0 0 0 1 0 0 0 1 0\n0 0 1 1 1 1\nCELLS 2 10\n4 0 1\n2 3 4 1 2\n3\n4\nCELL_TYPES 2\n10\n10\n";

TEST(VtkValuePlaces, LegacyAsciiNodeIndexOutOfRangeNamesItsOwnLine) {
  // Cell 1's values wrap over lines 10-12; each bad one is named on its line.
  EXPECT_NE(vtk_error(replaced(kV42, "3\n4\nCELL_TYPES", "3\n7\nCELL_TYPES"))
                .find("mesh.vtk:12: cell 1: node 7 out of range [0, 5)"),
            std::string::npos)
      << vtk_error(replaced(kV42, "3\n4\nCELL_TYPES", "3\n7\nCELL_TYPES"));
  EXPECT_NE(vtk_error(replaced(kV42, "2 3 4 1 2\n", "2 3 4 9 2\n")).find("mesh.vtk:10: cell 1: node 9 out of range"),
            std::string::npos);
  EXPECT_NE(vtk_error(replaced(kV42, "4 0 1\n", "4 -1 1\n")).find("mesh.vtk:9: cell 0: node -1 out of range"),
            std::string::npos);
}

TEST(VtkValuePlaces, LegacyAscii51NamesTheConnectivityAndOffsetsLines) {
  const std::string v51 = file_text("vtk_v51.vtk");
  const std::string bad_node = replaced(v51, "1 2 3 4\n4\nCELL_TYPES", "1 2 3 4\n8\nCELL_TYPES");
  EXPECT_NE(vtk_error(bad_node).find(line_of(bad_node, "8\nCELL_TYPES", "mesh.vtk") +
                                     " cell 2: node 8 out of range [0, 5)"),
            std::string::npos)
      << vtk_error(bad_node);
  const std::string bad_offset = replaced(v51, "0 4 8\n9\n", "0 4 8\n12\n");
  EXPECT_NE(vtk_error(bad_offset).find(line_of(bad_offset, "12\n", "mesh.vtk") +
                                       " cell 2: offset 12 outside the connectivity array of 9"),
            std::string::npos)
      << vtk_error(bad_offset);
}

// A stream that cannot seek back, as a pipe: the value cannot be read
// again, so the message names the array's line and which value it is.
class OneWayBuffer : public std::streambuf {
 public:
  explicit OneWayBuffer(std::string text) : text_(std::move(text)) {
    setg(text_.data(), text_.data(), text_.data() + text_.size());
  }

 private:
  std::string text_;
};

TEST(VtkValuePlaces, LegacyAsciiFromAnUnseekableStreamNamesTheArrayAndTheEntry) {
  OneWayBuffer buffer(replaced(kV42, "3\n4\nCELL_TYPES", "3\n7\nCELL_TYPES"));
  std::istream in(&buffer);
  const std::string msg = testing::input_error_message([&] { read_vtk(in, "pipe"); }, "a pipe");
  EXPECT_EQ(msg, "pipe:8: cell 1: node 7 out of range [0, 5) (value 9, counted from 0, of the CELLS data after this "
                 "keyword)");
}

TEST(VtkValuePlaces, VtuAsciiNodeIndexOutOfRangeNamesItsOwnLine) {
  // The connectivity spread over lines, one value on a line of its own.
  const std::string text = replaced(file_text("vtu_ascii.vtu"), "1 2 3 4\n", "1 2 3\n5\n");
  const std::string msg = vtu_error(text);
  EXPECT_EQ(msg.rfind("mesh.vtu:29: cell 1: node 5 out of range [0, 5)", 0), 0u) << msg;  // the 5's line
  const std::string offsets = replaced(file_text("vtu_ascii.vtu"), "4 8 11 13", "4 8\n99 13");
  EXPECT_EQ(vtu_error(offsets).rfind(line_of(offsets, "99 13", "mesh.vtu") +
                                         " cell 2: offset 99 outside the connectivity array of 13", 0),
            0u)
      << vtu_error(offsets);
}

// Structural errors in the cells name what is wrong, not a consequence of it:
// a negative last offset is not "more than the file", and an offset out of
// range is placed on its own line even when the next offset is on another.
TEST(VtuErrors, OffsetProblemsAreNamedWhereTheyAre) {
  const std::string ascii = file_text("vtu_ascii.vtu");
  const std::string negative = vtu_error(replaced(ascii, "4 8 11 13", "4 8 11 -13"));
  EXPECT_NE(negative.find("negative cell offset"), std::string::npos) << negative;
  const std::string offsets = replaced(ascii, "4 8 11 13", "4 8\n99\n13");
  EXPECT_EQ(vtu_error(offsets).rfind(line_of(offsets, "99\n13", "mesh.vtu") + " cell 2: offset 99", 0), 0u)
      << vtu_error(offsets);
}

// mesh_from_vtk_cells wants the leading 0 and one offset per cell type, and
// one tag per cell. The VTU reader sizes all three from NumberOfCells, so no
// .vtu reaches these checks; a direct caller does (and a legacy file, below,
// the offsets one).
TEST(VtkCells, OffsetsOrTagsLongerThanTheCellTypesAreRefused) {
  const auto error = [](const std::vector<long long>& offsets, const std::vector<int>& tags) {
    TetMesh mesh = testing::regular_tet();
    const std::vector<long long> connectivity{0, 1, 2, 3, 0, 1, 2};  // a tet, then a triangle's worth
    const VtkCellPlace place = [](VtkCellArray, std::size_t, std::size_t) { return VtkValuePlace{"nowhere", ""}; };
    return testing::input_error_message(
        [&] { mesh_from_vtk_cells(mesh, connectivity, offsets, {10}, tags, {}, "cells.vtu:7", place); },
        "mesh_from_vtk_cells");
  };
  EXPECT_EQ(error({0, 4, 7}, {}), "cells.vtu:7: cell offsets do not match the 1 cell types");
  EXPECT_EQ(error({0}, {}), "cells.vtu:7: cell offsets do not match the 1 cell types");
  EXPECT_EQ(error({4, 8}, {}), "cells.vtu:7: cell offsets do not match the 1 cell types");  // no leading 0
  EXPECT_EQ(error({0, 4}, {5, 6}), "cells.vtu:7: 2 region tags for 1 cells");
  // The same arrays at their right lengths make one tet.
  TetMesh mesh = testing::regular_tet();
  mesh_from_vtk_cells(mesh, {0, 1, 2, 3}, {0, 4}, {10}, {5}, {}, "cells.vtu:7", {});
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{5}));
}

TEST(VtkValuePlaces, VtuBinaryNamesTheValuesByteOrTheArraysDataAndTheEntry) {
  TetMesh mesh = decorated_mesh();
  mesh.tets[5] = 99;  // cell 1, its second node
  const std::string plain = vtu_text(mesh);
  // Raw uncompressed appended data: the value's own byte.
  const std::size_t data = appended_data_at(plain, "connectivity");
  const std::string tag = plain.substr(plain.rfind("<DataArray", plain.find("Name=\"connectivity\"")));
  const std::size_t size = attribute(tag, "type") == "Int32" ? 4 : 8;
  EXPECT_EQ(vtu_error(plain), "mesh.vtu, byte " + std::to_string(data + 8 + 5 * size) +
                                  ": cell 1: node 99 out of range [0, 9)");
  // Compressed or base64 data: where the array's data start, and the entry.
  for (const VtuForm form : {VtuForm::Inline, VtuForm::AppendedRaw, VtuForm::AppendedBase64}) {
    Packing p;
    p.form = form;
    SCOPED_TRACE(describe(p));
    const std::string text = compressed_vtu(plain, p);
    const std::size_t decl = text.find("Name=\"connectivity\"");
    const std::size_t at = form == VtuForm::Inline ? text.find('>', decl) + 1 : appended_data_at(text, "connectivity");
    EXPECT_EQ(vtu_error(text), "mesh.vtu, byte " + std::to_string(at) +
                                   ": cell 1: node 99 out of range [0, 9) (value 5, counted from 0, of the "
                                   "connectivity array, whose compressed data start at this byte)");
  }
}

// File text in messages ------------------------------------------------------

TEST(VtuErrors, EchoedTextIsOneShortEscapedLine) {
  const std::string ascii = file_text("vtu_ascii.vtu");
  const std::string newline = vtu_error(replaced(ascii, "type=\"Int64\" Name=\"connectivity\"",
                                                 "type=\"UInt\n8\" Name=\"connectivity\""));
  EXPECT_NE(newline.find("unsupported DataArray type 'UInt\\x0a8'"), std::string::npos) << newline;
  const std::string huge = vtu_error(replaced(ascii, "type=\"Int64\" Name=\"connectivity\"",
                                              "type=\"" + std::string(1 << 20, 'Y') + "\" Name=\"connectivity\""));
  EXPECT_NE(huge.find("unsupported DataArray type '" + std::string(40, 'Y') + "...'"), std::string::npos);
  EXPECT_LT(huge.size(), 200u);
  const std::string control = vtu_error(replaced(ascii, "</Points>", "</Po\x1dints\x0b>"));
  EXPECT_NE(control.find("end tag 'Po\\x1dints\\x0b' does not match"), std::string::npos) << control;
  for (const std::string& msg : {newline, huge, control}) {
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\x1d'), std::string::npos) << msg;
  }
  // Array names in the notes on dropped arrays.
  const TetMesh noted = vtu_from_text(vtu_with_cell_data(vtu_cell_array("a\nb", "1 2 3 4")));
  ASSERT_FALSE(noted.extras.read_notes.empty());
  EXPECT_EQ(noted.extras.read_notes.back(), "cell data array 'a\\x0ab' is ignored and not written back");
}

TEST(VtuErrors, AFileThatIsNotXmlIsNamedByWhatItHolds) {
  EXPECT_EQ(vtu_error("hello world\n"),
            "mesh.vtu:1: not a VTK XML file: expected <VTKFile type=\"UnstructuredGrid\">, found 'hello world\\x0a'");
  const std::string msh = vtu_error("\n$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  EXPECT_EQ(msh.rfind("mesh.vtu:2: not a VTK XML file: expected <VTKFile type=\"UnstructuredGrid\">, found "
                      "'$MeshFormat\\x0a4.1 0 8\\x0a$EndMeshFormat\\x0a'", 0),
            0u)
      << msh;
  EXPECT_EQ(vtu_error(""), "mesh.vtu:1: empty file, expected <VTKFile type=\"UnstructuredGrid\">");
  EXPECT_EQ(vtu_error(" \n\t\r\n"), "mesh.vtu:1: empty file, expected <VTKFile type=\"UnstructuredGrid\">");
}

// A cell count that outruns the CELLS size stops at the cell, before reading
// the next section's keyword as a node count; a file without POINTS is named
// as such rather than by its first node index out of range.
TEST(LegacyVtkErrors, CellsPastTheDeclaredSizeAndMissingPoints) {
  const std::string v42 =
      "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n"
      "0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 2 5\n4 0 1 2 3\nCELL_TYPES 2\n10\n10\n";
  const std::string past = vtk_error(v42);
  EXPECT_NE(past.find("cell 1 runs past the 5 values that CELLS declared"), std::string::npos) << past;
  const std::string no_points =
      vtk_error(replaced(replaced(v42, "POINTS 4 double\n0 0 0 1 0 0 0 1 0 0 0 1\n", ""), "CELLS 2 5\n4 0 1 2 3\nCELL_TYPES 2\n10\n10\n",
                         "CELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n"));
  EXPECT_NE(no_points.find("no POINTS section"), std::string::npos) << no_points;
}

// VTK writes NULL_ARRAY for an empty slot of a FIELD; the arrays after it
// are still read.
TEST(LegacyVtk, NullArrayInAFieldIsSkipped) {
  const std::string text =
      "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n"
      "0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n"
      "CELL_DATA 1\nFIELD FieldData 2\nNULL_ARRAY\ngmsh:physical 1 1 int\n4\n";
  EXPECT_EQ(vtk_from_text(text).extras.tet_tags, (std::vector<int>{4}));
}

TEST(LegacyVtk, RejectsFieldsOfTheWrongSize) {
  MeshFields fields;
  fields.tet_scalars.push_back({"short", {}});
  std::ostringstream out;
  EXPECT_THROW(write_vtk(testing::regular_tet(), out, fields), std::invalid_argument);
  MeshFields nodes;
  nodes.node_scalars.push_back({"short", {1.0}});
  EXPECT_THROW(write_vtk(testing::regular_tet(), out, nodes), std::invalid_argument);
}

// Tags are written where either the tets or a pass-through block has them:
// tets alone, or blocks alone (the tets then get 0).
TEST(VtkTagArrays, TagsOfTetsAloneOrBlocksAloneAreWritten) {
  TetMesh tets = testing::regular_tet();
  tets.extras.tet_tags = {5};
  TetMesh blocks = testing::regular_tet();
  blocks.extras.blocks.push_back(PassThroughBlock{"triangle", 3, {0, 1, 2}, {3}, {}, {}});
  for (const bool vtu : {false, true}) {
    SCOPED_TRACE(vtu ? "vtu" : "vtk");
    const auto round_trip = [&](const TetMesh& mesh) {
      std::ostringstream out;
      vtu ? write_vtu(mesh, out, {}) : write_vtk(mesh, out, {});
      return vtu ? vtu_from_text(out.str()) : vtk_from_text(out.str());
    };
    EXPECT_EQ(round_trip(tets).extras.tet_tags, (std::vector<int>{5}));
    const TetMesh back = round_trip(blocks);
    EXPECT_EQ(back.extras.tet_tags, (std::vector<int>{0}));
    ASSERT_EQ(back.extras.blocks.size(), 1u);
    EXPECT_EQ(back.extras.blocks[0].tags, (std::vector<int>{3}));
  }
}

// Region tags come from cell data only: a point array under a tag name is
// another point array (noted, not read as tags). Any non-zero value of the
// fixed-node array pins its node, negative ones too.
TEST(VtkTagArrays, TagNamesOnPointsAreNotTagsAndNonZeroFixedValuesPin) {
  const std::string v42 =
      "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n"
      "0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n"
      "POINT_DATA 4\nSCALARS gmsh:physical int 1\nLOOKUP_TABLE default\n1 2 3 4\n"
      "SCALARS tetsmooth:fixed int 1\nLOOKUP_TABLE default\n0 -1 2 0\n";
  const TetMesh mesh = vtk_from_text(v42);
  EXPECT_TRUE(mesh.extras.tet_tags.empty());
  EXPECT_EQ(mesh.extras.read_notes,
            (std::vector<std::string>{"point data array 'gmsh:physical' is ignored and not written back"}));
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{0, 1, 1, 0}));
}

// An ascii array with a value too many is named at that value; one whose
// NumberOfComponents is not the 3 of a point is refused even when the value
// count would fit another shape.
TEST(VtuErrors, ExtraValuesAndWrongComponentCountsAreNamed) {
  const std::string text = file_text("vtu_ascii.vtu");
  const std::string extra = vtu_error(replaced(text, "0 0 1  1 1 1", "0 0 1  1 1 1 5"));
  EXPECT_NE(extra.find("mesh.vtu:22:"), std::string::npos) << extra;
  EXPECT_NE(extra.find("holds more than the expected 15 values"), std::string::npos) << extra;
  const std::string comps =
      vtu_error(replaced(text, "Name=\"Points\" NumberOfComponents=\"3\"", "Name=\"Points\" NumberOfComponents=\"5\""));
  EXPECT_NE(comps.find("has '5' components, expected 3"), std::string::npos) << comps;
}

// An empty file has no line 0: the error names line 1, where the header
// was expected.
TEST(LegacyVtkErrors, EmptyFileNamesLine1) {
  const std::string msg = vtk_error("");
  EXPECT_EQ(msg.rfind("mesh.vtk:1:", 0), 0u) << msg;
}

// A negative count is named as such, not read as a huge one to the end of
// the file.
TEST(LegacyVtkErrors, NegativeCountsAreNamed) {
  const std::string v42 =
      "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n"
      "0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
  const std::string msg = vtk_error(replaced(v42, "POINTS 4", "POINTS -1"));
  EXPECT_NE(msg.find("mesh.vtk:5: invalid point count -1"), std::string::npos) << msg;
}

// The last offset one past the connectivity array is out of it.
TEST(LegacyVtkErrors, OffsetOnePastTheConnectivityIsNamed) {
  const std::string v51 =
      "# vtk DataFile Version 5.1\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n"
      "0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 2 4\nOFFSETS vtktypeint64\n0 5\nCONNECTIVITY vtktypeint64\n0 1 2 3\n"
      "CELL_TYPES 1\n10\n";
  const std::string msg = vtk_error(v51);
  EXPECT_NE(msg.find("offset 5 outside the connectivity array of 4"), std::string::npos) << msg;
}

// Legacy files reach the offsets check of mesh_from_vtk_cells: CELLS and
// CELL_TYPES count the cells each on their own, and a cell without a type
// (or a type without a cell) is refused, not dropped.
TEST(LegacyVtkErrors, CellsAndCellTypesOfDifferentCountsAreRefused) {
  const std::string v42 =
      "# vtk DataFile Version 4.2\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 double\n"
      "0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 2 10\n4 0 1 2 3\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
  EXPECT_EQ(vtk_error(v42), "mesh.vtk:10: cell offsets do not match the 1 cell types");
  EXPECT_EQ(vtk_error(replaced(v42, "CELL_TYPES 1\n10\n", "CELL_TYPES 3\n10 10 10\n")),
            "mesh.vtk:10: cell offsets do not match the 3 cell types");
}

// A 5.1 ASCII file of five points and the cell arrays given as their
// values' text: CELLS counts the values of each; one cell type per offset
// after the first, all tets.
std::string legacy51(const std::string& offsets, const std::string& connectivity) {
  const auto count = [](const std::string& values) {
    std::istringstream in(values);
    return std::distance(std::istream_iterator<std::string>(in), std::istream_iterator<std::string>());
  };
  const auto cells = count(offsets) - 1;
  std::string types;
  for (long k = 0; k < cells; ++k) types += k ? " 10" : "10";
  return "# vtk DataFile Version 5.1\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n"
         "0 0 0 1 0 0 0 1 0 0 0 1 1 1 1\nCELLS " +
         std::to_string(count(offsets)) + " " + std::to_string(count(connectivity)) + "\nOFFSETS vtktypeint64\n" +
         offsets + "\nCONNECTIVITY vtktypeint64\n" + connectivity + "\nCELL_TYPES " + std::to_string(cells) + "\n" +
         types + "\n";
}

// 5.x OFFSETS start with the 0 of the first cell; read from another start,
// the cell would take nodes that are not its own (here a valid tet).
TEST(LegacyVtkErrors, OffsetsThatDoNotStartAtZeroAreRefused) {
  EXPECT_EQ(vtk_error(legacy51("4 8", "3 3 3 3 0 1 2 3")), "mesh.vtk:12: cell offsets do not match the 1 cell types");
  EXPECT_EQ(vtk_from_text(legacy51("0 4", "0 1 2 3")).tets, (std::vector<index_t>{0, 1, 2, 3}));
}

// VTK ends the connectivity array at the last offset: a 5.x file with more
// connectivity values than its cells use is refused at that offset, not
// read with the extra values dropped.
TEST(LegacyVtkErrors, ConnectivityLongerThanTheCellsUseIsRefused) {
  EXPECT_EQ(vtk_error(legacy51("0 4", "0 1 2 3 4")), "mesh.vtk:9: the cells use 4 of the connectivity array's 5 values");
  const std::string none = vtk_error(legacy51("0", "0 1 2 3 4"));  // no cells at all
  EXPECT_NE(none.find("the cells use 0 of the connectivity array's 5 values"), std::string::npos) << none;
}

TEST(VtuErrors, NegativeAppendedOffsetIsRefused) {
  const std::string text = file_text("vtu_appended_base64.vtu");
  const std::size_t at = text.find("offset=\"");
  ASSERT_NE(at, std::string::npos);
  const std::size_t end = text.find('"', at + 8);
  const std::string msg = vtu_error(text.substr(0, at + 8) + "-1" + text.substr(end));
  EXPECT_NE(msg.find("missing or bad offset attribute"), std::string::npos) << msg;
}

}  // namespace
}  // namespace tetsmooth
