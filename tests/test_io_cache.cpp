// The .tsm cache: bit-exact round trips, and every kind of damage (magic,
// version, counts, truncation at any length, flipped bytes, trailing bytes)
// rejected with an InputError naming the file and the byte offset.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>

#include "mesh/errors.hpp"
#include "mesh/io/tsm_cache.hpp"
#include "support/scratch_dir.hpp"
#include "support/test_meshes.hpp"
#include "input_error.hpp"

namespace tetsmooth {
namespace {

std::string bytes_of(const TetMesh& mesh) {
  std::ostringstream out;
  write_cache(mesh, out);
  return out.str();
}

// The InputError message from reading `bytes` as cube.tsm, or a test failure.
std::string read_error(const std::string& bytes) {
  std::istringstream in(bytes);
  return testing::input_error_message([&] { read_cache(in, "cube.tsm"); },
                                      "read_cache, " + std::to_string(bytes.size()) + " bytes");
}

TEST(TsmCache, LayoutMatchesTheDocumentedSize) {
  const TetMesh mesh = testing::cube_with_centre();
  const std::string bytes = bytes_of(mesh);
  EXPECT_EQ(bytes.size(), 32 + 24 * mesh.num_nodes() + 16 * mesh.num_tets() + 8);
  EXPECT_EQ(bytes.substr(1, 3), "TSM");
  EXPECT_EQ(static_cast<unsigned char>(bytes[8]), kTsmVersion);  // little-endian version
}

// FNV-1a 64 as published (offset basis 0xcbf29ce484222325, prime
// 0x100000001b3, xor then multiply), written here from the definition.
std::uint64_t fnv1a_64(const std::string& bytes) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : bytes) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

std::uint64_t le64_at(const std::string& bytes, std::size_t at) {
  std::uint64_t v = 0;
  for (int k = 7; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)]);
  return v;
}

// The trailer of a cache with `bytes` before it, as the layout documents it.
std::string with_checksum(const std::string& body) {
  std::string out = body;
  std::uint64_t h = fnv1a_64(body);
  for (int k = 0; k < 8; ++k, h >>= 8) out += static_cast<char>(h & 0xff);
  return out;
}

// The documented layout byte by byte: a cache written by another build, or
// read by another tool, agrees on the magic and on the checksum being FNV-1a
// (a self-consistent variant, FNV-1 say, would round-trip and still break
// every cache already on disk).
TEST(TsmCache, MagicAndChecksumAreTheDocumentedOnes) {
  ASSERT_EQ(fnv1a_64("a"), 0xaf63dc4c8601ec8cULL);  // the published test vector
  const std::string bytes = bytes_of(testing::regular_tet());
  EXPECT_EQ(bytes.substr(0, 8), std::string("\x89TSM\r\n\x1a\n", 8));
  EXPECT_EQ(le64_at(bytes, 16), 4u);
  EXPECT_EQ(le64_at(bytes, 24), 1u);
  EXPECT_EQ(le64_at(bytes, bytes.size() - 8), fnv1a_64(bytes.substr(0, bytes.size() - 8)));
}

// Non-zero flags with a checksum that matches them are refused for the flags
// themselves (byte 12), not passed because the checksum agrees.
TEST(TsmCache, RejectsUnknownFlagsAtByteTwelve) {
  const std::string bytes = bytes_of(testing::regular_tet());
  std::string body = bytes.substr(0, bytes.size() - 8);
  body[12] = 1;
  const std::string msg = read_error(with_checksum(body));
  EXPECT_NE(msg.find("cube.tsm, byte 12"), std::string::npos) << msg;
  EXPECT_NE(msg.find("unknown flags 1"), std::string::npos) << msg;
}

// Values are converted 65,536 at a time: a mesh of more than one batch of
// coordinates (29,791 nodes: 89,373 values) and of tets (27,000 cubes: 648,000
// indices) round-trips bit for bit across the batch boundaries.
TEST(TsmCache, RoundTripAcrossConversionBatches) {
  const TetMesh mesh = testing::cube_grid(30, 0.3);
  ASSERT_GT(mesh.xyz.size(), 65536u);
  ASSERT_GT(mesh.tets.size(), 65536u);
  std::istringstream in(bytes_of(mesh));
  const TetMesh back = read_cache(in, "cube.tsm");
  ASSERT_EQ(back.xyz.size(), mesh.xyz.size());
  EXPECT_EQ(std::memcmp(back.xyz.data(), mesh.xyz.data(), mesh.xyz.size() * sizeof(double)), 0);
  EXPECT_EQ(back.tets, mesh.tets);
}

TEST(TsmCache, RoundTripIsBitExact) {
  TetMesh mesh = testing::cube_grid(4, 0.35);
  mesh.xyz[0] = -0.0;                     // sign of zero survives
  mesh.xyz[1] = 4.9406564584124654e-324;  // so does a denormal
  std::istringstream in(bytes_of(mesh));
  const TetMesh back = read_cache(in, "cube.tsm");
  ASSERT_EQ(back.xyz.size(), mesh.xyz.size());
  EXPECT_EQ(std::memcmp(back.xyz.data(), mesh.xyz.data(), mesh.xyz.size() * sizeof(double)), 0);
  EXPECT_EQ(back.tets, mesh.tets);
}

TEST(TsmCache, FileRoundTrip) {
  const testing::ScratchDir dir("cache");
  const std::string path = dir.file("roundtrip.tsm");
  const TetMesh mesh = testing::cube_with_centre(0.3, 0.6, 0.45);
  write_cache_file(mesh, path);
  const TetMesh back = read_cache_file(path);
  EXPECT_EQ(back.xyz, mesh.xyz);
  EXPECT_EQ(back.tets, mesh.tets);
}

TEST(TsmCache, RejectsWrongMagicAtByteZero) {
  std::string bytes = bytes_of(testing::regular_tet());
  bytes[1] = 'X';
  const std::string msg = read_error(bytes);
  EXPECT_NE(msg.find("cube.tsm, byte 0"), std::string::npos) << msg;
  EXPECT_NE(msg.find("magic"), std::string::npos) << msg;
  EXPECT_NE(read_error("# vtk DataFile Version 4.2\n").find("magic"), std::string::npos);
}

TEST(TsmCache, RejectsOtherVersionAtByteEight) {
  std::string bytes = bytes_of(testing::regular_tet());
  bytes[8] = 2;
  const std::string msg = read_error(bytes);
  EXPECT_NE(msg.find("cube.tsm, byte 8"), std::string::npos) << msg;
  EXPECT_NE(msg.find("version 2"), std::string::npos) << msg;
}

TEST(TsmCache, RejectsImplausibleCounts) {
  std::string bytes = bytes_of(testing::regular_tet());
  bytes[16 + 7] = 0x10;  // node count >= 2^60
  EXPECT_NE(read_error(bytes).find("byte 16"), std::string::npos);
  bytes = bytes_of(testing::regular_tet());
  bytes[24 + 4] = 0x01;  // tet count 2^32 + 1: within no index range
  EXPECT_NE(read_error(bytes).find("byte 24"), std::string::npos);
  bytes = bytes_of(testing::regular_tet());
  bytes[24 + 3] = 0x20;  // 2^29 + 1 tets: 4 node-to-tet entries a tet pass 32-bit offsets
  const std::string msg = read_error(bytes);
  EXPECT_NE(msg.find("byte 24"), std::string::npos) << msg;
  EXPECT_NE(msg.find("536870911"), std::string::npos) << msg;
}

TEST(TsmCache, RejectsCountsLargerThanTheFile) {
  std::string bytes = bytes_of(testing::regular_tet());
  bytes[16 + 3] = 0x10;  // claims 2^28 + 4 nodes
  const std::string msg = read_error(bytes);
  EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;
}

TEST(TsmCache, RejectsEveryTruncation) {
  const std::string bytes = bytes_of(testing::regular_tet());
  for (std::size_t len = 0; len < bytes.size(); ++len) {
    const std::string msg = read_error(bytes.substr(0, len));
    EXPECT_NE(msg.find("cube.tsm, byte " + std::to_string(len)), std::string::npos) << len << ": " << msg;
    EXPECT_NE(msg.find("truncated"), std::string::npos) << len << ": " << msg;
  }
}

TEST(TsmCache, RejectsEveryFlippedByte) {
  const std::string bytes = bytes_of(testing::cube_with_centre());
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    std::string damaged = bytes;
    damaged[i] = static_cast<char>(damaged[i] ^ 0x20);
    EXPECT_FALSE(read_error(damaged).empty()) << "byte " << i;
  }
}

TEST(TsmCache, ChecksumMismatchNamesTheChecksumOffset) {
  std::string bytes = bytes_of(testing::regular_tet());
  bytes[40] = static_cast<char>(bytes[40] ^ 1);  // inside the coordinates
  const std::string msg = read_error(bytes);
  EXPECT_NE(msg.find("checksum"), std::string::npos) << msg;
  EXPECT_NE(msg.find("byte " + std::to_string(bytes.size() - 8)), std::string::npos) << msg;
}

TEST(TsmCache, RejectsTrailingBytes) {
  const std::string msg = read_error(bytes_of(testing::regular_tet()) + "x");
  EXPECT_NE(msg.find("after the checksum"), std::string::npos) << msg;
}

TEST(TsmCache, ValidatesTheMesh) {
  TetMesh mesh = testing::regular_tet();
  mesh.tets[3] = 7;  // out of range, yet a well-formed cache
  const std::string msg = read_error(bytes_of(mesh));
  EXPECT_NE(msg.find("cube.tsm"), std::string::npos) << msg;
  EXPECT_NE(msg.find("tet 0"), std::string::npos) << msg;
}

}  // namespace
}  // namespace tetsmooth
