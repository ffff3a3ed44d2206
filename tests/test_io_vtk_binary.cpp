// Legacy VTK BINARY files: meshio's, in the 4.2 and 5.1 layouts (fixtures
// made by tests/data/vtk_binary_make.py); blocks longer than the reader's
// chunks; every section kind of an unstructured grid with a binary form;
// and errors that name the byte offset of the value or line at fault.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "input_error.hpp"
#include "mesh/errors.hpp"
#include "mesh/io/little_endian.hpp"
#include "mesh/io/vtk_legacy.hpp"
#include "support/test_meshes.hpp"

namespace tetsmooth {
namespace {

// Values as a BINARY block holds them: big-endian, back to back.
template <class T>
std::string be(std::initializer_list<T> values) {
  std::string out;
  for (T v : values) {
    unsigned char bytes[sizeof(T)];
    store_le(bytes, v);
    std::reverse(bytes, bytes + sizeof(T));
    out.append(reinterpret_cast<const char*>(bytes), sizeof(T));
  }
  return out;
}

TetMesh read_text(const std::string& text) {
  std::istringstream in(text);
  return read_vtk(in, "mesh.vtk");
}

std::string vtk_error(const std::string& text) {
  std::istringstream in(text);
  return testing::input_error_message([&] { read_vtk(in, "mesh.vtk"); }, "a BINARY file");
}

const std::string kHeader42 = "# vtk DataFile Version 4.2\nbinary test\nBINARY\nDATASET UNSTRUCTURED_GRID\n";
const std::string kHeader51 = "# vtk DataFile Version 5.1\nbinary test\nBINARY\nDATASET UNSTRUCTURED_GRID\n";

// Five points (the last at a coordinate no short decimal holds), two tets
// and a vertex cell, in the 4.2 layout, with nothing after CELL_TYPES.
std::string points_and_cells_42() {
  return kHeader42 + "POINTS 5 double\n" + be<double>({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1.25, 0.75, 1.0 / 3.0}) +
         "\nCELLS 3 12\n" + be<std::int32_t>({4, 0, 1, 2, 3, 4, 1, 2, 3, 4, 1, 4}) + "\nCELL_TYPES 3\n" +
         be<std::int32_t>({10, 10, 1}) + "\n";
}

void expect_fixture_mesh(const TetMesh& mesh) {
  EXPECT_EQ(mesh.xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1.25, 0.75, 1.0 / 3.0}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3, 1, 2, 3, 4}));
  ASSERT_EQ(mesh.extras.blocks.size(), 1u);
  EXPECT_EQ(mesh.extras.blocks[0].kind, "vertex");
  EXPECT_EQ(mesh.extras.blocks[0].connectivity, (std::vector<std::int32_t>{4}));
}

TEST(LegacyVtkBinary, ReadsMeshiosFilesInBothLayouts) {
  for (const char* name : {"vtk_binary42.vtk", "vtk_binary51.vtk"}) {
    SCOPED_TRACE(name);
    const TetMesh mesh = read_vtk_file(testing::data_path(name));
    expect_fixture_mesh(mesh);
    EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{5, 6}));
    EXPECT_EQ(mesh.extras.blocks[0].tags, (std::vector<int>{9}));
    EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{0, 0, 0, 0, 1}));
    ASSERT_EQ(mesh.extras.read_notes.size(), 1u);
    EXPECT_NE(mesh.extras.read_notes[0].find("'pressure'"), std::string::npos) << mesh.extras.read_notes[0];
  }
}

// A mesh's points (double) and tets in the 4.2 layout (int counts and
// nodes) or the 5.1 one (int64 offsets and connectivity).
std::string binary_file(const TetMesh& mesh, bool v51) {
  std::string out = (v51 ? kHeader51 : kHeader42) + "POINTS " + std::to_string(mesh.num_nodes()) + " double\n";
  for (double x : mesh.xyz) out += be<double>({x});
  const std::size_t tets = mesh.num_tets();
  if (v51) {
    out += "\nCELLS " + std::to_string(tets + 1) + " " + std::to_string(4 * tets) + "\nOFFSETS vtktypeint64\n";
    for (std::size_t t = 0; t <= tets; ++t) out += be<std::int64_t>({static_cast<std::int64_t>(4 * t)});
    out += "\nCONNECTIVITY vtktypeint64\n";
    for (index_t v : mesh.tets) out += be<std::int64_t>({v});
  } else {
    out += "\nCELLS " + std::to_string(tets) + " " + std::to_string(5 * tets) + "\n";
    for (std::size_t t = 0; t < tets; ++t)
      out += be<std::int32_t>({4, mesh.tets[4 * t], mesh.tets[4 * t + 1], mesh.tets[4 * t + 2], mesh.tets[4 * t + 3]});
  }
  out += "\nCELL_TYPES " + std::to_string(tets) + "\n";
  for (std::size_t t = 0; t < tets; ++t) out += be<std::int32_t>({10});
  return out + "\n";
}

TEST(LegacyVtkBinary, BlocksLongerThanAReadChunkReadExactly) {
  // 24,389 points (73,167 coordinates) and 131,712 tets: every block spans
  // several of the reader's chunks of 65,536 values.
  const TetMesh mesh = testing::cube_grid(28, 0.2);
  ASSERT_GT(mesh.xyz.size(), 65536u);
  for (bool v51 : {false, true}) {
    SCOPED_TRACE(v51 ? "5.1" : "4.2");
    const TetMesh back = read_text(binary_file(mesh, v51));
    EXPECT_EQ(back.xyz, mesh.xyz);
    EXPECT_EQ(back.tets, mesh.tets);
  }
}

TEST(LegacyVtkBinary, EverySectionWithABinaryFormIsReadOrSkipped) {
  // Float points and dataset FIELD data; in cell data SCALARS with a table,
  // COLOR_SCALARS (bytes), a LOOKUP_TABLE (bytes), TENSORS, TENSORS6 and
  // METADATA; in point data VECTORS, NORMALS, TEXTURE_COORDINATES, and FIELD
  // arrays of 16-bit, 64-bit, vtkIdType (4 bytes, as VTK writes ids) and bit
  // (8 a byte) types, the fixed flags last.
  const std::string text =
      kHeader42 + "FIELD FieldData 1\nTIME 1 1 double\n" + be<double>({0.5}) + "\nPOINTS 5 float\n" +
      be<float>({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}) + "\nCELLS 2 10\n" +
      be<std::int32_t>({4, 0, 1, 2, 3, 4, 1, 2, 3, 4}) + "\nCELL_TYPES 2\n" + be<std::int32_t>({10, 10}) +
      "\nCELL_DATA 2\nSCALARS tetsmooth:tag short 1\nLOOKUP_TABLE colours\n" + be<std::int16_t>({-3, 8}) +
      "\nCOLOR_SCALARS rgb 3\n" + std::string("\x01\x02\x03\x04\x05\x06", 6) + "\nLOOKUP_TABLE colours 2\n" +
      std::string(8, '\x7f') + "\nTENSORS stress float\n" + be<float>({1, 2, 3, 4, 5, 6, 7, 8, 9}) +
      be<float>({1, 2, 3, 4, 5, 6, 7, 8, 9}) + "\nTENSORS6 strain double\n" +
      be<double>({1, 2, 3, 4, 5, 6, 1, 2, 3, 4, 5, 6}) + "\nMETADATA\nINFORMATION 0\n\n" +
      "POINT_DATA 5\nVECTORS v double\n" +
      be<double>({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15}) + "\nNORMALS n float\n" +
      be<float>({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}) + "\nTEXTURE_COORDINATES uv 2 double\n" +
      be<double>({0, 0, 1, 0, 0, 1, 1, 1, 0.5, 0.5}) + "\nFIELD more 4\nids 1 5 vtktypeint64\n" +
      be<std::int64_t>({1, 2, 3, 4, 5}) + "\nvtkOriginalPointIds 1 5 vtkIdType\n" + be<std::int32_t>({0, 1, 2, 3, 4}) +
      "\nmask 1 5 bit\n" + std::string(1, '\xa8') + "\ntetsmooth:fixed 1 5 unsigned_short\n" +
      be<std::uint16_t>({0, 1, 0, 0, 0}) + "\n";
  const TetMesh mesh = read_text(text);
  EXPECT_EQ(mesh.xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3, 1, 2, 3, 4}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{-3, 8}));
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{0, 1, 0, 0, 0}));
}

TEST(LegacyVtkBinary, IdArraysAreFourBytesAsVtkWritesThem) {
  // ParaView's output carries vtkOriginalCellIds; read as 8-byte values,
  // the reader would run into the tags after it.
  const std::string text = points_and_cells_42() + "CELL_DATA 3\nFIELD FieldData 2\n" +
                           "vtkOriginalCellIds 1 3 vtkIdType\n" + be<std::int32_t>({0, 1, 2}) +
                           "\ngmsh:physical 1 3 int\n" + be<std::int32_t>({5, 6, 9}) + "\n";
  const TetMesh mesh = read_text(text);
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{5, 6}));
  EXPECT_EQ(mesh.extras.blocks[0].tags, (std::vector<int>{9}));
}

// Errors ----------------------------------------------------------------------

TEST(LegacyVtkBinaryErrors, ATruncatedBlockNamesTheFirstMissingByte) {
  const std::string whole = points_and_cells_42();
  const std::size_t data = whole.find("POINTS 5 double\n") + 16;
  const std::string cut = whole.substr(0, data + 37);  // inside the fifth coordinate
  EXPECT_NE(
      vtk_error(cut).find("mesh.vtk, byte " + std::to_string(data + 37) + ": unexpected end of file in coordinate"),
      std::string::npos)
      << vtk_error(cut);
  const std::size_t cells = whole.find("CELLS 3 12\n") + 11;
  const std::string msg = vtk_error(whole.substr(0, cells + 20));
  EXPECT_NE(msg.find("mesh.vtk, byte " + std::to_string(cells + 20) + ": unexpected end of file in CELLS data"),
            std::string::npos)
      << msg;
}

TEST(LegacyVtkBinaryErrors, ABlockOfAnotherLengthThanItsCountAndTypeSayIsCaughtWhereItEnds) {
  // The points are doubles, declared float: the block read ends halfway,
  // and what follows it is data, not a line break.
  std::string text = points_and_cells_42();
  text.replace(text.find("POINTS 5 double"), 15, "POINTS 5 float");
  const std::size_t data = text.find("POINTS 5 float\n") + 15;
  EXPECT_NE(vtk_error(text).find("mesh.vtk, byte " + std::to_string(data + 60) +
                                 ": expected a line break after the coordinate data"),
            std::string::npos)
      << vtk_error(text);
}

TEST(LegacyVtkBinaryErrors, ArgumentsMustBeOnTheirKeywordsLine) {
  // Read from the next line, the type would come from the data.
  std::string text = points_and_cells_42();
  text.replace(text.find("POINTS 5 double"), 15, "POINTS 5");
  const std::string msg = vtk_error(text);
  EXPECT_NE(msg.find("mesh.vtk, byte " + std::to_string(text.find("POINTS")) + ": expected point type on this line"),
            std::string::npos)
      << msg;
}

TEST(LegacyVtkBinaryErrors, CellsThatRunPastTheirBlockNameTheirCount) {
  std::string text = points_and_cells_42();
  const std::size_t cells = text.find("CELLS 3 12\n");
  const std::size_t block = cells + 11;
  // The third cell's count, at value 10 of the block, says 2 nodes where
  // one value is left.
  std::string past = text;
  past.replace(block + 40, 4, be<std::int32_t>({2}));
  EXPECT_NE(vtk_error(past).find("mesh.vtk, byte " + std::to_string(block + 40) +
                                 ": cell 2 runs past the 12 values that CELLS declared"),
            std::string::npos)
      << vtk_error(past);
  // Two cells' values declared for three cells: the third has no count.
  std::string short_block = text;
  short_block.replace(cells, 11 + 48, "CELLS 3 10\n" + be<std::int32_t>({4, 0, 1, 2, 3, 4, 1, 2, 3, 4}));
  EXPECT_NE(vtk_error(short_block).find("mesh.vtk, byte " + std::to_string(block + 40) +
                                        ": cell 2 runs past the 10 values that CELLS declared"),
            std::string::npos)
      << vtk_error(short_block);
}

TEST(LegacyVtkBinaryErrors, ANonFiniteCoordinateNamesItsByteAndPoint) {
  std::string text = points_and_cells_42();
  const std::size_t data = text.find("POINTS 5 double\n") + 16;
  const std::string nan = be<double>({std::numeric_limits<double>::quiet_NaN()});
  text.replace(data + 7 * 8, 8, nan);  // point 2, y
  const std::string msg = vtk_error(text);
  EXPECT_NE(msg.find("mesh.vtk, byte " + std::to_string(data + 56) + ": non-finite coordinate of point 2"),
            std::string::npos)
      << msg;
}

TEST(LegacyVtkBinaryErrors, TypesThatCannotHoldTheirDataAreNamed) {
  const std::string cells51 = kHeader51 + "POINTS 4 double\n" + be<double>({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}) +
                              "\nCELLS 2 4\nOFFSETS vtktypeint64\n" + be<std::int64_t>({0, 4}) +
                              "\nCONNECTIVITY vtktypeint64\n" + be<std::int64_t>({0, 1, 2, 3}) + "\nCELL_TYPES 1\n" +
                              be<std::int32_t>({10}) + "\n";
  ASSERT_EQ(read_text(cells51).tets, (std::vector<index_t>{0, 1, 2, 3}));

  std::string floats = cells51;
  floats.replace(floats.find("OFFSETS vtktypeint64"), 20, "OFFSETS vtktypefloat64");
  EXPECT_NE(vtk_error(floats).find("offset: expected an integer data type, found 'vtktypefloat64'"),
            std::string::npos);

  std::string huge = cells51;
  const std::size_t connectivity = huge.find("CONNECTIVITY vtktypeint64\n") + 26;
  huge.replace(huge.find("CONNECTIVITY vtktypeint64"), 25, "CONNECTIVITY vtktypeuint64");
  huge.replace(connectivity + 1 + 16, 8, be<std::uint64_t>({std::uint64_t{1} << 63}));  // the third node
  EXPECT_NE(vtk_error(huge).find("mesh.vtk, byte " + std::to_string(connectivity + 1 + 16) +
                                 ": node index: value out of range"),
            std::string::npos)
      << vtk_error(huge);

  // A bit array is skipped where it is not wanted, but it cannot hold tags.
  const std::string bits =
      points_and_cells_42() + "CELL_DATA 3\nFIELD f 1\ntetsmooth:tag 1 3 bit\n" + std::string(1, '\0') + "\n";
  EXPECT_NE(vtk_error(bits).find("value: data type 'bit' cannot be read from a BINARY file"), std::string::npos)
      << vtk_error(bits);
  const std::string strings =
      points_and_cells_42() + "CELL_DATA 3\nFIELD f 1\nnames 1 3 string\n" + std::string("a\nb\nc\n");
  EXPECT_NE(vtk_error(strings).find("value: data type 'string' cannot be read"), std::string::npos)
      << vtk_error(strings);
}

TEST(LegacyVtkBinaryErrors, ScalarsNeedTheirLookupTableLine) {
  const std::string text =
      points_and_cells_42() + "CELL_DATA 3\nSCALARS tetsmooth:tag int 1\n" + be<std::int32_t>({5, 6, 9}) + "\n";
  EXPECT_NE(vtk_error(text).find("SCALARS tetsmooth:tag: a BINARY file needs the LOOKUP_TABLE line"),
            std::string::npos)
      << vtk_error(text);
}

TEST(LegacyVtkBinaryErrors, LinesAreNamedByTheirByteOffset) {
  // Once a file is BINARY, line numbers no longer locate anything past its
  // first block: every message names the byte at which its line starts.
  std::string text = points_and_cells_42();
  const std::size_t types = text.find("CELL_TYPES");
  text.replace(types, 10, "CELL_KINDS");
  EXPECT_NE(vtk_error(text).find("mesh.vtk, byte " + std::to_string(types) + ": unknown or misplaced keyword"),
            std::string::npos)
      << vtk_error(text);
  std::string polydata = kHeader42;
  polydata.replace(polydata.find("UNSTRUCTURED_GRID"), 17, "POLYDATA");
  EXPECT_NE(vtk_error(polydata).find("mesh.vtk, byte " + std::to_string(kHeader42.find("DATASET")) +
                                     ": DATASET 'POLYDATA' is not supported"),
            std::string::npos)
      << vtk_error(polydata);
}


// A node index or offset is checked once the whole file is read: the message
// names the byte of the value itself (its array's start plus its place times
// its type's size), in both layouts, not the line the reader stands at.
TEST(LegacyVtkBinaryErrors, ANodeIndexOrOffsetOutOfRangeNamesItsOwnByte) {
  TetMesh mesh = testing::cube_with_centre(0.4, 0.5, 0.6);
  mesh.tets[5] = 99;  // cell 1, its second node
  const std::string range = ": cell 1: node 99 out of range [0, " + std::to_string(mesh.num_nodes()) + ")";
  const std::string v42 = binary_file(mesh, false);
  const std::size_t cells = v42.find('\n', v42.find("\nCELLS ") + 1) + 1;
  // Cell 0's count and 4 nodes, cell 1's count and first node before it.
  EXPECT_EQ(vtk_error(v42), "mesh.vtk, byte " + std::to_string(cells + 4 * 7) + range);
  const std::string v51 = binary_file(mesh, true);
  const std::size_t connectivity = v51.find("CONNECTIVITY vtktypeint64\n") + 26;
  EXPECT_EQ(vtk_error(v51), "mesh.vtk, byte " + std::to_string(connectivity + 8 * 5) + range);

  // The last offset past the connectivity.
  mesh.tets[5] = 1;
  std::string offsets = binary_file(mesh, true);
  const std::size_t tets = mesh.num_tets();
  const std::size_t last = offsets.find("OFFSETS vtktypeint64\n") + 21 + 8 * tets;
  offsets.replace(last, 8, be<std::int64_t>({99}));
  EXPECT_EQ(vtk_error(offsets), "mesh.vtk, byte " + std::to_string(last) + ": cell " + std::to_string(tets - 1) +
                                    ": offset 99 outside the connectivity array of " + std::to_string(4 * tets));
}

// Meshio's own 5.1 BINARY file, a node index made 99.
TEST(LegacyVtkBinaryErrors, ANodeIndexOutOfRangeInMeshiosFileNamesItsByte) {
  std::ifstream in(testing::data_path("vtk_binary51.vtk"), std::ios::binary);
  std::string text(std::istreambuf_iterator<char>(in), {});
  const std::size_t connectivity = text.find("CONNECTIVITY vtktypeint64\n") + 26;
  text.replace(connectivity + 8 * 6, 8, be<std::int64_t>({99}));  // cell 1, its third node
  EXPECT_EQ(vtk_error(text), "mesh.vtk, byte " + std::to_string(connectivity + 48) +
                                 ": cell 1: node 99 out of range [0, 5)");
}

// Region tags in a signed one-byte array: char is signed in VTK, so the
// byte 0xFF is tag -1, not 255 (negative TetGen-style regions survive).
TEST(LegacyVtkBinary, SignedByteTagsKeepTheirSign) {
  for (const char* type : {"char", "signed_char", "vtktypeint8"}) {
    SCOPED_TRACE(type);
    const std::string text = points_and_cells_42() + "CELL_DATA 3\nSCALARS gmsh:physical " + type +
                             " 1\nLOOKUP_TABLE default\n" + be<std::int8_t>({-1, -128, 7}) + "\n";
    const TetMesh mesh = read_text(text);
    EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{-1, -128}));
    ASSERT_EQ(mesh.extras.blocks.size(), 1u);
    EXPECT_EQ(mesh.extras.blocks[0].tags, (std::vector<int>{7}));
  }
}

// In BINARY the data start on the line after the keyword's: a token left
// on the keyword line means the line is not what the reader takes it for.
TEST(LegacyVtkBinaryErrors, TokensAfterTheArgumentsAreRefused) {
  std::string text = points_and_cells_42();
  text.replace(text.find("POINTS 5 double"), 15, "POINTS 5 double junk");
  const std::string msg = vtk_error(text);
  EXPECT_NE(msg.find("expected the end of the line before coordinate, found 'junk'"), std::string::npos) << msg;
}

}  // namespace
}  // namespace tetsmooth
