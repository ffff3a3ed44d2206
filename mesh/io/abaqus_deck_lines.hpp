#pragma once
// The lines of an Abaqus/CalculiX input deck (.inp), for the reader (not a
// public API). A deck is a sequence of keyword lines ("*Element,
// type=C3D4, elset=Soil"), each followed by its data lines (fields split by
// commas); "**" starts a comment line. Keyword and parameter names ignore
// case and spaces, and those the reader interprets may be shortened to any
// prefix that no other of them shares (*ELEM, GEN), as Abaqus allows
// unambiguous abbreviations; a keyword line that ends with a comma goes on
// on the next line. *INCLUDE, INPUT=file reads that file in its place, a
// relative path taken from the directory of the deck first read (the job's
// directory, from which Abaqus resolves it), '\' read as '/'.
#include <cstdint>
#include <istream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mesh/io/included_lines.hpp"

namespace tetsmooth::abaqus {

// A keyword line, parsed.
struct Keyword {
  // Upper case, without the '*' and spaces, in full where it shortens one
  // the reader interprets: "ELEMENT", "SOLIDSECTION".
  std::string name;
  // Parameters in order: names as `name`; values trimmed, as written (a
  // quoted value keeps its quotes), "" for a parameter without a value.
  std::vector<std::pair<std::string, std::string>> params;

  // The value of parameter `key` (upper case, in full), or nullptr.
  const std::string* param(std::string_view key) const;
};

// Parses a keyword line (its continuation lines joined after it). Throws
// std::invalid_argument with the reason on an unclosed quote, a name that
// shortens more than one the reader interprets, or a parameter that is no
// name (a data line joined on by a trailing comma).
Keyword parse_keyword(std::string_view line);

// The comma-separated fields of a data line, without surrounding spaces
// (commas inside double quotes separate nothing); a line's trailing comma
// leaves no empty last field.
std::vector<std::string_view> split_fields(std::string_view line);

// Whether a data line ends with a comma (an element line that goes on).
bool ends_with_comma(std::string_view line);

// How Abaqus compares keyword and parameter names: upper case, spaces
// removed.
std::string normalized(std::string_view name);

// How Abaqus compares set names: upper case; a name in double quotes keeps
// its spaces (and loses the quotes), any other loses them.
std::string set_name(std::string_view name);

// A name as the deck writes it, for people to read: trimmed, unquoted.
std::string unquoted(std::string_view value);

class DeckLines {
 public:
  enum class Kind { Keyword, Data, Comment };

  DeckLines(std::istream& in, std::string source);
  ~DeckLines();

  // Moves to the next line (a keyword line with its continuation lines);
  // false at the end of the deck. *INCLUDE lines are followed, not returned.
  bool next();
  Kind kind() const { return kind_; }
  // The line as written (a keyword's continuation lines joined by '\n'),
  // without the line break, a trailing '\r' and a file's byte order mark.
  const std::string& text() const { return text_; }
  // The parsed keyword, for Kind::Keyword.
  const Keyword& keyword() const { return keyword_; }

  // "file:line" of the current line, and InputError there.
  std::string where() const;
  [[noreturn]] void fail(const std::string& what) const;
  // The place of the current line, 4 bytes to keep per item read (a node, an
  // element) for a message once the whole deck is read, and its "file:line".
  std::uint32_t mark() const { return mark_; }
  std::string where_of(std::uint32_t mark) const { return lines_.where_of(mark); }

  // The files *INCLUDE read, each once, in the order met.
  const std::vector<std::string>& included() const { return lines_.included(); }

 private:
  bool raw_line(std::string& out) { return lines_.next(out); }
  void include(const Keyword& kw);

  IncludedLines lines_;
  std::string text_;
  Keyword keyword_;
  Kind kind_ = Kind::Data;
  std::uint32_t mark_ = 0;
};

}  // namespace tetsmooth::abaqus
