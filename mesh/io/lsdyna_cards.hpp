#pragma once
// The lines of an LS-DYNA keyword deck, field by field (not a public API;
// lsdyna_io.hpp describes the deck).
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tetsmooth::lsdyna {

// Column layouts: standard (ids in 8 or 10 columns), I10 (ids in 10) and
// long (every field narrower than 20 columns widened to 20, a card still on
// one line: *NODE's six fields take 120 columns, a solid's ten 200; text
// fields of 80, such as titles and file names, stay as they are).
enum class Layout { Standard, I10, Long };
// The mark after a keyword that asks for a layout ("-", "%", "+"), and the
// layout's name in messages.
const char* layout_mark(Layout layout);
const char* layout_name(Layout layout);

// A keyword line: "*NODE %" is {"NODE", I10, true}.
struct Keyword {
  std::string name;  // upper case, without the '*' and the layout mark
  Layout layout = Layout::Standard;
  bool marked = false;  // a '+', '%' or '-' gave the layout
  std::string rest;     // what follows the name and the mark on the line (*KEYWORD's options)
};
// `line` starts with '*'.
Keyword keyword_of(std::string_view line);

// A card's fields: the columns of `widths` in fixed format, or the texts
// between commas where the line has one (free format), each without its
// blanks; fields the line does not reach are empty.
struct Card {
  std::vector<std::string_view> fields;
  bool free = false;
  const std::string_view& operator[](std::size_t k) const;  // "" past the last field

 private:
  static const std::string_view kBlank;
};
Card card_of(std::string_view line, const std::vector<int>& widths);

// A whole number: blank is 0; "7", "+7", "7." and "7.0" are 7. False for
// anything else.
bool int_field(std::string_view field, long long& value);
// A real as Fortran reads it (nastran_fields.hpp: parse_real_field): blank
// is 0.
bool real_field(std::string_view field, double& value);

// `value` in a coordinate's `width` columns (16, or 20 in the long layout),
// right-aligned after at least one blank so that the fields stay apart to
// the eye and to readers that split at blanks: nastran::real_field in
// width - 1 columns in C's style ("0.25", "1.5E+20"): the shortest form
// that reads back exactly where it fits, else as many significant digits
// as fit (in 16 columns at least 12 for sizes from 0.1 to 1e12, 13 but for
// negative values below 1; in 20, 16 or more).
std::string coordinate_field(double value, std::size_t width = 16);
// coordinate_field without its blanks, for a free-format card, whose
// fields may not be wider than in fixed columns.
std::string free_coordinate(double value, std::size_t width = 16);

// The widths of the fields of *NODE (NID X Y Z TC RC) and of the ten-field
// element cards, in `layout`.
const std::vector<int>& node_widths(Layout layout);
const std::vector<int>& element_widths(Layout layout);
// The widths of the eight-field cards most other keywords use (10 columns,
// 20 in the long layout).
const std::vector<int>& wide_widths(Layout layout);

}  // namespace tetsmooth::lsdyna
