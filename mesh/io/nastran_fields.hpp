#pragma once
// Nastran field values as text, both ways (not a public API).
#include <cstddef>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace tetsmooth::nastran {

// A real in any of Nastran's forms: "1.5", ".5", "5.", "1.5E-3", "1.5-3"
// (the exponent's E left out), "1.5+3", "1.5D-3"; a whole number ("1", as
// Gmsh writes some coordinates) too. False for anything else and for
// values that are not finite.
bool parse_real_field(std::string_view field, double& value);

// How a real is written. Nastran: as short as Fortran reads it (".25",
// "1.5E-3", "1.5E3"). C: as C's strtod and readers written in C, which may
// not take a leading point or an exponent without its sign, read it too
// ("0.25", "1.5E-3", "1.5E+3"; LS-DYNA's writer uses it).
enum class RealStyle { Nastran, C };

// A finite `value` in at most `width` characters (8 or more) as a real with
// a decimal point: the shortest form that reads back exactly where that
// fits, else the form that fits and reads back closest, in fixed or
// exponent notation. Width 16 keeps a relative error below 5e-10 for
// exponents of two digits (below 5e-14 for sizes from 1 to 1e13).
std::string real_field(double value, std::size_t width, RealStyle style = RealStyle::Nastran);

// Writes one entry: small field (8 columns) or large field (a '*' after the
// name, 16 columns, 4 fields a line), `fields` being the data fields
// (Nastran's fields 2..9 of each logical line; each must fit its width).
// A large-field entry goes on on lines that start with '*'; a small-field
// one on lines whose first field is the marker "+<id in base 36>", which
// also ends the line before (Gmsh reads a second line without one as
// another entry). Trailing blank fields are left out.
void write_entry(std::ostream& out, std::string_view name, const std::vector<std::string>& fields, bool large,
                 long long id);

}  // namespace tetsmooth::nastran
