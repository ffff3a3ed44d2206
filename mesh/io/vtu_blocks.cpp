#include "mesh/io/vtu_blocks.hpp"

#include <utility>

#include "mesh/errors.hpp"
#include "mesh/io/inflate.hpp"
#include "mesh/io/little_endian.hpp"

namespace tetsmooth {
namespace {

constexpr std::size_t kCompressedHeaderItems = 3;  // #blocks, #u-size, #p-size; then one #c-size per block

// The decompressed bytes that a block table promises, when at most `most`:
// false otherwise, so that a corrupt table cannot overflow the sum.
bool promised_bytes(std::uint64_t blocks, std::uint64_t block_size, std::uint64_t last_size, std::uint64_t most,
                    std::uint64_t& total) {
  if (blocks == 0) {
    total = 0;
    return true;
  }
  if (blocks > 1 && block_size > most / (blocks - 1)) return false;
  total = (blocks - 1) * block_size + last_size;  // last_size <= block_size: no overflow
  return total <= most;
}

}  // namespace

bool vtu_compressor(const std::string& name, VtuCompressor& compressor) {
  // An empty attribute means no compression, as before there was any.
  static const std::pair<const char*, VtuCompressor> kNames[] = {{"", VtuCompressor::None},
                                                                 {"vtkZLibDataCompressor", VtuCompressor::Zlib},
                                                                 {"vtkLZMADataCompressor", VtuCompressor::Lzma}};
  for (const auto& [known, c] : kNames)
    if (name == known) {
      compressor = c;
      return true;
    }
  return false;
}

std::uint64_t VtuBlocks::item(const unsigned char* header, std::size_t i) const {
  const unsigned char* p = header + i * enc_.header_bytes;
  return enc_.header_bytes == 8 ? load_le<std::uint64_t>(p, enc_.big_endian)
                                : load_le<std::uint32_t>(p, enc_.big_endian);
}

void VtuBlocks::fail(const std::string& problem) const { throw InputError(where_, what_ + ": " + problem); }

std::size_t VtuBlocks::header_size(const unsigned char* first, std::size_t limit) const {
  if (enc_.compressor == VtuCompressor::None) return enc_.header_bytes;
  const std::uint64_t blocks = item(first, 0);
  if (blocks > limit / enc_.header_bytes)
    fail("the compression header's block count " + std::to_string(blocks) + " exceeds the file");
  return (kCompressedHeaderItems + blocks) * enc_.header_bytes;
}

std::uint64_t VtuBlocks::data_size(const unsigned char* header, std::size_t limit) const {
  if (enc_.compressor == VtuCompressor::None) {
    const std::uint64_t n = item(header, 0);
    if (n > limit) fail("block size " + std::to_string(n) + " exceeds the file");
    return n;
  }
  const std::uint64_t blocks = item(header, 0);
  std::uint64_t total = 0;
  for (std::uint64_t k = 0; k < blocks; ++k) {
    const std::uint64_t c = item(header, kCompressedHeaderItems + k);
    if (c > limit - total) fail("compressed block " + std::to_string(k + 1) + " runs past the end of the file");
    total += c;
  }
  return total;
}

const unsigned char* VtuBlocks::values(const unsigned char* p, std::size_t n, std::uint64_t expected,
                                       const std::string& values, std::vector<unsigned char>& inflated) const {
  if (enc_.compressor == VtuCompressor::None) return plain(p, n, expected, values);
  return inflate(p, n, expected, values, inflated);
}

const unsigned char* VtuBlocks::plain(const unsigned char* p, std::size_t n, std::uint64_t expected,
                                      const std::string& values) const {
  if (n < enc_.header_bytes) fail("truncated block header");
  const std::uint64_t bytes = item(p, 0);
  if (bytes != expected)
    fail("block holds " + std::to_string(bytes) + " bytes, expected " + std::to_string(expected) + " for " + values);
  if (n - enc_.header_bytes < bytes)
    fail("truncated: the file ends inside the block of " + std::to_string(bytes) + " bytes");
  return p + enc_.header_bytes;
}

const unsigned char* VtuBlocks::inflate(const unsigned char* p, std::size_t n, std::uint64_t expected,
                                        const std::string& values, std::vector<unsigned char>& inflated) const {
  const std::size_t hb = enc_.header_bytes;
  if (n < kCompressedHeaderItems * hb) fail("truncated compression header");
  const std::uint64_t blocks = item(p, 0);
  if (blocks > n / hb - kCompressedHeaderItems)
    fail("truncated: the compression header of " + std::to_string(blocks) + " blocks runs past the end of the file");
  const std::uint64_t block_size = item(p, 1);
  const std::uint64_t partial = item(p, 2);
  if (partial > block_size)
    fail("the last block's size " + std::to_string(partial) + " exceeds the block size " + std::to_string(block_size));
  const std::uint64_t last_size = partial != 0 ? partial : block_size;
  std::uint64_t total = 0;
  const bool fits = promised_bytes(blocks, block_size, last_size, expected, total);
  if (!fits || total != expected)
    fail("the compressed blocks hold " + (fits ? std::to_string(total) : "more than " + std::to_string(expected)) +
         " bytes, expected " + std::to_string(expected) + " for " + values);

  const Codec codec = enc_.compressor == VtuCompressor::Zlib ? Codec::Zlib : Codec::Xz;
  std::size_t at = static_cast<std::size_t>((kCompressedHeaderItems + blocks) * hb);  // <= n, checked above
  inflated.clear();
  for (std::uint64_t k = 0; k < blocks; ++k) {
    const std::string block = "block " + std::to_string(k + 1) + " of " + std::to_string(blocks);
    const std::uint64_t c = item(p, kCompressedHeaderItems + k);
    if (c > n - at) fail("truncated: the file ends inside compressed " + block);
    const std::uint64_t u = k + 1 == blocks ? last_size : block_size;
    if (std::string problem = inflate_stream(codec, p + at, c, u, inflated); !problem.empty())
      fail(block + ": " + problem);
    at += c;
  }
  return inflated.data();
}

}  // namespace tetsmooth
