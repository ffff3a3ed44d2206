#pragma once
// Where an *INSTANCE puts its part in the assembly (not a public API): the
// optional data lines of *INSTANCE, PART=..., a translation "x, y, z" and a
// rotation "ax, ay, az, bx, by, bz, angle" about the axis from point a to
// point b, in degrees, right-handed (Abaqus Keywords Reference, *INSTANCE),
// the translation applied first: the Reference lists the lines without
// saying their order, and we read it from the decks Abaqus/CAE writes, whose
// rotation axis passes through the translated part. A node at part
// coordinates p sits at R (p + t - a) + a in the assembly.
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace tetsmooth::abaqus {

class Placement {
 public:
  // No motion: part coordinates are assembly coordinates.
  Placement() = default;
  // From the fields of *INSTANCE's data lines (one or two lines). Throws
  // std::invalid_argument with the reason for a line of the wrong length, a
  // field that is no finite number, or an axis whose points coincide.
  static Placement from_lines(const std::vector<std::vector<std::string_view>>& lines);

  bool moves() const { return moves_; }
  std::array<double, 3> place(const double* part) const;        // part -> assembly
  std::array<double, 3> part_of(const double* assembly) const;  // assembly -> part (R's transpose)

  // Exact text form, for the kept deck (shortest round-trip doubles), and
  // back. from_text throws std::invalid_argument on text to_text did not
  // write.
  std::string to_text() const;
  static Placement from_text(std::string_view text);

 private:
  bool moves_ = false;
  std::array<double, 3> t_{}, a_{};
  std::array<double, 9> r_{1, 0, 0, 0, 1, 0, 0, 0, 1};  // row-major
};

}  // namespace tetsmooth::abaqus
