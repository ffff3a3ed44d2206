#pragma once
// The lines of an Abaqus/CalculiX input deck (.inp), for the reader (not a
// public API). A deck is a sequence of keyword lines ("*Element,
// type=C3D4, elset=Soil"), each followed by its data lines (fields split by
// commas); "**" starts a comment line. Keyword and parameter names ignore
// case and spaces; a keyword line that ends with a comma goes on on the next
// line. *INCLUDE, INPUT=file reads that file in its place (relative to the
// including file's directory), as Abaqus does.
#include <fstream>
#include <istream>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tetsmooth::abaqus {

// A keyword line, parsed.
struct Keyword {
  std::string name;  // upper case, without the '*' and spaces: "ELEMENT", "SOLIDSECTION"
  // Parameters in order: names upper case without spaces, values trimmed
  // and unquoted as written ("" for a parameter without a value).
  std::vector<std::pair<std::string, std::string>> params;

  // The value of parameter `name` (upper case), or nullptr.
  const std::string* param(std::string_view key) const;
};

// Parses a keyword line (its continuation lines joined after it). Throws
// std::invalid_argument with the reason on an unclosed quote.
Keyword parse_keyword(std::string_view line);

// The comma-separated fields of a data line, without surrounding spaces; a
// line's trailing comma leaves no empty last field.
std::vector<std::string_view> split_fields(std::string_view line);

// Whether a data line ends with a comma (an element line that goes on).
bool ends_with_comma(std::string_view line);

// Upper case, spaces removed: how Abaqus compares keyword, parameter and set
// names.
std::string normalized(std::string_view name);

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
  // without the line break and a trailing '\r'.
  const std::string& text() const { return text_; }
  // The parsed keyword, for Kind::Keyword.
  const Keyword& keyword() const { return keyword_; }

  // "file:line" of the current line, and InputError there.
  std::string where() const;
  [[noreturn]] void fail(const std::string& what) const;

  // The files *INCLUDE read, in the order met.
  const std::vector<std::string>& included() const { return included_; }

 private:
  struct Source {
    std::istream* in;
    std::unique_ptr<std::ifstream> owned;
    std::string path;
    std::size_t line = 0;
  };
  bool raw_line(std::string& out);
  void include(const Keyword& kw);

  std::vector<Source> stack_;
  std::string text_;
  Keyword keyword_;
  Kind kind_ = Kind::Data;
  std::string where_;
  std::vector<std::string> included_;
};

}  // namespace tetsmooth::abaqus
