#pragma once
// Exodus II element types as tetsmooth maps them (not a public API).
//
// An Exodus block names its topology in the connect variable's `elem_type`
// attribute ("TETRA", "tetra4", "TRISHELL3", "HEX8", ...) and its order by
// its nodes per element, so a type is found from the name's first three
// letters, in any case, and the node count: "TETRA" with 10 nodes is a
// 10-node tet. The corner orders of the types mapped here are those of
// Gmsh's (and VTK's, but for the wedge) elements, so blocks convert as they
// are: a tet's corners are right-handed ((b-a)·((c-a)×(d-a)) > 0), a
// TETRA10's midside nodes follow on the edges 1-2, 2-3, 3-1, 1-4, 2-4, 3-4
// (tet_mesh.hpp's kTetEdges order), a wedge's first triangle is wound
// towards its second, as Gmsh's.
#include <string>

#include "mesh/second_order.hpp"

namespace tetsmooth::exodus {

// A TETRA10 lists its midside nodes after its corners, in kTetEdges order.
inline constexpr MidsidePlaces kTetra10Midsides = {4, 5, 6, 7, 8, 9};

struct ElementType {
  const char* kind;  // PassThroughBlock::kind, "tetra" or "tetra10" for tets
  int nodes;
  const char* name;  // the elem_type a new file writes
};

// The type of a block, or nullptr for one tetsmooth does not carry (a
// 20-node brick, a polyhedron, ...), whose nodes it pins.
const ElementType* element_type(const std::string& elem_type, int nodes_per_element);

// The type a new file writes for a block of `kind`, or nullptr.
const ElementType* element_type_of_kind(const std::string& kind, int nodes_per_element);

// The corners (0-based, within the tet) of side `side` (1..4) of a tet, as
// Exodus numbers a tet's sides in side sets: 1 = (1,2,4), 2 = (2,3,4),
// 3 = (1,3,4), 4 = (1,2,3) in its 1-based node numbers.
const int* tet_side_corners(int side);

}  // namespace tetsmooth::exodus
