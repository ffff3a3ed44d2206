// FLAC3D grid reading (flac3d_io.hpp): a text grid is parsed line by line
// (a binary one by flac3d_binary.cpp) into records, which are resolved once
// the whole grid is read (flac3d_resolve.cpp), since a group may come
// before the zones it holds, and ids name items by the file's numbers.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <istream>
#include <string_view>
#include <utility>
#include <vector>

#include "mesh/errors.hpp"
#include "mesh/io/flac3d_grid_records.hpp"
#include "mesh/io/flac3d_io.hpp"
#include "mesh/io/flac3d_records.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/kept_deck.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth {
namespace {

using flac3d::Elements;
using flac3d::GridRecords;
using flac3d::Group;
using flac3d::ZoneType;

class TextGridParser {
 public:
  TextGridParser(const std::string& text, const std::string& source) : text_(text) { r_.source = source; }
  GridRecords parse();

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(r_.where(line_no_), what); }
  long long id(std::string_view value, const char* what) const;
  void record(std::string_view line);
  void gridpoint();
  void element(Elements& into, char record);
  void group(char record);
  void unread_record();

  const std::string& text_;
  GridRecords r_;
  std::size_t line_no_ = 0;
  std::vector<std::string_view> values_;
  // The group whose ids the next lines may list (an index in r_.groups).
  static constexpr std::size_t kNone = ~std::size_t{0};
  std::size_t open_group_ = kNone;
  // Whether the lines of ids that follow belong to a record not read.
  bool skipping_ = false;
  std::vector<std::pair<std::string, std::size_t>> unread_;  // each kind not read, and its first line
  std::vector<std::size_t> unread_pins_;                     // lines of pin comments that are no list of ids
};

// Why a value that does not parse is not one: too many digits, or no
// number at all (a Fortran exponent, "1.5D+00", is none).
std::string not_read(std::string_view value, bool real) {
  double d = 0;
  const auto [ptr, ec] =
      std::from_chars(value.data() + (!value.empty() && value[0] == '+'), value.data() + value.size(), d);
  const bool digits = std::all_of(value.begin(), value.end(), [](char c) {
    return std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-';
  });
  if (ptr == value.data() + value.size() && ec == std::errc::result_out_of_range)
    return " is out of the range of a double";
  if (!real && digits && !value.empty()) return " is out of range";
  return real ? " is not a number" : " is not a whole number";
}

long long TextGridParser::id(std::string_view value, const char* what) const {
  long long v = 0;
  if (!parse_integer(value, v)) fail(std::string(what) + " " + quoted_token(value) + not_read(value, false));
  if (v <= 0) fail(std::string(what) + " " + std::to_string(v) + " is not positive");
  return v;
}

void TextGridParser::gridpoint() {
  if (values_.size() != 5)
    fail("a gridpoint is 'G id x y z', and this line has " + std::to_string(values_.size()) + " values");
  r_.node_ids.push_back(id(values_[1], "gridpoint id"));
  for (std::size_t c = 0; c < 3; ++c) {
    double v = 0;
    const std::string axis = std::string("coordinate ") + "xyz"[c] + " " + quoted_token(values_[2 + c]);
    if (!parse_real(values_[2 + c], v)) fail(axis + not_read(values_[2 + c], true));
    if (!std::isfinite(v)) fail(axis + " is not finite");
    r_.xyz.push_back(v);
  }
  r_.node_places.push_back(line_no_);
}

void TextGridParser::element(Elements& into, char record) {
  const char* what = record == 'Z' ? "zone" : "face";
  if (values_.size() < 3) fail(std::string("a ") + what + " is '" + record + " type id gridpoints...'");
  const ZoneType* type = flac3d::zone_type(values_[1], record);
  if (type == nullptr)
    fail(std::string(what) + " type " + quoted_token(values_[1]) + " is not one of " + flac3d::zone_codes(record));
  if (values_.size() != 3 + type->nodes)
    fail(std::string("a ") + type->code + " " + what + " has " + std::to_string(type->nodes) +
         " gridpoints, and this line lists " + std::to_string(values_.size() - 3));
  into.types.push_back(type);
  into.ids.push_back(id(values_[2], record == 'Z' ? "zone id" : "face id"));
  into.first.push_back(into.gridpoints.size());
  for (std::size_t k = 0; k < type->nodes; ++k) into.gridpoints.push_back(id(values_[3 + k], "gridpoint id"));
  into.places.push_back(line_no_);
}

void TextGridParser::group(char record) {
  const bool slotted = values_.size() == 4 && upper_case(values_[2]) == "SLOT";
  if (values_.size() != 2 && !slotted)
    fail(std::string("a group is '") + record + "GROUP name' or '" + record + "GROUP name SLOT slot'");
  r_.groups.push_back(Group{record, std::string(values_[1]), slotted ? std::string(values_[3]) : "", {}, {}});
  open_group_ = r_.groups.size() - 1;
}

void TextGridParser::record(std::string_view line) {
  if (!flac3d::split_values(line, values_)) fail("a quote that is not closed");
  if (values_.empty()) return;
  long long first = 0;
  if (parse_integer(values_[0], first)) {
    if (skipping_) return;
    if (open_group_ == kNone) fail("a line of ids outside a ZGROUP or FGROUP");
    Group& g = r_.groups[open_group_];
    for (std::string_view v : values_) {
      g.ids.push_back(id(v, g.record == 'Z' ? "zone id" : "face id"));
      g.places.push_back(line_no_);
    }
    return;
  }
  open_group_ = kNone;
  skipping_ = false;
  const std::string keyword = upper_case(values_[0]);
  if (flac3d::is_gridpoint(values_))
    gridpoint();
  else if (keyword == "Z" || keyword == "F")
    element(keyword == "Z" ? r_.zones : r_.faces, keyword[0]);
  else if (keyword == "ZGROUP" || keyword == "FGROUP")
    group(keyword[0]);
  else
    unread_record();
}

// A record of a kind not read, and the lines of ids after it, are kept in
// the text (written back as they are) and named in a note.
void TextGridParser::unread_record() {
  skipping_ = true;
  const std::string kind = upper_case(values_[0]);
  for (const auto& [k, line] : unread_)
    if (k == kind) return;
  unread_.emplace_back(kind, line_no_);
}

GridRecords TextGridParser::parse() {
  std::size_t start = bom_length(text_);
  while (start < text_.size()) {
    std::size_t end = text_.find('\n', start);
    if (end == std::string::npos) end = text_.size();
    const std::string_view line(text_.data() + start, end - start);
    ++line_no_;
    std::vector<std::string_view> ids;
    // Comments leave a group's ids open: they may come among them.
    switch (flac3d::pin_comment(line, ids)) {
      case flac3d::PinComment::Pins:
        for (std::string_view v : ids) r_.pins.emplace_back(id(v, "pinned gridpoint"), line_no_);
        break;
      case flac3d::PinComment::Unread:
        unread_pins_.push_back(line_no_);
        break;
      case flac3d::PinComment::None:
        if (!flac3d::is_comment(line)) record(line);
        break;
    }
    start = end + 1;
  }
  if (!unread_pins_.empty()) {
    std::vector<std::string> lines;
    for (std::size_t line : unread_pins_) lines.push_back(std::to_string(line));
    r_.notes.push_back(std::string(unread_pins_.size() == 1 ? "line " : "lines ") + joined(lines) +
                       ": a '* TETSMOOTH PINNED' comment whose words are not all gridpoint ids pins nothing");
  }
  if (!unread_.empty()) {
    std::vector<std::string> kinds;
    for (const auto& [kind, line] : unread_)
      kinds.push_back(quoted_token(kind) + " (line " + std::to_string(line) + ")");
    r_.notes.push_back("records of kinds tetsmooth does not read, " + joined(kinds) +
                       ", are kept in FLAC3D output and left out of other formats; gridpoints they name are not "
                       "pinned: list those that must stay on a '* TETSMOOTH PINNED' line");
  }
  return std::move(r_);
}

// A binary grid has zero bytes (its version, 3, has three, and its counts
// and ids more); a text grid has none.
bool is_binary(const std::string& file) { return file.find('\0') != std::string::npos; }

}  // namespace

TetMesh read_flac3d(std::istream& in, const std::string& source) {
  std::string file = read_all(in, source);
  if (file.compare(0, 2, "\xFF\xFE") == 0 || file.compare(0, 2, "\xFE\xFF") == 0)
    throw InputError(source, "UTF-16 text (as Windows PowerShell saves it): save the grid as ASCII or UTF-8");
  const bool binary = is_binary(file);
  if (!binary && file.find('\n') == std::string::npos && file.find('\r') != std::string::npos)
    throw InputError(source, "lines that end in a carriage return alone: save the grid with LF or CRLF line ends");
  TetMesh mesh =
      flac3d::resolve_grid(binary ? flac3d::parse_binary_grid(file, source) : TextGridParser(file, source).parse());
  mesh.extras.raw_sections.emplace_back(binary ? "flac3d:binary" : "flac3d:text", std::move(file));
  stamp_kept_deck(mesh, "flac3d");
  return mesh;
}

TetMesh read_flac3d_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return read_flac3d(in, path);
}

}  // namespace tetsmooth
