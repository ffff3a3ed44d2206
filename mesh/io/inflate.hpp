#pragma once
// Decompression of one complete zlib (RFC 1950) or xz stream whose
// decompressed size is known beforehand, as the blocks of compressed VTU
// data are (vtu_blocks.hpp).
#include <cstddef>
#include <string>
#include <vector>

namespace tetsmooth {

enum class Codec { Zlib, Xz };

// Appends the `size` bytes that the stream [in, in + in_size) decompresses
// to onto `out`. Returns an empty string, or what is wrong: a corrupt or
// truncated stream, one that yields more or fewer than `size` bytes, or
// bytes left over after its end. `out` then holds whatever came out.
//
// The output grows only as the stream yields bytes, never to `size` up
// front, so a corrupt `size` cannot make it allocate more than the data
// really decompresses to. xz decoding may use at most kXzMemoryLimit bytes
// of working memory (its dictionary size is read from the stream).
std::string inflate_stream(Codec codec, const unsigned char* in, std::size_t in_size, std::size_t size,
                           std::vector<unsigned char>& out);

// Twice what `xz -9` needs to decompress (65 MiB); VTK and meshio use at
// most that preset.
constexpr std::size_t kXzMemoryLimit = std::size_t{128} << 20;

}  // namespace tetsmooth
