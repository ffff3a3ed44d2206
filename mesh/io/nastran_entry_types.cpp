// The Nastran entries the deck reader reads (nastran_entry_types.hpp).
#include "mesh/io/nastran_entry_types.hpp"

#include <cctype>
#include <iterator>

#include "mesh/errors.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth::nastran {
namespace {

constexpr bool kElement = true, kLoad = false, kPid = true, kNoPid = false;

const EntryType kTypes[] = {
    // Elements whose shape other formats have.
    {"CTRIA3", kElement, "triangle", 3, kPid, Grids::Run, 2, 3},
    {"CTRIAR", kElement, "triangle", 3, kPid, Grids::Run, 2, 3},
    {"CTRIA6", kElement, "triangle6", 6, kPid, Grids::Run, 2, 6},
    {"CQUAD4", kElement, "quad", 4, kPid, Grids::Run, 2, 4},
    {"CQUADR", kElement, "quad", 4, kPid, Grids::Run, 2, 4},
    {"CSHEAR", kElement, "quad", 4, kPid, Grids::Run, 2, 4},
    {"CROD", kElement, "line", 2, kPid, Grids::Run, 2, 2},
    {"CTUBE", kElement, "line", 2, kPid, Grids::Run, 2, 2},
    {"CVISC", kElement, "line", 2, kPid, Grids::Run, 2, 2},
    {"CGAP", kElement, "line", 2, kPid, Grids::Run, 2, 2},
    {"CBAR", kElement, "line", 2, kPid, Grids::Run, 2, 2},
    {"CBEAM", kElement, "line", 2, kPid, Grids::Run, 2, 2},
    {"CBUSH", kElement, "line", 2, kPid, Grids::Run, 2, 2},
    {"CONROD", kElement, "line", 2, kNoPid, Grids::Run, 1, 2},
    {"CONM1", kElement, "vertex", 1, kNoPid, Grids::Run, 1, 1},
    {"CONM2", kElement, "vertex", 1, kNoPid, Grids::Run, 1, 1},
    // Solids: their corners have a shape; with midside nodes they only pin.
    {"CHEXA", kElement, "hexahedron", 8, kPid, Grids::Run, 2, 20},
    {"CPENTA", kElement, "wedge", 6, kPid, Grids::Run, 2, 15},
    {"CPYRAM", kElement, "pyramid", 5, kPid, Grids::Run, 2, 13},
    {"CPYRA", kElement, "pyramid", 5, kPid, Grids::Run, 2, 13},
    // Elements that only pin.
    {"CQUAD8", kElement, nullptr, 0, kPid, Grids::Run, 2, 8},
    {"CELAS1", kElement, nullptr, 0, kPid, Grids::Listed, 0, 0, {2, 4, -1, -1}},
    {"CDAMP1", kElement, nullptr, 0, kPid, Grids::Listed, 0, 0, {2, 4, -1, -1}},
    {"CELAS2", kElement, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {2, 4, -1, -1}},
    {"CDAMP2", kElement, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {2, 4, -1, -1}},
    {"RBAR", kElement, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 2, -1, -1}},
    {"RBE2", kElement, nullptr, 0, kNoPid, Grids::Rbe2},
    {"RBE3", kElement, nullptr, 0, kNoPid, Grids::Rbe3},
    // Loads and constraints.
    {"SPC", kLoad, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 4, -1, -1}},
    {"SPCD", kLoad, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 4, -1, -1}},
    {"SPC1", kLoad, nullptr, 0, kNoPid, Grids::Spc1},
    {"FORCE", kLoad, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, -1, -1, -1}},
    {"FORCE1", kLoad, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, -1, -1, -1}},
    {"FORCE2", kLoad, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, -1, -1, -1}},
    {"MOMENT", kLoad, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, -1, -1, -1}},
    {"MOMENT1", kLoad, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, -1, -1, -1}},
    {"MOMENT2", kLoad, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, -1, -1, -1}},
    {"PLOAD", kLoad, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {2, 3, 4, 5}},
    {"DAREA", kLoad, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 4, -1, -1}},
    {"SUPORT", kLoad, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {0, 2, 4, 6}},
    {"SUPORT1", kLoad, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 3, 5, -1}},
    {"MPC", kLoad, nullptr, 0, kNoPid, Grids::EveryLine},
};

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

bool whole_number(const std::string& field) {
  long long v = 0;
  return parse_integer(field, v);
}

}  // namespace

const EntryType* entry_type(const std::string& name) {
  for (const EntryType& t : kTypes)
    if (name == t.name) return &t;
  return nullptr;
}

bool is_mesh_entry(const std::string& name) {
  if (name == "GRID" || name == "GRID*" || name == "CTETRA" || name == "CTETRA*") return true;
  const std::string bare = !name.empty() && name.back() == '*' ? name.substr(0, name.size() - 1) : name;
  const EntryType* type = entry_type(bare);
  return type != nullptr && type->element;
}

long long id_field(const std::string& field, const char* what, const std::string& where, bool blank_ok) {
  if (field.empty() && blank_ok) return 0;
  long long id = 0;
  if (!parse_integer(field, id) || id <= 0)
    throw InputError(where, std::string("expected ") + what + " (a positive whole number), found " +
                                (field.empty() ? std::string("a blank field") : quoted_token(field)));
  return id;
}

std::vector<std::pair<long long, long long>> grid_ranges(const EntryType& type, const Card& card,
                                                         const std::string& where) {
  std::vector<std::pair<long long, long long>> ranges;
  const auto add = [&](std::size_t d) {
    const std::string& f = card.field(d);
    if (f.empty() || f == "0") return;  // no grid point (a grounded spring, a blank MPC term)
    const long long id = id_field(f, "a grid point id", where);
    ranges.emplace_back(id, id);
  };
  const std::size_t fields = card.fields.size();
  switch (type.grids) {
    case Grids::Run:
      for (int k = 0; k < type.count; ++k) add(static_cast<std::size_t>(type.first + k));
      break;
    case Grids::Listed:
      for (int d : type.at)
        if (d >= 0) add(static_cast<std::size_t>(d));
      break;
    case Grids::EveryLine:
      for (std::size_t d = 0; d < fields; ++d)
        if (d % 8 == 1 || d % 8 == 4) add(d);
      break;
    case Grids::Spc1:
      if (upper(card.field(3)) == "THRU") {
        const long long first = id_field(card.field(2), "a grid point id", where);
        const long long last = id_field(card.field(4), "a grid point id", where);
        if (last < first) throw InputError(where, "a THRU range that ends before it starts");
        ranges.emplace_back(first, last);
        break;
      }
      for (std::size_t d = 2; d < fields; ++d) add(d);
      break;
    case Grids::Rbe2:
      // EID GN CM GM1 GM2 ...: the dependent grids run to the first field
      // that is no whole number (ALPHA, a real).
      add(1);
      for (std::size_t d = 3; d < fields; ++d) {
        if (card.field(d).empty()) continue;
        if (!whole_number(card.field(d))) break;
        add(d);
      }
      break;
    case Grids::Rbe3: {
      // EID _ REFGRID REFC, then groups WTi Ci Gi,1 Gi,2 ..., then "UM" and
      // pairs GMi CMi; ALPHA or TREF end the list.
      add(2);
      enum { Weight, Component, Grid, UmGrid, UmComponent } next = Weight;
      for (std::size_t d = 4; d < fields; ++d) {
        const std::string f = upper(card.field(d));
        if (f.empty()) continue;
        if (f == "UM") {
          next = UmGrid;
        } else if (f == "ALPHA" || f == "TREF") {
          break;
        } else if (next == UmGrid) {
          add(d);
          next = UmComponent;
        } else if (next == UmComponent) {
          next = UmGrid;
        } else if (!whole_number(f)) {
          next = Component;  // a weight: its components come next
        } else if (next == Component) {
          next = Grid;
        } else {
          add(d);
        }
      }
      break;
    }
  }
  return ranges;
}

}  // namespace tetsmooth::nastran
