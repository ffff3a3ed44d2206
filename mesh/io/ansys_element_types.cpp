#include "mesh/io/ansys_element_types.hpp"

#include <algorithm>
#include <cctype>
#include <initializer_list>
#include <iterator>

namespace tetsmooth::ansys {
namespace {

// Element types of the ANSYS element reference by shape: tets (structural,
// thermal, electric and coupled-field ones) and bricks, whose tets, wedges
// and pyramids repeat nodes.
constexpr int kTets[] = {72, 87, 92, 98, 123, 127, 168, 187, 227, 232, 237, 285};
constexpr int kBricks[] = {5, 45, 65, 69, 70, 90, 95, 96, 97, 117, 122, 164, 185, 186, 226, 231, 236, 278, 279};

// Commands that make, move, reorder or delete nodes or elements (solid
// model commands among them, which carry a mesh along), change their
// materials (MPCHG), or read another file into the model.
constexpr std::string_view kMeshCommands[] = {
    "N",       "E",        "EN",      "EMORE",   "EGEN",    "ENGEN",   "NGEN",    "NMODIF",  "EMODIF",  "NDELE",
    "EDELE",   "NSYM",     "ESYM",    "NSCALE",  "NFILL",   "FILL",    "NKPT",    "MOVE",    "NUMMRG",  "NUMCMP",
    "VMESH",   "AMESH",    "LMESH",   "KMESH",   "VSWEEP",  "ESURF",   "EINTF",   "CDREAD",  "/INPUT",  "EREAD",
    "NREAD",   "EEXTRUDE", "NREFINE", "EREFINE", "VEXT",    "VDRAG",   "VROTAT",  "ACLEAR",  "VCLEAR",  "KCLEAR",
    "LCLEAR",  "UPGEOM",   "MORPH",   "EMID",    "EORIENT", "ENSYM",   "VTRAN",   "VGEN",    "VSYMM",   "CZMESH",
    "*USE",    "NSMOOTH",  "RESUME",  "/CLEAR",  "AREFINE", "LREFINE", "KREFINE", "MSHCOPY", "EINFIN",  "AGEN",
    "ARSYM",   "ATRAN",    "LGEN",    "KGEN",    "KSYMM",   "LSYMM",   "KTRAN",   "LTRAN",   "UPCOORD", "DAMORPH",
    "DEMORPH", "DVMORPH",  "EREINF",  "GCGEN",   "EMTGEN",  "MPCHG"};

bool listed(const int* first, const int* last, int n) { return std::find(first, last, n) != last; }

// Whether the nodes at `places` in `n` are one node.
bool all_same(const long long* n, std::initializer_list<int> places) {
  for (int p : places)
    if (n[p] != n[*places.begin()]) return false;
  return true;
}

// Whether the nodes at `places` in `n` are all given (not 0) and all
// different.
bool distinct(const long long* n, std::initializer_list<int> places) {
  for (auto i = places.begin(); i != places.end(); ++i) {
    if (n[*i] == 0) return false;
    for (auto j = places.begin(); j != i; ++j)
      if (n[*i] == n[*j]) return false;
  }
  return true;
}

SolidShape shape_of(Shape shape, std::initializer_list<int> places) {
  SolidShape s;
  s.shape = shape;
  for (int p : places) s.places[s.count++] = p;
  return s;
}

// A brick's eight corners (I..P) as a brick, wedge (K=L, O=P), pyramid
// (M=N=O=P) or tet (K=L, M=N=O=P).
SolidShape brick_corners(const long long* n) {
  if (distinct(n, {0, 1, 2, 3, 4, 5, 6, 7})) return shape_of(Shape::Hexahedron, {0, 1, 2, 3, 4, 5, 6, 7});
  if (n[2] == n[3] && all_same(n, {4, 5, 6, 7}) && distinct(n, {0, 1, 2, 4}))
    return shape_of(Shape::Tet4, {0, 1, 2, 4});
  if (n[2] == n[3] && n[6] == n[7] && distinct(n, {0, 1, 2, 4, 5, 6}))
    return shape_of(Shape::Wedge, {0, 1, 2, 4, 5, 6});
  if (all_same(n, {4, 5, 6, 7}) && distinct(n, {0, 1, 2, 3, 4})) return shape_of(Shape::Pyramid, {0, 1, 2, 3, 4});
  return {};
}

bool none_listed(const long long* n, int from, int to) {
  for (int i = from; i < to; ++i)
    if (n[i] != 0) return false;
  return true;
}

}  // namespace

Family family_of(int type_number) {
  if (listed(std::begin(kTets), std::end(kTets), type_number)) return Family::Tet;
  if (listed(std::begin(kBricks), std::end(kBricks), type_number)) return Family::Brick;
  return Family::Other;
}

int type_number_of(std::string_view ename) {
  std::size_t i = 0;
  while (i < ename.size() && std::isalpha(static_cast<unsigned char>(ename[i]))) ++i;
  if (i == ename.size() || ename.size() - i > 6) return -1;
  int n = 0;
  for (; i < ename.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(ename[i]))) return -1;
    n = 10 * n + (ename[i] - '0');
  }
  return n;
}

SolidShape solid_shape(Family family, const long long* n, int count) {
  if (family == Family::Tet) {
    // SOLID187 and its kin list the midside nodes after the corners (I, J,
    // K, L, then IJ, JK, KI, IL, JL, KL: kTetEdges' order); a tet whose
    // midside nodes were dropped lists 4, or 10 with the six left 0.
    if (count == 4 || (count == 10 && none_listed(n, 4, 10)))
      return distinct(n, {0, 1, 2, 3}) ? shape_of(Shape::Tet4, {0, 1, 2, 3}) : SolidShape{};
    if (count == 10 && distinct(n, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9}))
      return shape_of(Shape::Tet10, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
    return {};
  }
  if (family != Family::Brick) return {};
  if (count == 8 || (count == 20 && none_listed(n, 8, 20))) return brick_corners(n);
  // SOLID186's degenerate tet: I, J, K, K, M, M, M, M, then the edges Q (IJ),
  // R (JK), S (KK, = K), T (KI), U..X (= M), Y (IM), Z (JM), A (KM), B (= A).
  if (count == 20 && brick_corners(n).shape == Shape::Tet4 && n[10] == n[2] && all_same(n, {4, 12, 13, 14, 15}) &&
      n[18] == n[19] && distinct(n, {0, 1, 2, 4, 8, 9, 11, 16, 17, 18}))
    return shape_of(Shape::Tet10, {0, 1, 2, 4, 8, 9, 11, 16, 17, 18});
  return {};
}

bool changes_mesh(std::string_view command) {
  for (std::string_view name : kMeshCommands) {
    if (command == name) return true;
    // APDL takes a command cut to its first four letters or more.
    if (command.size() >= 4 && command.size() < name.size() && name.substr(0, command.size()) == command) return true;
  }
  return false;
}

}  // namespace tetsmooth::ansys
