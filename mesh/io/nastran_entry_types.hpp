#pragma once
// The Nastran entries the deck reader reads besides GRID (not a public API;
// the list is in nastran_io.hpp): elements, whose grid points a smoother
// must keep unless they are tets, and loads and constraints, whose grid
// points it must keep. Where each names its grid points is given in data
// fields (nastran_cards.hpp: 0 for Nastran's field 2 of the first line).
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mesh/second_order.hpp"
#include "mesh/io/nastran_cards.hpp"

namespace tetsmooth::nastran {

enum class Grids {
  Run,        // data fields first .. first + count - 1 (elements' connectivity)
  Listed,     // the data fields in `at`
  EveryLine,  // data fields 1 and 4 of each logical line (MPC's terms)
  IdList,     // every field from `first` on, "G1 THRU G2" ranges among them (SPC1, ASET1, ...)
  Pairs,      // fields 1, 3 and 5 of each logical line, past "UM" too, up to a field that is no id (RBE1)
  Rbe2,       // field 1, then the whole numbers from field 3 on
  Rbe3,       // field 2, then each weight's grids and those after UM
};

struct EntryType {
  const char* name;
  bool element;            // an element (its EID shares the element ids), or a load, constraint, set, ...
  const char* kind;        // its shape for other formats (PassThroughBlock::kind), or nullptr: it only pins
  int shape_grids;         // the shape's node count: more grids (a higher-order solid) only pin
  bool has_pid;            // data field 1 is its PID
  Grids grids;
  int first = 0, count = 0;  // Run; IdList: first
  int at[6] = {-1, -1, -1, -1, -1, -1};  // Listed; -1 ends
  // A data field that names a grid point too where it holds a whole number
  // (the orientation node G0 of a bar, beam, bush or gap), or -1.
  int orientation = -1;
};

// The type of an entry name (upper case, as Card::name), or nullptr when
// the reader does not read it (GRID and CTETRA are read on their own).
const EntryType* entry_type(const std::string& name);

// The element a new deck writes for a shape (PassThroughBlock::kind), or
// nullptr: the first of the types above with that shape.
const EntryType* entry_type_of_kind(const std::string& kind);

// CTETRA lists its midside nodes in kTetEdges order, after the corners.
inline constexpr MidsidePlaces kCtetraMidsides = {4, 5, 6, 7, 8, 9};

// SPOINT and EPOINT: ids of scalar points, which loads, constraints and
// scalar elements name beside grid points.
const EntryType& scalar_point_type();

// Entry types that name grid points in ways the reader does not read
// (welds, fasteners, splines, heat transfer boundaries, ...): their nodes
// are not pinned, which the reader says.
bool names_grids_unread(const std::string& name);

// Entry types known to name no grid point whose node a smoother must keep:
// properties, materials, tables, parameters, load and constraint sets that
// combine others, element loads, design and solution data. Any other type
// the reader does not read gets a note that its points, if it names any,
// are not pinned.
bool names_no_grids(const std::string& name);

// Whether an entry of this name is part of a mesh (GRID, CTETRA, another
// element): none comes before BEGIN BULK, so a deck that opens with one
// has no executive or case control.
bool is_mesh_entry(const std::string& name);

// The grid point ids `card` names as `type` lays them, as ranges (first,
// last) (a single id is (id, id)); blank fields and 0 (no grid point, as in
// a grounded spring) are left out. InputError at the card's line for a
// field that is not an id (`what` names the ids).
// Scalar points (SPOINT, EPOINT) are read with the IdList layout from field
// 0 (scalar_point_type()); grid_ranges gives their ids.
std::vector<std::pair<long long, long long>> grid_ranges(const EntryType& type, const Card& card,
                                                         const BulkCards& cards, const char* what = "a grid point id");

// The ids of a "$TETSMOOTH PINNED <id> ..." comment line (the words in any
// case), as text, or nullopt for any other line.
std::optional<std::string> pinned_comment_ids(const std::string& line);

// A line of the deck, for a message made only when one is needed.
struct Place {
  const BulkCards& cards;
  std::uint32_t mark;
  std::string where() const { return cards.where(mark); }
};

// A field that must hold a positive id (an element or grid point id);
// InputError at `at` naming `what` otherwise. A blank field is 0 where
// `blank_ok`.
long long id_field(const std::string& field, const char* what, const Place& at, bool blank_ok = false);

}  // namespace tetsmooth::nastran
