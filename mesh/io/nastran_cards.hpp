#pragma once
// A Nastran deck taken entry by entry (not a public API; the rules are in
// nastran_io.hpp). An entry's physical lines, in any of the three field
// formats, become one list of data fields, 8 for each logical line: field k
// (2..9, Nastran's numbering) of logical line L is data field
// 8 * (L - 1) + k - 2. A large-field line holds half a logical line. The
// first field (the name, or a continuation marker) and the tenth (a marker)
// are not data. INCLUDE statements are followed (included_lines.hpp): the
// included lines come in their place.
#include <cstddef>
#include <cstdint>
#include <deque>
#include <istream>
#include <string>
#include <vector>

#include "mesh/io/included_lines.hpp"

namespace tetsmooth::nastran {

struct Card {
  std::string name;                 // upper case, without a large field's '*'
  std::vector<std::string> fields;  // data fields without their blanks ("" for a blank one)
  std::uint32_t mark = 0;           // its first line (IncludedLines::mark)
  std::string text;                 // its lines as read (comments between them too), each ending in '\n'

  // Data field d, or "" past the end.
  const std::string& field(std::size_t d) const;
};

class BulkCards {
 public:
  BulkCards(std::istream& in, std::string source);

  enum class Kind { Card, Text, End };
  // The next entry of the bulk data (Card), or a line that is none: before
  // BEGIN BULK, after ENDDATA, a comment or a blank line (Text).
  Kind next();
  const Card& card() const { return card_; }
  // A Text line, ending in '\n'.
  const std::string& text() const { return text_; }
  // Whether the last Text line is a comment of the bulk data, and its mark.
  bool bulk_comment() const { return bulk_comment_; }
  // After the last card: BEGIN BULK was read but no ENDDATA, as in a deck
  // cut short. Bulk data alone (an included file's) needs neither.
  bool bulk_unended() const { return began_bulk_ && part_ != Part::After; }
  std::uint32_t text_mark() const { return text_mark_; }

  // "file:line" of a mark, and InputError there.
  std::string where(std::uint32_t mark) const { return lines_.where_of(mark); }
  [[noreturn]] void fail(std::uint32_t mark, const std::string& what) const;
  // The files INCLUDE read, each once, in the order met.
  const std::vector<std::string>& included() const { return lines_.included(); }

 private:
  struct Line {
    std::string text;  // without its line end
    std::uint32_t mark = 0;
  };
  enum class Part { Undecided, Bulk, After };

  bool read_line(Line& line);
  Kind next_undecided();
  Kind next_bulk();
  Kind take_text(Line line, bool bulk_comment);
  void start_card(const Line& line);
  void add_line(const Line& line, bool first);
  void finish_card();
  void include(const Line& line);

  IncludedLines lines_;
  Part part_ = Part::Undecided;
  bool began_bulk_ = false;
  std::deque<Line> ahead_;  // lines read but not yet taken
  // Lines before BEGIN BULK or the first mesh entry, whichever comes first.
  std::deque<Line> undecided_;
  std::deque<Line> header_;  // lines known to come before BEGIN BULK, to give out as Text

  Card card_;
  bool half_line_ = false;  // the card's last logical line has only a large-field half
  std::string text_;
  bool bulk_comment_ = false;
  std::uint32_t text_mark_ = 0;
};

}  // namespace tetsmooth::nastran
