// The Nastran entries the deck reader reads (nastran_entry_types.hpp).
#include "mesh/io/nastran_entry_types.hpp"

#include <algorithm>
#include <cctype>
#include <iterator>

#include "mesh/errors.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth::nastran {
namespace {

// An element, or an entry that only names grid points (a load, a
// constraint, a set, a coordinate system).
constexpr bool kElement = true, kNamesPoints = false, kPid = true, kNoPid = false;

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
    {"CBUSH1D", kElement, "line", 2, kPid, Grids::Run, 2, 2},
    {"CBUSH2D", kElement, "line", 2, kPid, Grids::Run, 2, 2},
    {"CGAP", kElement, "line", 2, kPid, Grids::Run, 2, 2, {-1, -1, -1, -1, -1, -1}, 4},
    {"CBAR", kElement, "line", 2, kPid, Grids::Run, 2, 2, {-1, -1, -1, -1, -1, -1}, 4},
    {"CBEAM", kElement, "line", 2, kPid, Grids::Run, 2, 2, {-1, -1, -1, -1, -1, -1}, 4},
    {"CBUSH", kElement, "line", 2, kPid, Grids::Run, 2, 2, {-1, -1, -1, -1, -1, -1}, 4},
    {"CBEND", kElement, "line", 2, kPid, Grids::Run, 2, 2, {-1, -1, -1, -1, -1, -1}, 4},
    {"CONROD", kElement, "line", 2, kNoPid, Grids::Run, 1, 2},
    {"CONM2", kElement, "vertex", 1, kNoPid, Grids::Run, 1, 1},
    {"CONM1", kElement, "vertex", 1, kNoPid, Grids::Run, 1, 1},
    // Solids: their corners have a shape; with midside nodes they only pin.
    {"CHEXA", kElement, "hexahedron", 8, kPid, Grids::Run, 2, 20},
    {"CPENTA", kElement, "wedge", 6, kPid, Grids::Run, 2, 15},
    {"CPYRAM", kElement, "pyramid", 5, kPid, Grids::Run, 2, 13},
    {"CPYRA", kElement, "pyramid", 5, kPid, Grids::Run, 2, 13},
    // Elements that only pin.
    {"CQUAD8", kElement, nullptr, 0, kPid, Grids::Run, 2, 8},
    {"CBEAM3", kElement, nullptr, 0, kPid, Grids::Run, 2, 3, {-1, -1, -1, -1, -1, -1}, 5},
    {"CQUAD", kElement, nullptr, 0, kPid, Grids::Run, 2, 9},
    {"CTRIAX6", kElement, nullptr, 0, kNoPid, Grids::Run, 2, 6},
    {"CELAS1", kElement, nullptr, 0, kPid, Grids::Listed, 0, 0, {2, 4, -1, -1, -1, -1}},
    {"CDAMP1", kElement, nullptr, 0, kPid, Grids::Listed, 0, 0, {2, 4, -1, -1, -1, -1}},
    {"CMASS1", kElement, nullptr, 0, kPid, Grids::Listed, 0, 0, {2, 4, -1, -1, -1, -1}},
    {"CELAS2", kElement, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {2, 4, -1, -1, -1, -1}},
    {"CDAMP2", kElement, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {2, 4, -1, -1, -1, -1}},
    {"CMASS2", kElement, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {2, 4, -1, -1, -1, -1}},
    {"PLOTEL", kElement, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 2, -1, -1, -1, -1}},
    {"RBAR", kElement, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 2, -1, -1, -1, -1}},
    {"RBAR1", kElement, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 2, -1, -1, -1, -1}},
    {"RROD", kElement, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 2, -1, -1, -1, -1}},
    {"RJOINT", kElement, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 2, -1, -1, -1, -1}},
    {"RTRPLT", kElement, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 2, 3, -1, -1, -1}},
    {"RBE1", kElement, nullptr, 0, kNoPid, Grids::Pairs},
    {"RBE2", kElement, nullptr, 0, kNoPid, Grids::Rbe2},
    {"RBE3", kElement, nullptr, 0, kNoPid, Grids::Rbe3},
    // Loads, constraints, and the points that give a load or a coordinate
    // system its direction.
    {"SPC", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 4, -1, -1, -1, -1}},
    {"SPCD", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 4, -1, -1, -1, -1}},
    {"SPC1", kNamesPoints, nullptr, 0, kNoPid, Grids::IdList, 2},
    {"FORCE", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, -1, -1, -1, -1, -1}},
    {"MOMENT", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, -1, -1, -1, -1, -1}},
    {"FORCE1", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 3, 4, -1, -1, -1}},
    {"MOMENT1", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 3, 4, -1, -1, -1}},
    {"FORCE2", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 3, 4, 5, 6, -1}},
    {"MOMENT2", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 3, 4, 5, 6, -1}},
    {"RFORCE", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, -1, -1, -1, -1, -1}},
    {"RFORCE1", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, -1, -1, -1, -1, -1}},
    {"NOLIN1", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 4, -1, -1, -1, -1}},
    {"DVGRID", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, -1, -1, -1, -1, -1}},
    // The default orientation node G0 of bars and beams.
    {"BAROR", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {-1, -1, -1, -1, -1, -1}, 4},
    {"BEAMOR", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {-1, -1, -1, -1, -1, -1}, 4},
    {"PLOAD", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {2, 3, 4, 5, -1, -1}},
    {"DAREA", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 4, -1, -1, -1, -1}},
    {"ACCEL1", kNamesPoints, nullptr, 0, kNoPid, Grids::IdList, 8},
    {"SUPORT", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {0, 2, 4, 6, -1, -1}},
    {"SUPORT1", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 3, 5, -1, -1, -1}},
    {"MPC", kNamesPoints, nullptr, 0, kNoPid, Grids::EveryLine},
    {"CORD1R", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 2, 3, 5, 6, 7}},
    {"CORD1C", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 2, 3, 5, 6, 7}},
    {"CORD1S", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 2, 3, 5, 6, 7}},
    // Degrees of freedom an analysis sets apart (often a test's measured
    // points): ASET ID1 C1 ID2 C2 ..., ASET1 C G1 G2 ... (THRU too).
    {"ASET", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {0, 2, 4, 6, -1, -1}},
    {"BSET", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {0, 2, 4, 6, -1, -1}},
    {"CSET", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {0, 2, 4, 6, -1, -1}},
    {"QSET", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {0, 2, 4, 6, -1, -1}},
    {"OMIT", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {0, 2, 4, 6, -1, -1}},
    {"ASET1", kNamesPoints, nullptr, 0, kNoPid, Grids::IdList, 1},
    {"BSET1", kNamesPoints, nullptr, 0, kNoPid, Grids::IdList, 1},
    {"CSET1", kNamesPoints, nullptr, 0, kNoPid, Grids::IdList, 1},
    {"QSET1", kNamesPoints, nullptr, 0, kNoPid, Grids::IdList, 1},
    {"OMIT1", kNamesPoints, nullptr, 0, kNoPid, Grids::IdList, 1},
    {"BNDFIX1", kNamesPoints, nullptr, 0, kNoPid, Grids::IdList, 1},
    {"SPCOFF1", kNamesPoints, nullptr, 0, kNoPid, Grids::IdList, 1},
    {"USET", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, 3, 5, -1, -1, -1}},
    {"USET1", kNamesPoints, nullptr, 0, kNoPid, Grids::IdList, 2},
    {"TIC", kNamesPoints, nullptr, 0, kNoPid, Grids::Listed, 0, 0, {1, -1, -1, -1, -1, -1}},
};

const EntryType kScalarPoints{"SPOINT", kNamesPoints, nullptr, 0, kNoPid, Grids::IdList, 0};

// Entries that name grid points in layouts the reader does not follow.
const char* const kUnread[] = {"CWELD",  "CFAST",  "CSEAM",  "RSPLINE", "GENEL",  "DMIG",    "BCGRID",
                               "TEMPBC", "CHBDYG", "CHBDYP", "CIFHEX",  "CIFPENT", "CHEXCZ", "CPENTCZ",
                               "SPCR",   "RBE3D",  "CTRAX3", "CTRAX6",  "CQUADX", "CTRIAX", "RSSCON", "CONV",   "RBE2GS", "SPCOFF"};

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

const EntryType& scalar_point_type() { return kScalarPoints; }

std::optional<std::string> pinned_comment_ids(const std::string& line) {
  constexpr std::string_view kWords = "TETSMOOTH PINNED";
  const std::size_t dollar = line.find_first_not_of(" \t");
  if (dollar == std::string::npos || line[dollar] != '$') return std::nullopt;
  const std::size_t start = line.find_first_not_of(" \t", dollar + 1);
  if (start == std::string::npos || upper_case(std::string_view(line).substr(start, kWords.size())) != kWords)
    return std::nullopt;
  return line.substr(start + kWords.size());
}

const EntryType* entry_type_of_kind(const std::string& kind) {
  for (const EntryType& t : kTypes)
    if (t.kind != nullptr && kind == t.kind) return &t;
  return nullptr;
}

bool names_grids_unread(const std::string& name) {
  return std::find(std::begin(kUnread), std::end(kUnread), name) != std::end(kUnread);
}

bool names_no_grids(const std::string& name) {
  // By prefix: properties (P...: PSOLID, PSHELL, PBAR, ..., and PARAM and the
  // element pressures PLOAD1/2/4; PLOAD, which names grid points, is read
  // before this is asked), materials, tables, design and solution data.
  static const char* const kPrefixes[] = {"P",      "MAT",   "TABLE", "EIG",   "TSTEP", "FREQ",  "NLPARM", "NLPCI",
                                          "CORD2",  "DESVAR", "DRESP", "DCON",  "DEQATN", "DOPTPRM", "DVPREL",
                                          "DVMREL", "DVCREL", "DLINK", "DTABLE", "TEMP",  "RLOAD", "TLOAD",  "RANDPS",
                                          "MONPNT", "SPCADD", "MPCADD", "LOAD",  "DLOAD", "GRAV",  "ACCEL",  "NSM",
                                          "BCTSET", "BSURF", "BCPROP", "BCTPARA", "SURF"};
  return std::any_of(std::begin(kPrefixes), std::end(kPrefixes),
                     [&](const char* prefix) { return name.rfind(prefix, 0) == 0; });
}

bool is_mesh_entry(const std::string& name) {
  if (name == "GRID" || name == "GRID*" || name == "CTETRA" || name == "CTETRA*") return true;
  const std::string bare = !name.empty() && name.back() == '*' ? name.substr(0, name.size() - 1) : name;
  const EntryType* type = entry_type(bare);
  return type != nullptr && type->element;
}

long long id_field(const std::string& field, const char* what, const Place& at, bool blank_ok) {
  if (field.empty() && blank_ok) return 0;
  long long id = 0;
  if (!parse_integer(field, id) || id <= 0)
    throw InputError(at.where(), std::string("expected ") + what + " (a positive whole number), found " +
                                (field.empty() ? std::string("a blank field") : quoted_token(field)));
  return id;
}

std::vector<std::pair<long long, long long>> grid_ranges(const EntryType& type, const Card& card,
                                                         const BulkCards& cards, const char* what) {
  const Place at{cards, card.mark};
  std::vector<std::pair<long long, long long>> ranges;
  const auto add = [&](std::size_t d) {
    const std::string& f = card.field(d);
    if (f.empty() || f == "0") return;  // no grid point (a grounded spring, a blank MPC term)
    const long long id = id_field(f, what, at);
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
    case Grids::IdList:
      for (std::size_t d = static_cast<std::size_t>(type.first); d < fields; ++d) {
        if (upper_case(card.field(d)) != "THRU") {
          add(d);
          continue;
        }
        // G1 THRU G2: G1, the field before, was added as one id; the range
        // takes its place.
        long long first = 0;
        if (d > static_cast<std::size_t>(type.first)) parse_integer(card.field(d - 1), first);
        if (first <= 0 || ranges.empty() || ranges.back() != std::make_pair(first, first))
          throw InputError(at.where(), std::string("THRU without ") + what + " before it");
        const long long last = id_field(card.field(d + 1), what, at);
        if (last < first) throw InputError(at.where(), "a THRU range that ends before it starts");
        ranges.back().second = last;
        ++d;
      }
      break;
    case Grids::Pairs:
      // Up to the first field that is no whole number: ALPHA's value after
      // the last pair (or the word ALPHA or TREF, as some write it).
      for (std::size_t d = 1; d < fields; ++d) {
        const std::string& f = card.field(d);
        if (f.empty() || upper_case(f) == "UM") continue;
        if (!whole_number(f)) break;
        if (d % 8 == 1 || d % 8 == 3 || d % 8 == 5) add(d);
      }
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
        const std::string f = upper_case(card.field(d));
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
