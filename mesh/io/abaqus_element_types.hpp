#pragma once
// Abaqus (and CalculiX) element type names, for the .inp reader and writer
// (not a public API). A type names its element's shape and node count; its
// formulation (reduced integration, hybrid, pore pressure, ...) does not
// matter to a smoother, so a family is a base name followed by any letters:
// C3D4, C3D4H and C3D4P are all 4-node tets, C3D10, C3D10M and C3D10MPH all
// 10-node tets. Abaqus lists a 10-node tet's midside nodes in kTetEdges
// order, as VTK does, and orients tets as tetsmooth does.
#include <optional>
#include <string>

#include "mesh/second_order.hpp"

namespace tetsmooth::abaqus {

// Where a C3D10 lists the midside node of each kTetEdges edge: in that
// order, after the corners.
inline constexpr MidsidePlaces kMidsidePlaces = {4, 5, 6, 7, 8, 9};

struct ElementType {
  std::string kind;  // "tetra", "tetra10", or a PassThroughBlock::kind as the other readers name it
  int nodes = 0;
  int dimension = 3;  // 0 for points, 1 for lines, 2 for faces, 3 for solids
};

// The element type a TYPE= value names (any case), or nullopt.
std::optional<ElementType> element_type(const std::string& name);

// The message for a TYPE= value element_type() does not know, naming the
// element where the name tells it (a 20-node hexahedron, say).
std::string unsupported_element_type(const std::string& name);

// The type name the writer gives a kind with `nodes` nodes, or nullptr when
// it has none: a surface element without stiffness (SFM3D3, ...) for the
// faces and a truss for the lines that other formats pass through.
const char* type_name_of(const std::string& kind, int nodes);

// Where node k of an element of `kind` stands among the nodes its file line
// lists. Abaqus numbers a 3-node line end, middle, end; the other formats
// (and PassThroughBlock) put both ends first. The swap is its own inverse,
// so the same places serve reading and writing.
inline int file_place(const std::string& kind, int k) {
  constexpr int kLine3[3] = {0, 2, 1};
  return kind == "line3" ? kLine3[k] : k;
}

}  // namespace tetsmooth::abaqus
