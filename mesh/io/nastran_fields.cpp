// Nastran field values (nastran_fields.hpp).
#include "mesh/io/nastran_fields.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "mesh/io/text_lines.hpp"

namespace tetsmooth::nastran {
namespace {

// A number from std::to_chars in `style`: a decimal point always, no
// zeros after the mantissa's last digit, "E" with the exponent's leading
// zeros left out; Nastran's style also leaves out the exponent's '+' and
// writes "0." as ".".
std::string styled(std::string s, RealStyle style) {
  const bool nastran = style == RealStyle::Nastran;
  std::string exponent;
  if (const std::size_t e = s.find('e'); e != std::string::npos) {
    const int power = std::stoi(s.substr(e + 1));
    exponent = (nastran || power < 0 ? "E" : "E+") + std::to_string(power);
    s.resize(e);
  }
  if (s.find('.') == std::string::npos) s += '.';
  // A rounded value's trailing zeros say nothing: 100.00000 as 100.
  s.erase(s.find_last_not_of('0') + 1);
  const bool negative = s[0] == '-';
  if (nastran && s.compare(negative ? 1 : 0, 2, "0.") == 0 && s.size() > (negative ? 3u : 2u))
    s.erase(negative ? 1 : 0, 1);  // 0.25 as .25, but 0. stays
  return s + exponent;
}

// `value` as std::to_chars writes it in `format`, in `style`; "" where it
// does not fit the buffer (fixed notation of a huge value).
template <typename... Format>
std::string to_text(RealStyle style, double value, Format... format) {
  char buf[64];
  const auto result = std::to_chars(buf, buf + sizeof buf, value, format...);
  if (result.ec != std::errc()) return "";
  return styled(std::string(buf, result.ptr), style);
}

}  // namespace

bool parse_real_field(std::string_view field, double& value) {
  std::string s(field);
  for (char& c : s)
    if (c == 'd' || c == 'D') c = 'E';
  if (!parse_real(s, value)) {
    // An exponent's sign after the mantissa, without E: 1.5-3 is 1.5E-3.
    const std::size_t sign = s.find_last_of("+-");
    if (sign == std::string::npos || sign == 0 || s[sign - 1] == 'E' || s[sign - 1] == 'e') return false;
    s.insert(sign, "E");
    if (!parse_real(s, value)) return false;
  }
  return std::isfinite(value);
}

std::string real_field(double value, std::size_t width, RealStyle style) {
  const std::string shortest = to_text(style, value);
  if (!shortest.empty() && shortest.size() <= width) return shortest;  // exact
  std::string best;
  double best_error = INFINITY;
  const auto consider = [&](const std::string& candidate) {
    double back = 0;
    if (candidate.empty() || candidate.size() > width || !parse_real_field(candidate, back)) return;
    const double error = std::fabs(back - value);
    // On a tie the later one: fixed notation, considered last, reads best.
    if (error < best_error || (error == best_error && candidate.size() <= best.size())) {
      best_error = error;
      best = candidate;
    }
  };
  // In each notation the most digits that fit: `bare` is the length without
  // digits, which rounding may make one more or one less than with them
  // (9.96 is "10." bare, 9.96E9 "1.E10"), so one digit more and one fewer
  // are tried too.
  const auto most_digits = [&](auto format, int bare) {
    const int digits = static_cast<int>(width) - bare;
    for (int d = std::min(digits + 1, 17); d >= std::max(digits - 1, 0); --d)
      consider(to_text(style, value, format, d));
  };
  // "d.E<exponent>", the sign: every double fits 8 columns so (C's
  // style only adds the sign of exponents from 100, "-1.E+300").
  most_digits(std::chars_format::scientific,
              static_cast<int>(to_text(style, value, std::chars_format::scientific, 0).size()));
  // The mantissa cut short instead of rounded, which never rounds past the
  // largest double (1.8E308 would).
  const std::string all = to_text(style, value, std::chars_format::scientific, 17);
  if (const std::size_t e = all.find('E'); e != std::string::npos && all.size() - e < width)
    consider(all.substr(0, width - (all.size() - e)) + all.substr(e));
  if (std::fabs(value) < 1e15) {
    // "123." or "0.", whose 0 goes in Nastran's style where digits follow.
    const std::string whole = to_text(style, value, std::chars_format::fixed, 0);
    const bool zero_goes = style == RealStyle::Nastran && std::fabs(value) < 1;
    most_digits(std::chars_format::fixed, static_cast<int>(whole.size()) - (zero_goes ? 1 : 0));
  }
  return best;
}

void write_entry(std::ostream& out, std::string_view name, const std::vector<std::string>& fields, bool large,
                 long long id) {
  const std::size_t per_line = large ? 4 : 8, width = large ? 16 : 8;
  std::size_t used = fields.size();
  while (used > 0 && fields[used - 1].empty()) --used;
  // "+" and the id in base 36 (at most 7 characters for ids of 8 digits).
  std::string marker;
  for (long long rest = id; rest > 0; rest /= 36)
    marker.insert(marker.begin(), "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ"[rest % 36]);
  marker.insert(marker.begin(), '+');
  std::string line(name);
  if (large) line += '*';
  for (std::size_t i = 0; i == 0 || i < used; i += per_line) {
    if (i > 0) line = large ? "*" : marker;
    line.resize(8, ' ');
    for (std::size_t k = i; k < std::min(i + per_line, used); ++k) {
      line.append(width - std::min(width, fields[k].size()), ' ');  // right-justified, as numbers are
      line += fields[k];
    }
    if (!large && i + per_line < used) {
      line.resize(72, ' ');
      line += marker;
    }
    out << line << '\n';
  }
}

}  // namespace tetsmooth::nastran
