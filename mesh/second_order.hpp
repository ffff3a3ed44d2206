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
// A midside node 1e-4 off changes a well-shaped tet's Jacobian by well under
// 1% of the corner tet's; a thin tet, or one with rounding offsets up to 1%,
// could still fold as its corners move, which smooth() checks afterwards
// (folded_tets, kernels/second_order_smoothing.hpp).
inline constexpr double kStraightEdgeTolerance = 1e-4;

// How finely a file stored its coordinates, told from their values: `step`
// when every value is a whole multiple of one power of ten from 1 down to
// 1e-9 (an export rounded to millimetres, say: 1e-3), else 0; `relative`
// half the rounding of a value relative to its size: 2^-24 when every value
// is a float32 number (a binary VTU or VTK of Float32 points), 0.5e-5 when
// no value has more than 6 significant digits (C's %g), and so on; 0 for
// files that keep full double precision. A midside node of a straight edge
// then lies off its edge's midpoint by at most about a step, or `relative`
// of its coordinates' size.
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

// The smallest determinant of the Jacobian of tet t's quadratic map, with
// the coordinates `xyz` (3 per node), over 15 points: the corners, the
// midside nodes, the centroid and the 4-point Gauss rule's points. For a
// straight-sided tet it is constant, six times the signed volume. A sample,
// not a bound: it catches a tet folding near its nodes or its middle.
double smallest_jacobian(const TetMesh& mesh, const std::vector<double>& xyz, std::size_t t);

// Whether every midside node of tet t lies exactly on its edge's midpoint,
// with the coordinates `xyz`: the tet is then its corner tet, mapped
// affinely.
bool exactly_straight(const TetMesh& mesh, const std::vector<double>& xyz, std::size_t t);

// The tets with a midside node off its edge's midpoint (exactly straight
// tets fold only with their corner tets, which the smoothers judge) whose
// smallest_jacobian was positive with the coordinates `before` and is not
// with mesh.xyz.
std::vector<std::size_t> folded_tets(const TetMesh& mesh, const std::vector<double>& before);

// Moves every midside node whose edge's corners moved since `before` (the
// coordinates before smoothing, 3 per node) by the mean of their moves. A
// midside node whose corners did not move keeps its coordinates bit for
// bit.
void carry_midside_nodes(TetMesh& mesh, const std::vector<double>& before);

// Where a file format lists the midside node of each kTetEdges edge among
// a 10-node tet's nodes (its corners are nodes 0-3 in every format here);
// each format's reader and writer keep their own table.
using MidsidePlaces = int[6];

// Appends a tet listed as a file lists it (`nodes`: 4 corners, then the
// midside nodes at `places` when `ten`) to mesh.tets and mesh.midsides.
void append_file_tet(TetMesh& mesh, const index_t* nodes, bool ten, const MidsidePlaces& places);
// Tet t's ten nodes in a file's order, into out[0..9].
void file_tet10(const TetMesh& mesh, std::size_t t, const MidsidePlaces& places, index_t* out);

// Turns every tet listed left-handed (negative signed volume) round by
// swapping its corners 1 and 2, and its midside nodes with them, as the
// readers of formats whose solvers take a tet's nodes in either handedness
// (Nastran, LS-DYNA) do; returns how many it turned.
std::size_t turn_left_handed_tets(TetMesh& mesh);

// The message for a file whose tets are not all of one kind, at its first
// tet with `nodes` nodes (4 or 10) after tets of the other kind.
std::string mixed_tet_kinds(int nodes);

// Sets flags[m] for each midside node m whose edge's corners both have
// theirs set: with its corners in place, smoothing leaves it in place too.
// `flags` holds one per node; nothing changes for a first-order mesh.
void mark_midsides_of_marked_edges(const TetMesh& mesh, std::vector<std::uint8_t>& flags);

// For writers of formats without second-order tets (Medit, .tsm):
// throws OutputError naming `format` when the mesh has midside nodes.
void check_first_order_output(const TetMesh& mesh, const std::string& format);

}  // namespace tetsmooth
