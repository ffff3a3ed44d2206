#pragma once
// The mesh model shared by every module.
//
// Conventions (everything inside the library, whatever a file said):
//  * indices are 0-based `index_t` (int32: 2^31 nodes is far beyond one GPU);
//  * xyz holds #N nodes as packed x,y,z triples (AoS), 3*#N doubles;
//  * tets holds #T tets as 4 node indices each, 4*#T entries;
//  * a tet (a,b,c,d) is positively oriented when (b-a)·((c-a)×(d-a)) > 0.
//    A negative signed volume is an "inverted" tet, zero a "degenerate" one.
//  * Face f of a tet is the face opposite local vertex f:
//    f0=(1,2,3) f1=(0,3,2) f2=(0,1,3) f3=(0,2,1), each outward-facing for a
//    positively oriented tet.
//  * a second-order (10-node) tet is its four corners in tets and its six
//    midside nodes in midsides, edge e of a tet joining its local corners
//    kTetEdges[e] (VTK's quadratic tetra order; mesh/second_order.hpp).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/file_extras.hpp"

namespace tetsmooth {

using index_t = std::int32_t;

struct TetMesh {
  std::vector<double> xyz;    // 3 * num_nodes()
  std::vector<index_t> tets;  // 4 * num_tets()
  // Second-order meshes: 6 * num_tets() midside nodes, one per tet edge in
  // kTetEdges order; empty for first-order tets. The smoothers move the
  // corners alone (tets); smooth() carries the midside nodes along.
  std::vector<index_t> midsides;

  // Optional per-node flag (size num_nodes() or empty): nodes a file pins in
  // place, in addition to the geometric boundary (Medit RequiredVertices,
  // nodes of pass-through surface/line elements, ...).
  std::vector<std::uint8_t> fixed;

  // Data that only matters for writing a file back faithfully (original node
  // tags, region attributes, non-tet elements, format-specific sections).
  FileExtras extras;

  std::size_t num_nodes() const { return xyz.size() / 3; }
  std::size_t num_tets() const { return tets.size() / 4; }
};

// Local vertex triples of the four faces, see the file comment.
inline constexpr int kTetFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

// Local corners of a tet's six edges, in the order of the midside nodes
// (see the file comment).
inline constexpr int kTetEdges[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};

}  // namespace tetsmooth
