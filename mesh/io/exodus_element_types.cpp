#include "mesh/io/exodus_element_types.hpp"

#include <cctype>

namespace tetsmooth::exodus {
namespace {

struct Prefix {
  const char* prefix;  // the first three letters of an elem_type, upper case
  ElementType type;
};

// The types read, by prefix and node count; the first of each kind is the
// one written. Names are those the Exodus II documentation lists, and those
// meshio reads (it reads no other spelling of a wedge or a pyramid).
constexpr Prefix kTypes[] = {
    {"TET", {"tetra", 4, "TETRA"}},     {"TET", {"tetra10", 10, "TETRA10"}}, {"HEX", {"hexahedron", 8, "HEX8"}},
    {"WED", {"wedge", 6, "WEDGE"}},     {"PYR", {"pyramid", 5, "PYRAMID"}},  {"TRI", {"triangle", 3, "TRI3"}},
    {"TRI", {"triangle6", 6, "TRI6"}},  {"QUA", {"quad", 4, "QUAD4"}},       {"SHE", {"quad", 4, "SHELL4"}},
    {"SHE", {"triangle", 3, "SHELL3"}}, {"BAR", {"line", 2, "BAR2"}},        {"BAR", {"line3", 3, "BAR3"}},
    {"BEA", {"line", 2, "BEAM2"}},      {"BEA", {"line3", 3, "BEAM3"}},      {"TRU", {"line", 2, "TRUSS2"}},
    {"TRU", {"line3", 3, "TRUSS3"}},    {"EDG", {"line", 2, "EDGE2"}},       {"EDG", {"line3", 3, "EDGE3"}},
    {"SPH", {"vertex", 1, "SPHERE"}},   {"CIR", {"vertex", 1, "CIRCLE"}},
};

constexpr int kTetSides[4][3] = {{0, 1, 3}, {1, 2, 3}, {0, 2, 3}, {0, 1, 2}};

}  // namespace

const ElementType* element_type(const std::string& elem_type, int nodes_per_element) {
  if (elem_type.size() < 3) return nullptr;
  std::string prefix;
  for (std::size_t k = 0; k < 3; ++k)
    prefix += static_cast<char>(std::toupper(static_cast<unsigned char>(elem_type[k])));
  for (const Prefix& p : kTypes)
    if (prefix == p.prefix && p.type.nodes == nodes_per_element) return &p.type;
  return nullptr;
}

const ElementType* element_type_of_kind(const std::string& kind, int nodes_per_element) {
  for (const Prefix& p : kTypes)
    if (kind == p.type.kind && nodes_per_element == p.type.nodes) return &p.type;
  return nullptr;
}

const int* tet_side_corners(int side) { return side >= 1 && side <= 4 ? kTetSides[side - 1] : nullptr; }

}  // namespace tetsmooth::exodus
