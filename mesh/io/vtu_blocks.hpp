#pragma once
// The framing of one VTU DataArray's binary data, inline (format="binary",
// after base64 decoding) or appended (raw, or base64 after decoding).
//
// Uncompressed (no compressor attribute on <VTKFile>):
//
//   [n] [n bytes of values]
//
// Compressed (compressor="vtkZLibDataCompressor" or "vtkLZMADataCompressor"):
//
//   [#blocks] [#u-size] [#p-size] [#c-size-1] ... [#c-size-#blocks]
//   [block 1] ... [block #blocks]
//
// The values are cut into #blocks blocks of #u-size bytes, the last one of
// #p-size bytes (of #u-size when #p-size is 0: VTK writes 0 for a full last
// block, meshio its size), and each block is compressed on its own, to a
// zlib stream (RFC 1950) or an xz stream, of #c-size-i bytes; the blocks
// follow one another without gaps. No values: #blocks is 0.
//
// Every bracketed header item is a header_type integer (UInt32 unless the
// VTKFile says UInt64) in the file's byte_order. In base64 form the header
// and the blocks are encoded separately, each padded on its own (VTK's
// writers and meshio do so), so the data of an appended array begin
// base64_length(header bytes) characters after its offset.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tetsmooth {

enum class VtuCompressor { None, Zlib, Lzma };

// The compressor a VTKFile's compressor attribute names; false for one this
// reader does not know (vtkLZ4DataCompressor among them).
bool vtu_compressor(const std::string& name, VtuCompressor& compressor);

// A bound on how much larger than its compressed form a compressed array
// may be, for rejecting an absurd NumberOfPoints early: far above what
// zlib (1032:1 at most) or xz (about 7000:1 on zeros) reach.
constexpr std::size_t kVtuMaxExpansion = std::size_t{1} << 16;

// How a file frames its binary data, from the VTKFile and AppendedData tags.
struct VtuEncoding {
  bool big_endian = false;
  std::size_t header_bytes = 4;  // UInt32 unless header_type says UInt64
  VtuCompressor compressor = VtuCompressor::None;
  bool has_appended = false;
  bool appended_base64 = false;
  std::size_t appended_begin = 0;  // offset of the byte after the '_'
};

// Reads the framing of one array's bytes. Every problem throws InputError
// with `where` (the file and the byte offset of the array's data) and
// `what` (the array) in front of it.
class VtuBlocks {
 public:
  VtuBlocks(const VtuEncoding& encoding, std::string where, std::string what)
      : enc_(encoding), where_(std::move(where)), what_(std::move(what)) {}

  // The size of the header whose first item (header_bytes bytes) is at
  // `first`; `limit` bounds a sane size (the file's).
  std::size_t header_size(const unsigned char* first, std::size_t limit) const;
  // The bytes that follow the whole header at `header`, at most `limit`.
  std::uint64_t data_size(const unsigned char* header, std::size_t limit) const;

  // The `expected` bytes of values framed in [p, p + n): in place when
  // uncompressed, decompressed into `inflated` when not. `values` names
  // them for messages ("15 Float64 values").
  const unsigned char* values(const unsigned char* p, std::size_t n, std::uint64_t expected, const std::string& values,
                              std::vector<unsigned char>& inflated) const;

 private:
  const unsigned char* plain(const unsigned char* p, std::size_t n, std::uint64_t expected,
                             const std::string& values) const;
  const unsigned char* inflate(const unsigned char* p, std::size_t n, std::uint64_t expected, const std::string& values,
                               std::vector<unsigned char>& inflated) const;
  std::uint64_t item(const unsigned char* header, std::size_t i) const;
  [[noreturn]] void fail(const std::string& problem) const;

  VtuEncoding enc_;
  std::string where_, what_;
};

}  // namespace tetsmooth
