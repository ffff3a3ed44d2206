#include "mesh/io/ansys_fields.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "mesh/io/text_lines.hpp"

namespace tetsmooth::ansys {
namespace {

// Reads the digits at `s` into `value` (at most 4 of them, so that a
// format's counts stay small); false without a digit.
bool take_count(std::string_view& s, int& value) {
  std::size_t n = 0;
  value = 0;
  while (n < s.size() && n < 4 && std::isdigit(static_cast<unsigned char>(s[n]))) value = 10 * value + (s[n++] - '0');
  s.remove_prefix(n);
  return n > 0 && (s.empty() || !std::isdigit(static_cast<unsigned char>(s.front())));
}

// One item of a format: "3i9" or "6e21.13e3" (the count may be left off:
// 1). False for anything else.
bool take_item(std::string_view& s, BlockFormat& f) {
  int count = 1;
  if (!s.empty() && std::isdigit(static_cast<unsigned char>(s.front())) && !take_count(s, count)) return false;
  if (s.empty() || count == 0) return false;
  const char kind = static_cast<char>(std::tolower(static_cast<unsigned char>(s.front())));
  s.remove_prefix(1);
  int width = 0;
  if (!take_count(s, width) || width == 0) return false;
  if (kind == 'i') {
    if (f.ints != 0 || f.reals != 0 || f.texts != 0) return false;  // integers once, first
    f.ints = count;
    f.int_width = width;
    return true;
  }
  if (kind == 'a') {  // text fields after the integers (ETBLOCK's KEYOPTs)
    if (f.ints == 0 || f.reals != 0 || f.texts != 0) return false;
    f.texts = count;
    return true;
  }
  if (kind != 'e' && kind != 'd' && kind != 'g') return false;
  if (f.reals != 0 || f.texts != 0 || s.empty() || s.front() != '.') return false;
  s.remove_prefix(1);
  if (!take_count(s, f.decimals)) return false;
  f.exponent_digits = 2;
  if (!s.empty() && (s.front() == 'e' || s.front() == 'E')) {
    s.remove_prefix(1);
    if (!take_count(s, f.exponent_digits) || f.exponent_digits == 0) return false;
  }
  f.reals = count;
  f.real_width = width;
  return true;
}

}  // namespace

std::optional<BlockFormat> parse_block_format(std::string_view line) {
  std::string_view s = trimmed(line);
  if (s.size() < 2 || s.front() != '(' || s.back() != ')') return std::nullopt;
  s = s.substr(1, s.size() - 2);
  BlockFormat f;
  while (true) {
    if (!take_item(s, f)) return std::nullopt;
    if (s.empty()) break;
    if (s.front() != ',') return std::nullopt;
    s.remove_prefix(1);
  }
  if (f.ints == 0) return std::nullopt;  // every block starts with a number
  return f;
}

std::string_view field_at(std::string_view line, std::size_t start, std::size_t width) {
  if (start >= line.size()) return {};
  return line.substr(start, width);
}

bool integer_field(std::string_view field, long long& value) {
  const std::string_view t = trimmed(field);
  value = 0;
  return t.empty() || parse_integer(t, value);
}

bool real_field(std::string_view field, double& value) {
  const std::string_view t = trimmed(field);
  value = 0;
  if (t.empty()) return true;
  std::string text(t);
  for (char& c : text)
    if (c == 'd' || c == 'D') c = 'E';  // Fortran's double-precision exponent
  return parse_real(text, value) && std::isfinite(value);
}

bool format_real(double value, const BlockFormat& format, std::string& out) {
  if (!std::isfinite(value)) return false;
  char buf[64];
  // A field narrower than its decimals need (a sign, a digit, the point,
  // the exponent) gets as many as fit.
  int decimals = std::min(format.decimals, format.real_width - 5 - format.exponent_digits);
  decimals = std::max(0, std::min(decimals, 30));
  std::snprintf(buf, sizeof buf, "%#.*E", decimals, value);  // '#': "5.E-01" without decimals
  // buf: [-]d.dddE±xx(x); rewrite the exponent with the format's digits.
  std::string text(buf);
  const std::size_t e = text.find('E');
  const int exponent = std::atoi(text.c_str() + e + 1);
  const int magnitude = exponent < 0 ? -exponent : exponent;
  int limit = 1;
  for (int d = 0; d < format.exponent_digits && limit < 100000; ++d) limit *= 10;
  if (magnitude >= limit) {
    if (exponent > 0) return false;
    return format_real(0.0, format, out);
  }
  std::string digits = std::to_string(magnitude);
  digits.insert(0, static_cast<std::size_t>(format.exponent_digits) - digits.size(), '0');
  text = text.substr(0, e + 1) + (exponent < 0 ? "-" : "+") + digits;
  if (text.size() > static_cast<std::size_t>(format.real_width)) return false;
  out.append(static_cast<std::size_t>(format.real_width) - text.size(), ' ');
  out += text;
  return true;
}

}  // namespace tetsmooth::ansys
