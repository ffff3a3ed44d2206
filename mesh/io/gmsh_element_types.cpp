#include <string>

#include "mesh/io/gmsh_detail.hpp"

namespace tetsmooth::gmsh {
namespace {

// Node ordering within each type is Gmsh's; pass-through blocks keep it.
// Of the second-order types, the 3-node line and the 6-node triangle order
// their nodes as VTK does (corners, then the edges' midside nodes in the
// corners' order), so blocks of them convert as they are.
constexpr ElementType kTypes[] = {
    {1, "line", 2, 1},       {2, "triangle", 3, 2}, {3, "quad", 4, 2},      {4, "tetra", 4, 3},
    {5, "hexahedron", 8, 3}, {6, "wedge", 6, 3},    {7, "pyramid", 5, 3},   {15, "vertex", 1, 0},
    {8, "line3", 3, 1},      {9, "triangle6", 6, 2}, {11, "tetra10", 10, 3},
};

// Names of the higher-order types of the MSH specification, for messages.
struct TypeName {
  int id;
  const char* name;
};
constexpr TypeName kOtherNames[] = {
    {10, "9-node quadrangle"},
    {12, "27-node hexahedron"},  {13, "18-node prism"},
    {14, "14-node pyramid"},     {16, "8-node quadrangle"},
    {17, "20-node hexahedron"},  {18, "15-node prism"},
    {19, "13-node pyramid"},     {20, "9-node incomplete triangle"},
    {21, "10-node triangle"},    {22, "12-node incomplete triangle"},
    {23, "15-node triangle"},    {24, "15-node incomplete triangle"},
    {25, "21-node triangle"},    {26, "4-node edge"},
    {27, "5-node edge"},         {28, "6-node edge"},
    {29, "20-node tetrahedron"}, {30, "35-node tetrahedron"},
    {31, "56-node tetrahedron"}, {92, "64-node hexahedron"},
    {93, "125-node hexahedron"},
};

}  // namespace

const ElementType* element_type(int id) {
  for (const ElementType& t : kTypes)
    if (t.id == id) return &t;
  return nullptr;
}

const ElementType* element_type_of_kind(const std::string& kind) {
  for (const ElementType& t : kTypes)
    if (kind == t.kind) return &t;
  return nullptr;
}

std::string unsupported_element_type(int id) {
  std::string what = "unsupported element type " + std::to_string(id);
  for (const TypeName& t : kOtherNames)
    if (t.id == id)
      return what + " (" + t.name +
             "); of the higher-order elements, only 10-node tetrahedra, 6-node triangles and 3-node lines are read";
  return what;
}

}  // namespace tetsmooth::gmsh
