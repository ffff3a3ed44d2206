#pragma once
// The fixed-width records of ANSYS blocks (NBLOCK, EBLOCK, CMBLOCK): the
// Fortran format line that lays them out, and their fields as numbers (not
// a public API; ansys_io.hpp describes the blocks).
#include <optional>
#include <string>
#include <string_view>

namespace tetsmooth::ansys {

// "(3i9,6e21.13e3)": `ints` integer fields of `int_width` characters, then
// `reals` real fields of `real_width` with `decimals` digits after the
// point and an exponent of `exponent_digits` (2 unless the format says
// "e3"); "(19i9)" and "(8i10)" have integers alone; "(2i9,19a9)" has
// `texts` text fields after them.
struct BlockFormat {
  int ints = 0, int_width = 0;
  int reals = 0, real_width = 0, decimals = 0, exponent_digits = 2;
  int texts = 0;
};

// The format of a block's second line, or nullopt when the line is not one
// (any case; blanks around it are allowed).
std::optional<BlockFormat> parse_block_format(std::string_view line);

// The text of `line` from `start` on, `width` characters at most (empty
// past the end: records may leave trailing fields off).
std::string_view field_at(std::string_view line, std::size_t start, std::size_t width);

// A field as a number; a blank field is 0. False for anything else than a
// whole number (integer_field) or a finite real (real_field: Fortran's
// forms, "1.5", "1.5E-3", "1.5D-3", "-.5e+000").
bool integer_field(std::string_view field, long long& value);
bool real_field(std::string_view field, double& value);

// `value` as Fortran's 1PE writes it in a field of the format's real width
// and decimals ("-5.0000000000000E-01", right-aligned; fewer decimals where
// the width has no room for them), into `out`; values
// whose exponent needs more digits than the format has are written as 0
// when small (below 1e-99 with two digits: a rounding residue) and refused
// (false) when large, as are infinities and NaNs. The decimal digits are
// correctly rounded from the double.
bool format_real(double value, const BlockFormat& format, std::string& out);

}  // namespace tetsmooth::ansys
