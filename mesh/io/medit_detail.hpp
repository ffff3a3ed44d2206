#pragma once
// Medit keywords shared by the .mesh reader and writer (not a public API).
#include <string_view>

namespace tetsmooth::medit {

// Element sections other than Tetrahedra: each entry is `nodes` 1-based
// vertex indices and a reference; they become pass-through blocks of `kind`.
struct ElementKeyword {
  const char* keyword;
  const char* kind;
  int nodes;
};
inline constexpr ElementKeyword kElementKeywords[] = {
    {"Edges", "line", 2},           {"Triangles", "triangle", 3}, {"Quadrilaterals", "quad", 4},
    {"Hexahedra", "hexahedron", 8}, {"Prisms", "wedge", 6},       {"Pyramids", "pyramid", 5},
};

// Sections that only annotate others (by element or vertex index) and are
// reproduced as read, through FileExtras::raw_sections under their keyword:
// each entry is `integers` positive indices then `reals` numbers.
struct KeptKeyword {
  const char* keyword;
  int integers;
  int reals;
};
inline constexpr KeptKeyword kKeptKeywords[] = {
    {"Ridges", 1, 0},
    {"RequiredEdges", 1, 0},
    {"RequiredTriangles", 1, 0},
    {"RequiredQuadrilaterals", 1, 0},
    {"RequiredTetrahedra", 1, 0},
    {"RequiredHexahedra", 1, 0},
    {"Normals", 0, 3},
    {"Tangents", 0, 3},
    {"NormalAtVertices", 2, 0},
    {"TangentAtVertices", 2, 0},
    {"NormalAtTriangleVertices", 3, 0},
    {"NormalAtQuadrilateralVertices", 3, 0},
};

// Sections that hold one string, quoted where it has spaces: the mesh's name
// and the file of its geometric support. Reproduced as read (as one line, its
// words joined by single spaces) through FileExtras::raw_sections, after
// Dimension.
inline constexpr const char* kStringKeywords[] = {"Identifier", "Geometry"};

// Whether a raw section of that name is one of the two lists above.
inline bool is_medit_section(std::string_view name) {
  for (const KeptKeyword& kw : kKeptKeywords)
    if (name == kw.keyword) return true;
  for (const char* kw : kStringKeywords)
    if (name == kw) return true;
  return false;
}

}  // namespace tetsmooth::medit
