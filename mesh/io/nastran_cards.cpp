// Nastran entries from a deck's lines (nastran_cards.hpp).
#include "mesh/io/nastran_cards.hpp"

#include <algorithm>
#include <cctype>

#include "mesh/errors.hpp"
#include "mesh/io/nastran_entry_types.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth::nastran {
namespace {

constexpr std::size_t kFixedColumns = 80;  // Nastran ignores what a fixed-format line has past column 80

constexpr const char* kBlanks = " \t";

std::string trimmed(std::string_view s) {
  const std::size_t first = s.find_first_not_of(kBlanks);
  if (first == std::string_view::npos) return "";
  return std::string(s.substr(first, s.find_last_not_of(kBlanks) + 1 - first));
}

bool blank(const std::string& line) { return line.find_first_not_of(kBlanks) == std::string::npos; }

bool comment(const std::string& line) {
  const std::size_t first = line.find_first_not_of(kBlanks);
  return first != std::string::npos && line[first] == '$';
}

// Where the text after an INCLUDE statement's first word starts, or npos
// for a line that is no INCLUDE (recognized by its first word, however
// indented, as Nastran reads it).
std::size_t include_name_at(const std::string& line) {
  constexpr std::string_view kWord = "INCLUDE";
  const std::size_t first = line.find_first_not_of(kBlanks);
  if (first == std::string::npos || line.size() - first < kWord.size()) return std::string::npos;
  for (std::size_t k = 0; k < kWord.size(); ++k)
    if (std::toupper(static_cast<unsigned char>(line[first + k])) != kWord[k]) return std::string::npos;
  const std::size_t after = first + kWord.size();
  const bool word_ends = after == line.size() || !std::isalnum(static_cast<unsigned char>(line[after]));
  return word_ends ? after : std::string::npos;
}

// A line's text before an inline '$' comment.
std::string_view data_part(const std::string& line) { return std::string_view(line).substr(0, line.find('$')); }

// Tabs to the next multiple of 8 columns, as fixed-format fields are laid.
std::string tabs_expanded(std::string_view line) {
  if (line.find('\t') == std::string_view::npos) return std::string(line);
  std::string out;
  for (char c : line) {
    if (c != '\t') {
      out += c;
      continue;
    }
    do out += ' ';
    while (out.size() % 8 != 0);
  }
  return out;
}

// The first field of a line, upper case: what names an entry.
std::string first_field(const std::string& line) {
  const std::string_view data = data_part(line);
  const std::size_t comma = data.find(',');
  if (comma != std::string_view::npos) return upper_case(trimmed(data.substr(0, comma)));
  return upper_case(trimmed(tabs_expanded(data.substr(0, 8)).substr(0, 8)));
}

// A line that goes on with the entry before it.
bool continuation(const std::string& line) {
  return !line.empty() && (line[0] == '+' || line[0] == '*' || line[0] == ',' || line[0] == ' ' || line[0] == '\t');
}

bool starts_with(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

}  // namespace

const std::string& Card::field(std::size_t d) const {
  static const std::string none;
  return d < fields.size() ? fields[d] : none;
}

BulkCards::BulkCards(std::istream& in, std::string source) : lines_(in, std::move(source)) {}

void BulkCards::fail(std::uint32_t mark, const std::string& what) const { throw InputError(where(mark), what); }

bool BulkCards::read_line(Line& line) {
  if (!ahead_.empty()) {
    line = std::move(ahead_.front());
    ahead_.pop_front();
    return true;
  }
  if (!lines_.next(line.text)) return false;
  line.mark = lines_.mark();
  // Line ends of another system ("\n\r") would leave a carriage return at
  // the start of a line, shifting its columns: refused, not guessed at.
  if (line.text.find('\r') != std::string::npos)
    fail(line.mark, "a carriage return inside the line: the file mixes line ends (give it one kind, LF or CRLF)");
  return true;
}

void BulkCards::include(const Line& line) {
  // INCLUDE 'file', the quoted name going on over the next lines of the
  // file until its closing quote; or INCLUDE file.
  std::string name = trimmed(std::string_view(line.text).substr(include_name_at(line.text)));
  if (!name.empty() && name.front() == '\'') {
    std::string more;
    while (name.find('\'', 1) == std::string::npos) {
      if (!lines_.next(more)) fail(line.mark, "INCLUDE: the file name's closing quote is missing");
      name += trimmed(more);
    }
    name = name.substr(1, name.find('\'', 1) - 1);
  }
  lines_.include(name, "INCLUDE", line.mark);
}

BulkCards::Kind BulkCards::take_text(Line line, bool bulk_comment) {
  text_ = std::move(line.text);
  text_ += '\n';
  text_mark_ = line.mark;
  bulk_comment_ = bulk_comment;
  return Kind::Text;
}

BulkCards::Kind BulkCards::next() {
  if (!header_.empty()) {
    Line line = std::move(header_.front());
    header_.pop_front();
    return take_text(std::move(line), false);
  }
  switch (part_) {
    case Part::Undecided:
      return next_undecided();
    case Part::Bulk:
      return next_bulk();
    case Part::After:
      break;
  }
  Line line;
  return read_line(line) ? take_text(std::move(line), false) : Kind::End;
}

BulkCards::Kind BulkCards::next_undecided() {
  Line line;
  while (read_line(line)) {
    const std::string name = first_field(line.text);
    if (starts_with(name, "BEGIN")) {
      const std::string all = upper_case(line.text);
      if (all.find("SUPER") != std::string::npos)
        fail(line.mark, "superelements are not read: give the model as one bulk data section");
      if (all.find("BULK") == std::string::npos)
        fail(line.mark, "'" + text_excerpt(trimmed(line.text)) + "': only BEGIN BULK is read");
      // What came before was executive and case control: kept, not read.
      header_ = std::move(undecided_);
      undecided_.clear();
      header_.push_back(std::move(line));
      part_ = Part::Bulk;
      began_bulk_ = true;
      return next();
    }
    if (include_name_at(line.text) != std::string::npos) {
      include(line);
      continue;
    }
    if (!comment(line.text) && is_mesh_entry(name)) {
      // No BEGIN BULK: the deck is bulk data from its first line.
      ahead_.push_front(std::move(line));
      ahead_.insert(ahead_.begin(), std::make_move_iterator(undecided_.begin()),
                    std::make_move_iterator(undecided_.end()));
      undecided_.clear();
      part_ = Part::Bulk;
      return next_bulk();
    }
    undecided_.push_back(std::move(line));
  }
  ahead_ = std::move(undecided_);
  undecided_.clear();
  part_ = Part::Bulk;
  return next_bulk();
}

BulkCards::Kind BulkCards::next_bulk() {
  Line line;
  if (!read_line(line)) return Kind::End;
  while (include_name_at(line.text) != std::string::npos) {
    include(line);
    if (!read_line(line)) return Kind::End;
  }
  if (blank(line.text) || comment(line.text)) {
    const bool is_comment = comment(line.text);
    return take_text(std::move(line), is_comment);
  }
  const std::string name = first_field(line.text);
  if (name == "ENDDATA") {
    part_ = Part::After;
    return take_text(std::move(line), false);
  }
  if (starts_with(name, "BEGIN"))
    fail(line.mark, "'" + text_excerpt(trimmed(line.text)) +
                          "' after bulk data: superelements and parts are not read, and BEGIN BULK comes once, "
                          "before the first entry");
  if (starts_with(name, "="))
    fail(line.mark, "replicated entries ('=' lines) are not read: write each entry out");
  if (continuation(line.text)) fail(line.mark, "a continuation line with no entry before it");
  start_card(line);
  std::vector<Line> held;  // comments and blank lines that may fall inside the entry
  Line next_line;
  while (read_line(next_line)) {
    if (blank(next_line.text) || comment(next_line.text)) {
      held.push_back(std::move(next_line));
      continue;
    }
    if (!continuation(next_line.text) || include_name_at(next_line.text) != std::string::npos) {
      ahead_.push_front(std::move(next_line));
      break;
    }
    for (const Line& h : held) card_.text += h.text + '\n';
    held.clear();
    add_line(next_line, false);
  }
  for (auto it = held.rbegin(); it != held.rend(); ++it) ahead_.push_front(std::move(*it));
  finish_card();
  return Kind::Card;
}

void BulkCards::start_card(const Line& line) {
  card_.name.clear();
  card_.fields.clear();
  card_.text.clear();
  card_.mark = line.mark;
  half_line_ = false;
  add_line(line, true);
}

void BulkCards::add_line(const Line& line, bool first) {
  const std::string_view data = data_part(line.text);
  std::string head;
  std::vector<std::string> fields;
  bool large = false;
  if (data.find(',') != std::string_view::npos) {
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = data.find(',', start);
      fields.push_back(trimmed(data.substr(start, comma - start)));
      if (comma == std::string_view::npos) break;
      start = comma + 1;
    }
    head = upper_case(fields.front());
    fields.erase(fields.begin());
    large = first ? !head.empty() && head.back() == '*' : starts_with(head, "*");
    const std::size_t capacity = large ? 4 : 8;
    if (fields.size() > capacity + 1)
      fail(line.mark, "a free-field line of " + std::string(large ? "large" : "small") + " fields holds " +
                            std::to_string(capacity) + " data fields and a continuation marker, and this one has " +
                            std::to_string(fields.size()) + " fields after its first");
    fields.resize(capacity);  // drops the continuation marker
  } else {
    std::string fixed = tabs_expanded(data);
    if (fixed.size() > kFixedColumns) fixed.resize(kFixedColumns);
    fixed.resize(kFixedColumns, ' ');
    head = upper_case(trimmed(fixed.substr(0, 8)));
    large = first ? !head.empty() && head.back() == '*' : starts_with(head, "*");
    const std::size_t width = large ? 16 : 8;
    for (std::size_t k = 0; k < (large ? 4u : 8u); ++k) fields.push_back(trimmed(fixed.substr(8 + k * width, width)));
  }
  if (first) {
    card_.name = head;
    if (large) card_.name.pop_back();
  }
  // A small line after half a logical line starts the next one.
  if (!large && half_line_) card_.fields.resize(card_.fields.size() + 4);
  card_.fields.insert(card_.fields.end(), std::make_move_iterator(fields.begin()),
                      std::make_move_iterator(fields.end()));
  half_line_ = large && !half_line_;
  card_.text += line.text;
  card_.text += '\n';
}

void BulkCards::finish_card() {
  if (half_line_) card_.fields.resize(card_.fields.size() + 4);
  half_line_ = false;
}

}  // namespace tetsmooth::nastran
