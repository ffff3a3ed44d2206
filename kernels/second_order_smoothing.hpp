#pragma once
// smooth() for second-order meshes (TetMesh::midsides, mesh/second_order.hpp):
// the smoothers move corners only, and this keeps the 10-node tets valid
// around them.
#include <functional>

#include "kernels/smooth_options.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// Runs `run` (a smoother of mesh that leaves nodes in mesh.fixed and nodes
// in no tet in place) with the corners of curved tets, and of edges whose
// midside node is pinned, added to mesh.fixed; then moves the midside nodes
// with their corners. Where a tet whose midside nodes lie off their edges'
// midpoints folds (folded_tets: rounding of the file's coordinates, or an
// offset under the straight-edge tolerance, bent further by the corners'
// moves), its corners are pinned too and `run` starts again from the input
// coordinates: each restart pins a corner that moved, and after
// kMaxRestarts every tet with an offset keeps its corners, so it ends.
// The result is the last run's, with the restarts and the tets they
// pinned counted in. mesh.fixed is the caller's again on return or throw.
SmoothResult smooth_second_order(TetMesh& mesh, const std::function<SmoothResult()>& run);

inline constexpr int kMaxRestarts = 8;

}  // namespace tetsmooth
