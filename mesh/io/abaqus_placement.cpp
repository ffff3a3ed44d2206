#include "mesh/io/abaqus_placement.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "mesh/io/number_text.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth::abaqus {
namespace {

constexpr double kPi = 3.14159265358979323846;

double finite_field(std::string_view field) {
  double v = 0;
  if (field.empty()) return 0;  // an omitted value is 0, as on *NODE lines
  if (!parse_real(field, v) || !std::isfinite(v))
    throw std::invalid_argument("expected a finite number, found '" + std::string(field) + "'");
  return v;
}

}  // namespace

Placement Placement::from_lines(const std::vector<std::vector<std::string_view>>& lines) {
  Placement p;
  if (lines.size() > 2) throw std::invalid_argument("*INSTANCE has at most two data lines: a translation, a rotation");
  if (!lines.empty()) {
    if (lines[0].size() > 3) throw std::invalid_argument("a translation line is 'x, y, z'");
    for (std::size_t c = 0; c < lines[0].size(); ++c) p.t_[c] = finite_field(lines[0][c]);
  }
  if (lines.size() == 2) {
    if (lines[1].size() != 7)
      throw std::invalid_argument("a rotation line is 'ax, ay, az, bx, by, bz, angle' (7 fields, not " +
                                  std::to_string(lines[1].size()) + ")");
    std::array<double, 7> f{};
    for (std::size_t c = 0; c < 7; ++c) f[c] = finite_field(lines[1][c]);
    std::array<double, 3> u{f[3] - f[0], f[4] - f[1], f[5] - f[2]};
    const double length = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
    if (length == 0) throw std::invalid_argument("the rotation axis needs two different points a and b");
    for (double& x : u) x /= length;
    const double angle = f[6] * kPi / 180, c = std::cos(angle), s = std::sin(angle), k = 1 - c;
    // Rodrigues' formula: R = c I + s [u]x + (1 - c) u u^T.
    p.r_ = {c + k * u[0] * u[0],        k * u[0] * u[1] - s * u[2], k * u[0] * u[2] + s * u[1],
            k * u[1] * u[0] + s * u[2], c + k * u[1] * u[1],        k * u[1] * u[2] - s * u[0],
            k * u[2] * u[0] - s * u[1], k * u[2] * u[1] + s * u[0], c + k * u[2] * u[2]};
    p.a_ = {f[0], f[1], f[2]};
  }
  p.moves_ = p.t_ != std::array<double, 3>{} || p.r_ != Placement().r_;
  return p;
}

std::array<double, 3> Placement::place(const double* part) const {
  if (!moves_) return {part[0], part[1], part[2]};
  std::array<double, 3> d{}, x{};
  for (int c = 0; c < 3; ++c) d[c] = part[c] + t_[c] - a_[c];
  for (int i = 0; i < 3; ++i) x[i] = r_[3 * i] * d[0] + r_[3 * i + 1] * d[1] + r_[3 * i + 2] * d[2] + a_[i];
  return x;
}

std::array<double, 3> Placement::part_of(const double* assembly) const {
  if (!moves_) return {assembly[0], assembly[1], assembly[2]};
  std::array<double, 3> d{}, p{};
  for (int c = 0; c < 3; ++c) d[c] = assembly[c] - a_[c];
  for (int j = 0; j < 3; ++j) p[j] = r_[j] * d[0] + r_[3 + j] * d[1] + r_[6 + j] * d[2] + a_[j] - t_[j];
  return p;
}

std::string Placement::to_text() const {
  std::ostringstream out;
  const auto put = [&](const auto& values) {
    for (double v : values) {
      put_real(out, v);
      out << ' ';
    }
  };
  put(t_);
  put(a_);
  put(r_);
  return out.str();
}

Placement Placement::from_text(std::string_view text) {
  Placement p;
  std::vector<double> values;
  std::istringstream in{std::string(text)};
  for (std::string token; in >> token;) {
    double v = 0;
    if (!parse_real(token, v)) throw std::invalid_argument("not a placement: '" + std::string(text) + "'");
    values.push_back(v);
  }
  if (values.size() != 15) throw std::invalid_argument("not a placement: '" + std::string(text) + "'");
  std::copy_n(values.begin(), 3, p.t_.begin());
  std::copy_n(values.begin() + 3, 3, p.a_.begin());
  std::copy_n(values.begin() + 6, 9, p.r_.begin());
  p.moves_ = true;
  return p;
}

}  // namespace tetsmooth::abaqus
