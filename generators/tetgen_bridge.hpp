#pragma once
// The one place that calls TetGen: runs tetrahedralize() and hands back a
// TetMesh in the library's conventions (0-based, positively oriented tets).
#include <string>

#include <tetgen.h>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// Runs TetGen on `in` with the model's `switches` ("" for a Delaunay
// tetrahedralisation of the points, "pq1.4a0.1" for a quality mesh of a PLC,
// ...); the bridge adds "zQF" (0-based, quiet, no face lists). `what` names
// the model in messages. Throws std::runtime_error when TetGen gives up or
// returns a tet that is not positively oriented.
TetMesh run_tetgen(tetgenio& in, const std::string& switches, const std::string& what);

}  // namespace tetsmooth
