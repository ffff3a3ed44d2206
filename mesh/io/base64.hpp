#pragma once
// Base64 decoding for VTU binary data (RFC 4648 alphabet). Whitespace is
// skipped; padding may close any 4-character group, not only the last, so
// that blocks encoded one after another (VTK encodes a data block's header
// separately from its data) decode as one byte sequence.
#include <cstddef>
#include <string_view>
#include <vector>

namespace tetsmooth {

// Appends the decoded bytes to `out`. Returns false on a character outside
// the alphabet or an incomplete final group; `bad_at` is then its index in
// `text`.
bool base64_decode(std::string_view text, std::vector<unsigned char>& out, std::size_t& bad_at);

// Characters needed to encode n bytes: 4 per 3-byte group, padded.
inline std::size_t base64_length(std::size_t n) { return (n + 2) / 3 * 4; }

}  // namespace tetsmooth
