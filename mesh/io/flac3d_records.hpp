#pragma once
// The lines of a FLAC3D grid as its reader and its writer split them
// (flac3d_io.hpp; not a public API).
#include <string>
#include <string_view>
#include <vector>

namespace tetsmooth::flac3d {

// Whether the line is a comment: its first character other than blanks is
// '*'.
bool is_comment(std::string_view line);

// The line's values, split at blanks (spaces, tabs, CR) and commas; a value
// that starts with a quote (' or ") runs to the same quote and is given
// without them, blanks and all. Returns false, `values` then incomplete,
// when such a quote is not closed.
bool split_values(std::string_view line, std::vector<std::string_view>& values);

// Whether a line that is no comment, split into `values`, is a gridpoint
// record ("G id x y z"): the reader takes the k-th such line for node k, and
// the writer writes node k back in its place.
bool is_gridpoint(const std::vector<std::string_view>& values);

// What a line is to the pins: a comment "* TETSMOOTH PINNED" (the words in
// any case) followed by gridpoint ids alone (Pins: the ids, as text, in
// `ids`), such a comment followed by anything else (Unread: a note says it
// pins nothing), or neither (None).
enum class PinComment { None, Pins, Unread };
PinComment pin_comment(std::string_view line, std::vector<std::string_view>& ids);

// "* TETSMOOTH PINNED", the start of a pin comment line.
inline constexpr const char* kPinnedComment = "* TETSMOOTH PINNED";

}  // namespace tetsmooth::flac3d
