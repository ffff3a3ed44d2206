#pragma once
// Second-order (10-node) tets: each tet's corners are in TetMesh::tets and
// the nodes at the middle of its six edges in TetMesh::midsides, in
// kTetEdges order. Smoothing moves corners only. A midside node then moves
// with its edge, by the mean of its two corners' moves, so that it keeps
// its offset from the edge's midpoint: a straight edge stays straight, and
// whatever offset the file gave it is kept.
//
// A tet whose edges are all straight is its corner tet, mapped affinely:
// its quality and validity are the corner tet's, which the smoothers judge.
// A curved edge (a midside node on a curved boundary, say) bends the tet,
// and the corner tet alone no longer tells whether a move keeps it valid,
// so the corners of such a tet stay in place, and with them its midside
// nodes: curved tets come back as they were.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// An edge is straight when its midside node lies within this fraction of
// the edge's length of the edge's midpoint. Loose enough for coordinates
// stored in single precision (about 1e-7 of their size), so that a file
// written in float32 still has straight edges; a midside node that far off
// changes the tet's Jacobian by well under 1% of the corner tet's.
inline constexpr double kStraightEdgeTolerance = 1e-4;

// The corners that must stay: all four of each tet with a curved edge, and
// both corners of each edge whose midside node the mesh pins (mesh.fixed),
// so that the node stays where the file pinned it (a 6-node boundary
// triangle pins its midside nodes, whose edges' corners are on the boundary
// anyway). Empty flags and no tets for a first-order mesh.
struct CurvedTetPins {
  std::vector<std::uint8_t> corners;  // per node, 1 to stay
  std::size_t tets = 0;               // tets with a curved edge
};
CurvedTetPins curved_tet_pins(const TetMesh& mesh);

// Moves every midside node whose edge's corners moved since `before` (the
// coordinates before smoothing, 3 per node) by the mean of their moves. A
// midside node whose corners did not move keeps its coordinates bit for
// bit.
void carry_midside_nodes(TetMesh& mesh, const std::vector<double>& before);

// For writers of formats without second-order tets (Medit, TetGen, .tsm):
// throws OutputError naming `format` when the mesh has midside nodes.
void check_first_order_output(const TetMesh& mesh, const std::string& format);

}  // namespace tetsmooth
