// Legacy VTK BINARY files: meshio's, in the 4.2 and 5.1 layouts (fixtures
// made by tests/data/vtk_binary_make.py), read as the same mesh as their
// ASCII form; every section kind with a binary form; and errors that name
// the byte offset of the value or line at fault.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
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

TEST(LegacyVtkBinary, ReadsWhatItsAsciiFormHolds) {
  const TetMesh binary = read_vtk_file(testing::data_path("vtk_binary51.vtk"));
  std::ostringstream ascii;
  write_vtk(binary, ascii, {});
  const TetMesh back = read_text(ascii.str());
  EXPECT_EQ(back.xyz, binary.xyz);
  EXPECT_EQ(back.tets, binary.tets);
  EXPECT_EQ(back.extras.tet_tags, binary.extras.tet_tags);
  EXPECT_EQ(back.fixed, binary.fixed);
}

TEST(LegacyVtkBinary, EverySectionWithABinaryFormIsReadOrSkipped) {
  // Float points; SCALARS with a table, COLOR_SCALARS (bytes), a standalone
  // LOOKUP_TABLE (bytes), VECTORS, TENSORS, and FIELD arrays of 16-bit,
  // 64-bit and float types, the fixed flags among them.
  const std::string text =
      kHeader42 + "FIELD FieldData 1\nTIME 1 1 double\n" + be<double>({0.5}) + "\nPOINTS 5 float\n" +
      be<float>({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}) + "\nCELLS 2 10\n" +
      be<std::int32_t>({4, 0, 1, 2, 3, 4, 1, 2, 3, 4}) + "\nCELL_TYPES 2\n" + be<std::int32_t>({10, 10}) +
      "\nCELL_DATA 2\nSCALARS tetsmooth:tag short 1\nLOOKUP_TABLE colours\n" + be<std::int16_t>({-3, 8}) +
      "\nCOLOR_SCALARS rgb 3\n" + std::string("\x01\x02\x03\x04\x05\x06", 6) + "\nLOOKUP_TABLE colours 2\n" +
      std::string(8, '\x7f') + "\nTENSORS stress float\n" + be<float>({1, 2, 3, 4, 5, 6, 7, 8, 9}) +
      be<float>({1, 2, 3, 4, 5, 6, 7, 8, 9}) + "\nPOINT_DATA 5\nVECTORS v double\n" +
      be<double>({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15}) + "\nFIELD more 2\nids 1 5 vtktypeint64\n" +
      be<std::int64_t>({1, 2, 3, 4, 5}) + "\ntetsmooth:fixed 1 5 unsigned_short\n" +
      be<std::uint16_t>({0, 1, 0, 0, 0}) + "\n";
  const TetMesh mesh = read_text(text);
  EXPECT_EQ(mesh.xyz, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(mesh.tets, (std::vector<index_t>{0, 1, 2, 3, 1, 2, 3, 4}));
  EXPECT_EQ(mesh.extras.tet_tags, (std::vector<int>{-3, 8}));
  EXPECT_EQ(mesh.fixed, (std::vector<std::uint8_t>{0, 1, 0, 0, 0}));
}

TEST(LegacyVtkBinary, DataBlocksWithoutTheirClosingNewlineStillRead) {
  // VTK and meshio end each block with '\n'; a writer that does not leaves
  // the next keyword right after the data.
  std::string text = points_and_cells_42();
  const std::string cells = "\nCELLS";
  text.erase(text.find(cells), 1);
  expect_fixture_mesh(read_text(text));
}

// Errors ----------------------------------------------------------------------

TEST(LegacyVtkBinaryErrors, ATruncatedBlockNamesTheFirstMissingByte) {
  const std::string whole = points_and_cells_42();
  const std::size_t data = whole.find("POINTS 5 double\n") + 16;
  const std::string cut = whole.substr(0, data + 37);  // inside the fifth coordinate
  EXPECT_NE(vtk_error(cut).find("mesh.vtk, byte " + std::to_string(data + 37) + ": unexpected end of file in coordinate"),
            std::string::npos)
      << vtk_error(cut);
  const std::size_t cells = whole.find("CELLS 3 12\n") + 11;
  const std::string msg = vtk_error(whole.substr(0, cells + 20));
  EXPECT_NE(msg.find("mesh.vtk, byte " + std::to_string(cells + 20) + ": unexpected end of file in CELLS data"),
            std::string::npos)
      << msg;
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

  const std::string bits = points_and_cells_42() + "POINT_DATA 5\nFIELD f 1\nflags 1 5 bit\n" + std::string(1, '\0');
  EXPECT_NE(vtk_error(bits).find("value: data type 'bit' cannot be read from a BINARY file"), std::string::npos)
      << vtk_error(bits);
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
                                     ": DATASET POLYDATA is not supported"),
            std::string::npos)
      << vtk_error(polydata);
}

}  // namespace
}  // namespace tetsmooth
