#pragma once
// Tokenizing of line-oriented text mesh formats (TetGen, legacy VTK, Medit,
// MSH ASCII), keeping the line number so that every error reads
// "file:line: what". Tokens are separated by spaces, tabs and CR (so CRLF
// files read like LF files); a comment character cuts a line short.
#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

namespace tetsmooth {

// Parse a whole token (a leading '+' allowed); false if anything is left over
// or the value does not fit. parse_real accepts "nan" and "inf": the caller
// decides whether non-finite values are acceptable.
bool parse_integer(std::string_view token, long long& value);
bool parse_real(std::string_view token, double& value);

// Text from a file for a message (a token, a name, an attribute value, a
// section name): cut to 40 characters with "..." after, bytes outside
// printable ASCII (line breaks, control bytes, bytes of a binary file)
// written as \xNN, so that a message stays one short line whatever the file
// holds. Every message that echoes file text goes through this;
// quoted_token puts it in single quotes, as most messages want it.
std::string text_excerpt(std::string_view text);
std::string quoted_token(std::string_view token);

// ASCII upper case, as the formats whose names ignore case compare them
// (legacy VTK keywords, Abaqus and Nastran names).
std::string upper_case(std::string_view text);

// `text` without the white space (blanks, tabs, a CR) at either end.
std::string_view trimmed(std::string_view text);

// "a, b, c": a list for a message or a note.
std::string joined(const std::vector<std::string>& items);

// joined's list of the first `most` items, then how many more: "a, b and 3
// more".
std::string listed(const std::vector<std::string>& items, std::size_t most);

// The length of the UTF-8 byte order mark that starts `text` (Windows
// editors write one): 3, or 0 without one. It is not content.
inline std::size_t bom_length(std::string_view text) { return text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0; }

class TextLines {
 public:
  // comment: a character that starts a comment running to the end of the
  // line, or '\0' for formats without comments.
  TextLines(std::istream& in, std::string source, char comment = '#');

  // Line mode: moves to the next line with at least one token; false at the
  // end of the input. A line reached in line mode counts as taken for token
  // mode, whose next token comes from the line after it.
  bool next_line();
  // next_line(), or InputError "unexpected end of file, expected <what>".
  void require_line(const std::string& what);
  // Moves to the next line even if it is blank (free-text lines such as a
  // legacy VTK title); false at the end of the input.
  bool next_raw_line();
  const std::string& line() const { return line_; }

  std::size_t size() const { return tokens_.size(); }
  // Token i of the current line; InputError if the line is shorter.
  std::string_view token(std::size_t i, const char* what) const;
  long long integer(std::size_t i, const char* what) const;
  double real(std::size_t i, const char* what) const;  // finite values only
  // An integer that may be written as a real with a whole value ("1.0",
  // "1e0"), as TetGen, which reads such fields with strtol, and meshio,
  // which writes them from float arrays, have it; "1.5" fails like a bad
  // integer().
  long long whole_number(std::size_t i, const char* what) const;

  // Token mode, for formats whose values may wrap across lines at will
  // (legacy VTK): the tokens after the ones already taken, line by line.
  bool at_end();
  std::string_view next_token(const char* what);
  // The token next_token would return, without taking it; empty at the end.
  std::string_view peek_token();
  // Whether the current line has tokens not yet taken (optional trailing
  // values, such as the component count of a VTK SCALARS line).
  bool line_has_more() const { return cursor_ < tokens_.size(); }
  long long next_integer(const char* what);
  double next_real(const char* what);  // finite values only
  // The next token of the current line, or InputError "expected <what> on
  // this line": for arguments that must share their keyword's line, where
  // the next line may be binary data.
  std::string_view next_token_on_line(const char* what);
  // Drops the rest of the current line and every following line up to and
  // including the next blank one (sections terminated by an empty line).
  void skip_past_blank_line();

  // Raw bytes, for formats that put binary blocks between text lines
  // (legacy VTK BINARY): the `n` bytes that follow the current line, whose
  // tokens must all have been taken; the next token comes from the text
  // after them. InputError at the first missing byte when the input ends
  // first.
  void read_bytes(char* out, std::size_t n, const char* what);
  // read_bytes without keeping them.
  void skip_bytes(std::size_t n, const char* what);
  // Whether the input goes on with a line break ('\n' or '\r') or ends:
  // what must follow a binary block before the text resumes.
  bool at_line_break();
  // Byte offset in the input of the next byte not yet read.
  std::uint64_t next_offset() const { return next_offset_; }
  // From now on where() names the byte offset at which the current line
  // starts ("source, byte N") instead of its number: once binary blocks are
  // read, line numbers no longer locate anything.
  void locate_by_byte() { by_byte_ = true; }
  // "source, byte N", and InputError there ("source, byte N: what").
  std::string where_at_byte(std::uint64_t offset) const;
  [[noreturn]] void fail_at_byte(std::uint64_t offset, const std::string& what) const;

  // A place in the input to count tokens from again: a message about a value
  // read long before (a node index found out of range only once every
  // section is read) can then name its line without a place kept per value.
  struct Mark {
    std::int64_t stream_at = -1;  // stream position of the marked line's start; -1 if the input cannot seek
    std::size_t line = 0;         // its number
    std::size_t token = 0;        // tokens of it already taken
  };
  // The place of the token next_token() would return next.
  Mark mark() const;
  // "source:line" of token n (0 for the first) from `mark` on, read again from
  // the input, which is left at some other place: for a message just before
  // failing. Empty when the input cannot seek back or holds fewer tokens.
  std::string where_of_token(const Mark& mark, std::uint64_t n) const;

  const std::string& source() const { return source_; }
  std::size_t line_number() const { return line_no_; }
  std::string where() const;  // "source:line", or "source, byte N" (locate_by_byte)
  [[noreturn]] void fail(const std::string& what) const;

 private:
  bool read_raw_line();
  void take_bytes(char* out, std::size_t n, const char* what);  // read_bytes, or skip_bytes without `out`
  long long to_integer(std::string_view token, const char* what) const;
  double to_real(std::string_view token, const char* what) const;

  std::istream& in_;
  std::string source_;
  char comment_;
  std::string line_;
  std::vector<std::string_view> tokens_;  // views into line_
  std::size_t cursor_ = 0;                // next token for token mode
  std::size_t line_no_ = 0;
  std::uint64_t line_offset_ = 0, next_offset_ = 0;  // of the current line, of the next byte
  bool by_byte_ = false;
};

}  // namespace tetsmooth
