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
// the edge's length of the edge's midpoint, beyond what the rounding of the
// file's coordinates explains (coordinate_resolution; up to 1% of the edge).
// A midside node 1e-4 off changes the tet's Jacobian by well under 1% of
// the corner tet's.
inline constexpr double kStraightEdgeTolerance = 1e-4;

// How finely a file stored its coordinates, told from their values: `step`
// when every value is a whole multiple of one power of ten from 1 down to
// 1e-9 (an export rounded to millimetres, say: 1e-3), else 0; `relative`
// 2^-24 when every value is a float32 number (a binary VTU or VTK of
// Float32 points), else 0. Files that keep full double precision have
// neither. A midside node of a straight edge then lies off its edge's
// midpoint by at most about a step, or 2^-24 of its coordinates' size.
struct CoordinateResolution {
  double step = 0;
  double relative = 0;
};
CoordinateResolution coordinate_resolution(const std::vector<double>& xyz);

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

// Sets flags[m] for each midside node m whose edge's corners both have
// theirs set: with its corners in place, smoothing leaves it in place too.
// `flags` holds one per node; nothing changes for a first-order mesh.
void mark_midsides_of_marked_edges(const TetMesh& mesh, std::vector<std::uint8_t>& flags);

// For writers of formats without second-order tets (Medit, TetGen, .tsm):
// throws OutputError naming `format` when the mesh has midside nodes.
void check_first_order_output(const TetMesh& mesh, const std::string& format);

}  // namespace tetsmooth
