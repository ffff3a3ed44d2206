#include "mesh/io/flac3d_zone_types.hpp"

#include <vector>

#include "mesh/io/text_lines.hpp"

namespace tetsmooth::flac3d {
namespace {

// The orders follow from the layouts at the top of flac3d_zone_types.hpp.
// meshio 5 reorders FLAC3D's bricks and pyramids the same way; its wedges
// it reads with the first triangle wound as VTK's, out of the cell, where
// its own wedge (and Gmsh's, and tetsmooth's) winds it into the cell.
constexpr ZoneType kTypes[] = {
    // Tets and faces are read and written as listed, and faces never mirrored.
    {"T4", 'Z', "tetra", 4, {0, 1, 2, 3}, {}},
    {"B8", 'Z', "hexahedron", 8, {0, 1, 4, 2, 3, 6, 7, 5}, {0, 2, 1, 3, 4, 6, 5, 7}},
    {"W6", 'Z', "wedge", 6, {0, 3, 1, 2, 5, 4}, {0, 3, 2, 1, 5, 4}},
    {"P5", 'Z', "pyramid", 5, {0, 1, 4, 2, 3}, {0, 2, 1, 3, 4}},
    {"B7", 'Z', "", 7, {}, {}},
    {"T3", 'F', "triangle", 3, {0, 1, 2}, {}},
    {"Q4", 'F', "quad", 4, {0, 1, 2, 3}, {}},
};

}  // namespace

const ZoneType* zone_type(std::string_view code, char record) {
  const std::string upper = upper_case(code);
  for (const ZoneType& t : kTypes)
    if (t.record == record && upper == t.code) return &t;
  return nullptr;
}

const ZoneType* zone_type_with(std::size_t nodes, char record) {
  for (const ZoneType& t : kTypes)
    if (t.record == record && t.nodes == nodes) return &t;
  return nullptr;
}

const ZoneType* zone_type_of_kind(const std::string& kind) {
  for (const ZoneType& t : kTypes)
    if (!kind.empty() && kind == t.kind) return &t;
  return nullptr;
}

std::string zone_codes(char record) {
  std::vector<std::string> codes;
  for (const ZoneType& t : kTypes)
    if (t.record == record) codes.emplace_back(t.code);
  std::string text;
  for (std::size_t i = 0; i < codes.size(); ++i)
    text += (i == 0 ? "" : i + 1 == codes.size() ? " or " : ", ") + codes[i];
  return text;
}

}  // namespace tetsmooth::flac3d
