#include "mesh/io/text_lines.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

#include "mesh/errors.hpp"

namespace tetsmooth {
namespace {

std::string_view strip_plus(std::string_view token) {
  // from_chars rejects a leading '+', which Fortran-style writers emit.
  if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') token.remove_prefix(1);
  return token;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

}  // namespace

std::string text_excerpt(std::string_view text) {
  constexpr std::size_t kMax = 40;  // a binary blob must not flood the message
  constexpr char kHex[] = "0123456789abcdef";
  std::string s;
  for (const char c : text.substr(0, kMax)) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x20 && byte < 0x7f) {
      s += c;
    } else {
      s += "\\x";
      s += kHex[byte >> 4];
      s += kHex[byte & 15];
    }
  }
  if (text.size() > kMax) s += "...";
  return s;
}

std::string quoted_token(std::string_view token) { return "'" + text_excerpt(token) + "'"; }

bool parse_integer(std::string_view token, long long& value) {
  token = strip_plus(token);
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end && !token.empty();
}

std::string upper_case(std::string_view text) {
  std::string out(text);
  for (char& c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::string joined(const std::vector<std::string>& items) {
  std::string list;
  for (const std::string& item : items) list += (list.empty() ? "" : ", ") + item;
  return list;
}

std::string listed(const std::vector<std::string>& items, std::size_t most) {
  if (items.size() <= most) return joined(items);
  const std::vector<std::string> first(items.begin(), items.begin() + static_cast<std::ptrdiff_t>(most));
  return joined(first) + " and " + std::to_string(items.size() - most) + " more";
}

bool parse_real(std::string_view token, double& value) {
  token = strip_plus(token);
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  // Out of range (1e999) is reported as such by from_chars; treat it as bad.
  return ec == std::errc() && ptr == end && !token.empty();
}

TextLines::TextLines(std::istream& in, std::string source, char comment)
    : in_(in), source_(std::move(source)), comment_(comment) {}

bool TextLines::read_raw_line() {
  line_offset_ = next_offset_;
  if (!std::getline(in_, line_)) {
    if (in_.bad()) fail("read error");
    line_.clear();
    tokens_.clear();
    cursor_ = 0;
    return false;
  }
  ++line_no_;
  next_offset_ += line_.size() + (in_.eof() ? 0 : 1);  // getline took the '\n' unless the input ended
  tokens_.clear();
  cursor_ = 0;
  std::string_view rest(line_);
  if (comment_ != '\0') rest = rest.substr(0, rest.find(comment_));
  std::size_t i = 0;
  while (i < rest.size()) {
    while (i < rest.size() && is_space(rest[i])) ++i;
    const std::size_t start = i;
    while (i < rest.size() && !is_space(rest[i])) ++i;
    if (i > start) tokens_.push_back(rest.substr(start, i - start));
  }
  return true;
}

bool TextLines::next_line() {
  while (read_raw_line()) {
    if (tokens_.empty()) continue;
    cursor_ = tokens_.size();
    return true;
  }
  return false;
}

bool TextLines::next_raw_line() {
  const bool ok = read_raw_line();
  cursor_ = tokens_.size();
  return ok;
}

void TextLines::require_line(const std::string& what) {
  if (!next_line()) fail("unexpected end of file, expected " + what);
}

std::string_view TextLines::token(std::size_t i, const char* what) const {
  if (i >= tokens_.size())
    fail(std::string("expected ") + what + " (value " + std::to_string(i + 1) + " on the line), found only " +
         std::to_string(tokens_.size()) + " values");
  return tokens_[i];
}

long long TextLines::to_integer(std::string_view token, const char* what) const {
  long long value = 0;
  if (!parse_integer(token, value)) fail(std::string("expected an integer ") + what + ", found " + quoted_token(token));
  return value;
}

double TextLines::to_real(std::string_view token, const char* what) const {
  double value = 0;
  if (!parse_real(token, value)) fail(std::string("expected a number ") + what + ", found " + quoted_token(token));
  if (!std::isfinite(value)) fail(std::string("non-finite ") + what + " " + quoted_token(token));
  return value;
}

long long TextLines::integer(std::size_t i, const char* what) const { return to_integer(token(i, what), what); }
double TextLines::real(std::size_t i, const char* what) const { return to_real(token(i, what), what); }

long long TextLines::whole_number(std::size_t i, const char* what) const {
  const std::string_view t = token(i, what);
  long long value = 0;
  if (parse_integer(t, value)) return value;
  double real = 0;
  // 2^63 as a double: the first whole value past long long.
  if (!parse_real(t, real) || real != std::trunc(real) || !(std::abs(real) < 0x1p63)) return to_integer(t, what);
  return static_cast<long long>(real);
}

bool TextLines::at_end() {
  while (cursor_ >= tokens_.size())
    if (!read_raw_line()) return true;
  return false;
}

std::string_view TextLines::next_token(const char* what) {
  if (at_end()) fail(std::string("unexpected end of file, expected ") + what);
  return tokens_[cursor_++];
}

std::string_view TextLines::next_token_on_line(const char* what) {
  if (cursor_ >= tokens_.size()) fail(std::string("expected ") + what + " on this line");
  return tokens_[cursor_++];
}

std::string_view TextLines::peek_token() { return at_end() ? std::string_view() : tokens_[cursor_]; }

long long TextLines::next_integer(const char* what) { return to_integer(next_token(what), what); }
double TextLines::next_real(const char* what) { return to_real(next_token(what), what); }

void TextLines::skip_past_blank_line() {
  while (read_raw_line()) {
    if (line_.find_first_not_of(" \t\r\v\f") == std::string::npos) return;
  }
}

void TextLines::read_bytes(char* out, std::size_t n, const char* what) { take_bytes(out, n, what); }
void TextLines::skip_bytes(std::size_t n, const char* what) { take_bytes(nullptr, n, what); }

void TextLines::take_bytes(char* out, std::size_t n, const char* what) {
  if (cursor_ < tokens_.size())
    fail(std::string("expected the end of the line before ") + what + ", found " + quoted_token(tokens_[cursor_]));
  if (out)
    in_.read(out, static_cast<std::streamsize>(n));
  else
    in_.ignore(static_cast<std::streamsize>(n));
  const auto got = static_cast<std::size_t>(in_.gcount());
  if (in_.bad()) fail("read error");
  if (got < n) fail_at_byte(next_offset_ + got, std::string("unexpected end of file in ") + what);
  next_offset_ += n;
}

bool TextLines::at_line_break() {
  const int c = in_.peek();
  return c == std::char_traits<char>::eof() || c == '\n' || c == '\r';
}

std::string TextLines::where_at_byte(std::uint64_t offset) const {
  return source_ + ", byte " + std::to_string(offset);
}

void TextLines::fail_at_byte(std::uint64_t offset, const std::string& what) const {
  throw InputError(where_at_byte(offset), what);
}

TextLines::Mark TextLines::mark() const {
  // The stream stands after the current line: step back over it.
  const std::streamoff after = in_.tellg();
  Mark m;
  const auto line_bytes = static_cast<std::int64_t>(next_offset_ - line_offset_);
  m.stream_at = after < 0 ? -1 : static_cast<std::int64_t>(after) - line_bytes;
  m.line = line_no_;
  m.token = cursor_;
  return m;
}

std::string TextLines::where_of_token(const Mark& mark, std::uint64_t n) const {
  if (mark.stream_at < 0) return {};
  in_.clear();
  if (!in_.seekg(mark.stream_at)) return {};
  // Tokenized by the same code as the first reading, so the count agrees.
  TextLines again(in_, source_, comment_);
  again.line_no_ = mark.line == 0 ? 0 : mark.line - 1;
  if (mark.line > 0 && !again.read_raw_line()) return {};
  again.cursor_ = std::min(mark.token, again.tokens_.size());
  for (std::uint64_t i = 0; i < n; ++i) {
    if (again.at_end()) return {};
    ++again.cursor_;
  }
  if (again.at_end()) return {};
  return again.where();
}

// An empty file reports line 1, where the missing content was expected.
std::string TextLines::where() const {
  if (by_byte_) return source_ + ", byte " + std::to_string(line_offset_);
  return source_ + ":" + std::to_string(line_no_ == 0 ? 1 : line_no_);
}

void TextLines::fail(const std::string& what) const { throw InputError(where(), what); }

}  // namespace tetsmooth
