#include "mesh/io/abaqus_element_types.hpp"

#include "mesh/io/abaqus_deck_lines.hpp"
#include "mesh/io/text_lines.hpp"

#include <cctype>
#include <string_view>

namespace tetsmooth::abaqus {
namespace {

struct Family {
  const char* base;   // the name up to the letters that choose a formulation
  bool solid_prefix;  // whether D (heat transfer) and A (acoustic) variants exist: DC3D4, AC3D10
  const char* kind;
  int nodes;
};

// First-order and 10-node solids, the faces and lines that bound or cut
// them (shells, membranes, surface elements, trusses, beams, rigid
// elements), and one-node elements. Every element but a tet passes through
// with its nodes pinned.
constexpr Family kFamilies[] = {
    {"C3D4", true, "tetra", 4},         {"C3D10", true, "tetra10", 10},      {"C3D8", true, "hexahedron", 8},
    {"C3D6", true, "wedge", 6},         {"C3D5", true, "pyramid", 5},
    // Cohesive elements (a fault, a joint), infinite elements and continuum
    // shells pass through like any other solid.
    {"COH3D6", false, "wedge", 6},      {"COH3D8", false, "hexahedron", 8}, {"CIN3D8", false, "hexahedron", 8},
    {"SC6R", false, "wedge", 6},        {"SC8R", false, "hexahedron", 8},
    {"SFM3D3", false, "triangle", 3},   {"S3", false, "triangle", 3},       {"STRI3", false, "triangle", 3},
    {"CPS3", false, "triangle", 3},     {"CPE3", false, "triangle", 3},     {"CAX3", false, "triangle", 3},
    {"M3D3", false, "triangle", 3},     {"R3D3", false, "triangle", 3},     {"DS3", false, "triangle", 3},
    {"DC2D3", false, "triangle", 3},    {"SFM3D6", false, "triangle6", 6},  {"STRI65", false, "triangle6", 6},
    {"S6", false, "triangle6", 6},      {"CPS6", false, "triangle6", 6},    {"CPE6", false, "triangle6", 6},
    {"CAX6", false, "triangle6", 6},    {"M3D6", false, "triangle6", 6},    {"DS6", false, "triangle6", 6},
    {"DC2D6", false, "triangle6", 6},   {"SFM3D4", false, "quad", 4},       {"S4", false, "quad", 4},
    {"S4R5", false, "quad", 4},         {"CPS4", false, "quad", 4},         {"CPE4", false, "quad", 4},
    {"CAX4", false, "quad", 4},         {"M3D4", false, "quad", 4},         {"R3D4", false, "quad", 4},
    {"DS4", false, "quad", 4},          {"DC2D4", false, "quad", 4},        {"T3D2", false, "line", 2},
    {"T2D2", false, "line", 2},         {"B31", false, "line", 2},          {"B21", false, "line", 2},
    {"RB3D2", false, "line", 2},        {"CONN3D2", false, "line", 2},      {"SPRINGA", false, "line", 2},
    {"DASHPOTA", false, "line", 2},     {"DC1D2", false, "line", 2},        {"SPRING2", false, "line", 2},
    {"DASHPOT2", false, "line", 2},     {"GAPUNI", false, "line", 2},        {"T3D3", false, "line3", 3},
    {"T2D3", false, "line3", 3},        {"B32", false, "line3", 3},         {"B22", false, "line3", 3},
    {"MASS", false, "vertex", 1},       {"ROTARYI", false, "vertex", 1},    {"SPRING1", false, "vertex", 1},
    {"DASHPOT1", false, "vertex", 1},   {"HEATCAP", false, "vertex", 1},
};

// The writer's name for each kind: the first of its families above.
struct Written {
  const char* kind;
  int nodes;
  const char* type;
};
constexpr Written kWritten[] = {
    {"tetra", 4, "C3D4"},        {"tetra10", 10, "C3D10"},  {"hexahedron", 8, "C3D8"}, {"wedge", 6, "C3D6"},
    {"pyramid", 5, "C3D5"},      {"triangle", 3, "SFM3D3"}, {"triangle6", 6, "SFM3D6"}, {"quad", 4, "SFM3D4"},
    {"line", 2, "T3D2"},         {"line3", 3, "T3D3"},      {"vertex", 1, "MASS"},
};

// Solids that tetsmooth does not read, named in the message.
struct Named {
  const char* base;
  const char* what;
};
constexpr Named kUnread[] = {
    {"C3D20", "a 20-node hexahedron"}, {"C3D27", "a 27-node hexahedron"}, {"C3D15", "a 15-node wedge"},
    {"C3D13", "a 13-node pyramid"},    {"S8", "an 8-node shell"},         {"CPS8", "an 8-node quadrilateral"},
    {"CPE8", "an 8-node quadrilateral"}, {"M3D8", "an 8-node quadrilateral"}, {"M3D9", "a 9-node quadrilateral"},
};

bool only_letters(std::string_view s) {
  for (char c : s)
    if (!std::isalpha(static_cast<unsigned char>(c))) return false;
  return true;
}

// Whether `name` (upper case) is `base`, with D or A before it if
// `solid_prefix`, followed by letters only.
bool in_family(std::string_view name, std::string_view base, bool solid_prefix) {
  if (solid_prefix && !name.empty() && (name.front() == 'D' || name.front() == 'A') &&
      name.substr(1, base.size()) == base)
    name.remove_prefix(1);
  return name.substr(0, base.size()) == base && only_letters(name.substr(base.size()));
}

}  // namespace

std::optional<ElementType> element_type(const std::string& name) {
  const std::string key = upper_case(name);
  for (const Family& f : kFamilies)
    if (in_family(key, f.base, f.solid_prefix)) {
      return ElementType{f.kind, f.nodes, kind_dimension(f.kind)};
    }
  return std::nullopt;
}

std::string unsupported_element_type(const std::string& name) {
  const std::string key = upper_case(name);
  for (const Named& n : kUnread)
    if (in_family(key, n.base, true))
      return "unsupported element type " + name + " (" + n.what +
             "); of the higher-order elements, only 10-node tets (C3D10...), 6-node triangles and 3-node lines "
             "are read";
  return "unsupported element type " + name +
         "; tets (C3D4..., C3D10...), first-order solids, shells, membranes, surface elements, trusses, beams "
         "and one-node elements are read";
}

const char* type_name_of(const std::string& kind, int nodes) {
  for (const Written& w : kWritten)
    if (kind == w.kind && nodes == w.nodes) return w.type;
  return nullptr;
}

}  // namespace tetsmooth::abaqus
