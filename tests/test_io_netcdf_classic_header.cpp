// The check of a classic netCDF header before netCDF reads it: a
// well-formed file passes, and every kind of corruption that could crash
// netCDF or have it allocate without bound is refused at its byte.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>

#include "mesh/errors.hpp"
#include "mesh/io/netcdf_classic_header.hpp"
#include "support/input_error.hpp"

namespace tetsmooth {
namespace {

// A CDF-1 file built byte by byte (big-endian, names padded to 4 bytes):
// dimension "n" of 2, a global text attribute, and an int variable "v" over
// n whose 8 bytes of data follow the header.
struct Classic {
  std::string bytes;
  void u32(std::uint32_t v) {
    for (int k = 3; k >= 0; --k) bytes += static_cast<char>(v >> (8 * k) & 0xFF);
  }
  void name(const std::string& n) {
    u32(static_cast<std::uint32_t>(n.size()));
    bytes += n;
    while (bytes.size() % 4 != 0) bytes += '\0';
  }
};

struct Parts {
  std::uint32_t dimension_count = 1, dimension_length = 2, variable_dimension = 0, type = 4, begin = 0;
  std::uint32_t attribute_values = 5;
  std::string second_dimension;  // a second dimension's name, if any
  std::size_t cut = 0;           // bytes cut off the end
};

std::string file(const Parts& p) {
  Classic c;
  c.bytes = std::string("CDF\x01", 4);
  c.u32(0);  // numrecs
  c.u32(10);
  c.u32(p.dimension_count);
  c.name("n");
  c.u32(p.dimension_length);
  if (!p.second_dimension.empty()) {
    c.name(p.second_dimension);
    c.u32(3);
  }
  c.u32(12);  // global attributes
  c.u32(1);
  c.name("title");
  c.u32(2);  // char
  c.u32(p.attribute_values);
  c.bytes += "tet  ";
  while (c.bytes.size() % 4 != 0) c.bytes += '\0';
  c.u32(11);  // variables
  c.u32(1);
  c.name("v");
  c.u32(1);
  c.u32(p.variable_dimension);
  c.u32(0);  // no attributes
  c.u32(0);
  c.u32(p.type);
  c.u32(8);  // vsize
  const std::uint32_t begin = p.begin != 0 ? p.begin : static_cast<std::uint32_t>(c.bytes.size() + 4);
  c.u32(begin);
  c.u32(7);
  c.u32(9);  // the data: two ints
  c.bytes.resize(c.bytes.size() - p.cut);
  return c.bytes;
}

std::string error_of(const Parts& p) {
  return testing::input_error_message([&] { netcdf::check_classic_header(file(p), "t.exo"); }, "a corrupt header");
}

TEST(ClassicHeader, AWellFormedFilePasses) { EXPECT_NO_THROW(netcdf::check_classic_header(file({}), "t.exo")); }

TEST(ClassicHeader, CorruptionIsRefusedAtItsByte) {
  const auto expect = [](Parts p, const std::string& part) {
    const std::string message = error_of(p);
    EXPECT_NE(message.find("t.exo: byte "), std::string::npos) << message;
    EXPECT_NE(message.find(part), std::string::npos) << message;
  };
  Parts p;
  p.dimension_count = 2000000000;
  expect(p, "byte 8: the dimension list counts 2000000000 entries");
  p = {};
  p.attribute_values = 100000;
  expect(p, "an attribute's values run past the end");
  p = {};
  p.variable_dimension = 3;
  expect(p, "variable 'v' names dimension 3, which is not defined");
  p = {};
  p.type = 10;  // a 64-bit int, which CDF-1 does not have
  expect(p, "variable 'v' has an unknown type");
  p = {};
  p.dimension_count = 2;
  p.second_dimension = "n";
  expect(p, "two dimensions are named 'n'");
  p = {};
  p.dimension_length = 1000;
  expect(p, "the data of variable 'v' lie outside the file");
  p = {};
  p.cut = 4;
  expect(p, "the data of variable 'v' lie outside the file");
  p = {};
  p.begin = 4;  // inside the header
  expect(p, "the data of variable 'v' lie outside the file");
  std::string streaming = file({});
  streaming.replace(4, 4, "\xFF\xFF\xFF\xFF");  // netCDF 4.9 would take 2^32 - 1 records
  EXPECT_NE(testing::input_error_message([&] { netcdf::check_classic_header(streaming, "t.exo"); }, "streaming")
                .find("t.exo: byte 4: the record count is that of a file still being written"),
            std::string::npos);
  const std::string cut = file({}).substr(0, 14);
  EXPECT_NE(testing::input_error_message([&] { netcdf::check_classic_header(cut, "t.exo"); }, "14 bytes")
                .find("t.exo: byte 12: the header ends early"),
            std::string::npos);
  EXPECT_NE(testing::input_error_message([] { netcdf::check_classic_header("CDF\x07", "t.exo"); }, "version 7")
                .find("not a classic netCDF file"),
            std::string::npos);
}

}  // namespace
}  // namespace tetsmooth
