#include "mesh/io/gmsh_source.hpp"

#include <climits>
#include <cmath>
#include <cstring>

#include "mesh/errors.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth::gmsh {
namespace {

std::string end_mismatch(std::string_view end_name, std::string_view found) {
  return "expected " + std::string(end_name) + ", found " + quoted_token(found) +
         " (do the counts in the section header match its data?)";
}

}  // namespace

// ---- ASCII ----------------------------------------------------------------

std::string_view AsciiSource::current_line() const {
  // TextLines hands out tokens as views into the line it holds, so the span
  // from the first token to the end of the last is the line without its
  // surrounding blanks: the text a section body is kept verbatim as.
  const std::string_view first = lines_.token(0, "a value");
  const std::string_view last = lines_.token(lines_.size() - 1, "a value");
  return {first.data(), static_cast<std::size_t>(last.data() + last.size() - first.data())};
}

bool AsciiSource::advance() {
  if (!lines_.next_line()) return false;
  started_ = true;
  taken_ = 0;
  if (recording_) {
    record_ += current_line();
    record_ += '\n';
  }
  return true;
}

std::string_view AsciiSource::token(const char* what) {
  while (!started_ || taken_ >= lines_.size())
    if (!advance()) fail(std::string("unexpected end of file, expected ") + what);
  return lines_.token(taken_++, what);
}

std::string_view AsciiSource::next_section() {
  while (!started_ || taken_ >= lines_.size())
    if (!advance()) return {};
  const std::string_view name = lines_.token(taken_++, "a section");
  alone_on_line(name);
  return name;
}

void AsciiSource::expect_end(std::string_view end_name) {
  const std::string name(end_name);
  const std::string_view found = token(name.c_str());
  if (found != end_name) fail(end_mismatch(end_name, found));
  alone_on_line(found);
}

// Section lines hold nothing else, so that a section body starts on a line
// of its own (and is kept verbatim as whole lines).
void AsciiSource::alone_on_line(std::string_view name) const {
  if (taken_ < lines_.size())
    fail("unexpected " + quoted_token(lines_.token(taken_, "a value")) + " after " + text_excerpt(name));
}

void AsciiSource::skip_section(std::string_view end_name) {
  while (advance()) {
    if (lines_.token(0, "a value") == end_name) {
      taken_ = 1;
      return;
    }
  }
  fail("unexpected end of file, expected " + text_excerpt(end_name));
}

std::string_view AsciiSource::line(const char* what) {
  if (!advance()) fail(std::string("unexpected end of file, expected ") + what);
  taken_ = lines_.size();
  return current_line();
}

std::uint64_t AsciiSource::size_value(const char* what) {
  token(what);
  const long long v = lines_.integer(taken_ - 1, what);
  if (v < 0) fail(std::string("negative ") + what + " " + std::to_string(v));
  return static_cast<std::uint64_t>(v);
}

int AsciiSource::int_value(const char* what) {
  token(what);
  const long long v = lines_.integer(taken_ - 1, what);
  if (v < INT_MIN || v > INT_MAX) fail(std::string(what) + " " + std::to_string(v) + " is out of the 32-bit range");
  return static_cast<int>(v);
}

double AsciiSource::real_value(const char* what) {
  token(what);
  return lines_.real(taken_ - 1, what);
}

void AsciiSource::start_recording() {
  recording_ = true;
  record_.clear();
}

std::string AsciiSource::stop_recording() {
  recording_ = false;
  return std::move(record_);
}

// ---- binary ---------------------------------------------------------------

std::string BinarySource::where() const { return source_ + ", byte " + std::to_string(base_ + pos_); }

void BinarySource::fail(const std::string& what) const { throw InputError(where(), what); }

void BinarySource::skip_blank() {
  while (pos_ < data_.size()) {
    const char c = data_[pos_];
    if (c != ' ' && c != '\t' && c != '\r' && c != '\n') return;
    ++pos_;
  }
}

std::string_view BinarySource::raw_line() {
  const std::size_t end = data_.find('\n', pos_);
  const std::size_t stop = end == std::string::npos ? data_.size() : end;
  std::string_view text(data_.data() + pos_, stop - pos_);
  while (!text.empty() && (text.back() == '\r' || text.back() == ' ' || text.back() == '\t')) text.remove_suffix(1);
  pos_ = end == std::string::npos ? data_.size() : end + 1;
  return text;
}

std::string_view BinarySource::next_section() {
  skip_blank();
  if (pos_ == data_.size()) return {};
  return raw_line();
}

void BinarySource::expect_end(std::string_view end_name) {
  skip_blank();
  if (pos_ == data_.size()) fail("unexpected end of file, expected " + std::string(end_name));
  const std::size_t mark = pos_;
  const std::string_view found = raw_line();
  if (found != end_name) {
    pos_ = mark;
    fail(end_mismatch(end_name, found));
  }
}

void BinarySource::skip_section(std::string_view end_name) {
  // Binary payloads have no line structure, so look for the end marker
  // standing alone at the start of a line.
  for (std::size_t from = pos_;;) {
    const std::size_t at = data_.find(end_name, from);
    if (at == std::string::npos) fail("unexpected end of file, expected " + text_excerpt(end_name));
    const std::size_t after = at + end_name.size();
    const bool starts_line = at == pos_ || data_[at - 1] == '\n';
    const bool ends_line = after == data_.size() || data_[after] == '\n' || data_[after] == '\r';
    if (starts_line && ends_line) {
      pos_ = after;
      return;
    }
    from = at + 1;
  }
}

std::string_view BinarySource::line(const char* what) {
  skip_blank();
  if (pos_ == data_.size()) fail(std::string("unexpected end of file, expected ") + what);
  return raw_line();
}

void BinarySource::read_raw(void* out, std::size_t bytes, const char* what) {
  if (data_.size() - pos_ < bytes)
    fail(std::string("unexpected end of file, expected ") + what + " (" + std::to_string(bytes) + " bytes)");
  std::memcpy(out, data_.data() + pos_, bytes);
  if (swap_) {
    auto* p = static_cast<unsigned char*>(out);
    for (std::size_t i = 0; i < bytes / 2; ++i) std::swap(p[i], p[bytes - 1 - i]);
  }
  pos_ += bytes;
}

std::uint64_t BinarySource::size_value(const char* what) {
  std::uint64_t v = 0;
  read_raw(&v, sizeof v, what);
  return v;
}

int BinarySource::int_value(const char* what) {
  std::int32_t v = 0;
  read_raw(&v, sizeof v, what);
  return v;
}

double BinarySource::real_value(const char* what) {
  double v = 0;
  read_raw(&v, sizeof v, what);
  if (!std::isfinite(v)) {
    pos_ -= sizeof v;
    fail(std::string("non-finite ") + what);
  }
  return v;
}

std::uint64_t BinarySource::text_count(const char* what) {
  const std::size_t mark = pos_;
  const std::string_view text = line(what);
  long long v = 0;
  if (!parse_integer(text, v) || v < 0) {
    pos_ = mark;
    fail(std::string("expected ") + what + " as a text line, found " + quoted_token(text));
  }
  return static_cast<std::uint64_t>(v);
}

std::size_t BinarySource::reservable(std::uint64_t count, std::size_t min_bytes_each) const {
  const std::size_t left = data_.size() - pos_;
  if (min_bytes_each > 0 && count > left / min_bytes_each)
    fail(std::to_string(count) + " items of at least " + std::to_string(min_bytes_each) +
         " bytes each cannot fit in the " + std::to_string(left) + " bytes left (truncated or corrupt count)");
  return static_cast<std::size_t>(count);
}

}  // namespace tetsmooth::gmsh
