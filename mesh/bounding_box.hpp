#pragma once
// The axis-aligned box around a mesh's nodes.
#include <algorithm>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

struct BoundingBox {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};  // all 0 for a mesh without nodes
  double centre(int k) const { return 0.5 * (lo[k] + hi[k]); }
  double largest_side() const { return std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]}); }
};

namespace detail {
// The box grown by node i; `first` says the box holds no node yet.
inline void take_node(BoundingBox& b, bool& first, const TetMesh& mesh, std::size_t i) {
  for (int k = 0; k < 3; ++k) {
    const double x = mesh.xyz[3 * i + k];
    b.lo[k] = first ? x : std::min(b.lo[k], x);
    b.hi[k] = first ? x : std::max(b.hi[k], x);
  }
  first = false;
}
}  // namespace detail

inline BoundingBox bounding_box(const TetMesh& mesh) {
  BoundingBox b;
  bool first = true;
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i) detail::take_node(b, first, mesh, i);
  return b;
}

// The box around the tets' corners alone: a node no tet uses (a stray point
// far away, a geometry vertex) takes no part in smoothing, and must not
// stretch the frame a float run works in. The whole mesh's box when there
// are no tets.
inline BoundingBox tet_corners_bounding_box(const TetMesh& mesh) {
  if (mesh.tets.empty()) return bounding_box(mesh);
  std::vector<char> used(mesh.num_nodes(), 0);  // marked first: the nodes then read in order, once
  // An index out of range is validate_mesh's to name, not this box's.
  for (const index_t v : mesh.tets)
    if (v >= 0 && static_cast<std::size_t>(v) < used.size()) used[static_cast<std::size_t>(v)] = 1;
  BoundingBox b;
  bool first = true;
  for (std::size_t i = 0; i < mesh.num_nodes(); ++i)
    if (used[i]) detail::take_node(b, first, mesh, i);
  return b;
}

}  // namespace tetsmooth
