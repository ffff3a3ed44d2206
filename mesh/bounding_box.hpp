#pragma once
// The axis-aligned box around a mesh's nodes.
#include <algorithm>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

struct BoundingBox {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};  // all 0 for a mesh without nodes
  double centre(int k) const { return 0.5 * (lo[k] + hi[k]); }
  double largest_side() const { return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}); }
};

inline BoundingBox bounding_box(const TetMesh& mesh) {
  BoundingBox b;
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i)
    for (int k = 0; k < 3; ++k) {
      const double x = mesh.xyz[3 * i + k];
      b.lo[k] = i == 0 ? x : std::min(b.lo[k], x);
      b.hi[k] = i == 0 ? x : std::max(b.hi[k], x);
    }
  return b;
}

}  // namespace tetsmooth
