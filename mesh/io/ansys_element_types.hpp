#pragma once
// What tetsmooth knows of ANSYS element types and commands (not a public
// API; ansys_io.hpp describes the file).
#include <string_view>

namespace tetsmooth::ansys {

// The 3-D solids whose node lists give their shape: tets (4 or 10 nodes)
// and bricks (8 or 20 nodes, degenerate into wedges, pyramids and tets by
// repeated nodes). Every other type is Other.
enum class Family { Other, Tet, Brick };
Family family_of(int type_number);

// The number in ET's ENAME: "187", "SOLID187" and "solid187" give 187; -1
// for a name without one.
int type_number_of(std::string_view ename);

// An element's shape as tetsmooth carries it, and where each of its nodes
// is in the file's node list: a tet's corners then its midside nodes in
// kTetEdges order; a hexahedron's, wedge's or pyramid's corners in Gmsh's
// order (which is ANSYS's).
enum class Shape { Other, Tet4, Tet10, Hexahedron, Wedge, Pyramid };
struct SolidShape {
  Shape shape = Shape::Other;
  int count = 0;        // nodes it keeps
  int places[10] = {};  // their places in the file's list
};

// The shape of a solid of `family` from its `count` listed nodes (node
// numbers; 0 where a midside node is left out).
SolidShape solid_shape(Family family, const long long* nodes, int count);

// Whether a command (upper case, as written or cut to four letters or more,
// as APDL takes it) defines, moves or deletes nodes or elements, or reads
// another file: a file with one is not read, since tetsmooth would not see
// the mesh it makes.
bool changes_mesh(std::string_view command);

}  // namespace tetsmooth::ansys
