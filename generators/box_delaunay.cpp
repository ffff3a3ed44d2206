// Lattice-plus-random-nodes boxes, the input meshes of the paper's §4.1:
// equidistant nodes, then random nodes in the same box, then TetGen's
// Delaunay tetrahedralisation of the point set.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

#include "generators/models.hpp"
#include "generators/rng.hpp"
#include "generators/tetgen_bridge.hpp"
#include "mesh/errors.hpp"

namespace tetsmooth {

TetMesh generate_box_delaunay(int lattice_per_axis, int random_nodes, std::uint64_t seed) {
  // Either no lattice, or at least the 8 corners, so that the convex hull,
  // and hence the mesh, is the whole unit box whatever the random nodes do.
  if (lattice_per_axis < 0 || lattice_per_axis == 1)
    throw UsageError("box model: lattice_per_axis must be 0 (none) or >= 2 (the box corners), got " +
                     std::to_string(lattice_per_axis));
  if (random_nodes < 0)
    throw UsageError("box model: random_nodes must be >= 0, got " + std::to_string(random_nodes));
  const std::int64_t n = lattice_per_axis;
  if (n > 1290 || n * n * n + random_nodes > std::numeric_limits<index_t>::max())
    throw UsageError("box model: " + std::to_string(lattice_per_axis) + "^3 lattice nodes plus " +
                     std::to_string(random_nodes) + " random nodes exceed 32-bit node indices");
  const std::int64_t total = n * n * n + random_nodes;
  if (total < 4) throw UsageError("box model: a tetrahedralisation needs at least 4 nodes");

  tetgenio in;
  in.numberofpoints = static_cast<int>(total);
  in.pointlist = new REAL[3 * static_cast<std::size_t>(total)];  // owned and freed by tetgenio
  REAL* p = in.pointlist;
  const double h = n > 1 ? 1.0 / static_cast<double>(n - 1) : 0.0;
  for (std::int64_t k = 0; k < n; ++k)
    for (std::int64_t j = 0; j < n; ++j)
      for (std::int64_t i = 0; i < n; ++i) {
        *p++ = static_cast<double>(i) * h;
        *p++ = static_cast<double>(j) * h;
        *p++ = static_cast<double>(k) * h;
      }
  // Open-interval draws keep random nodes off the faces, and in practice off
  // every lattice node: TetGen would leave a duplicate unreferenced.
  SplitMix64 rng(seed);
  for (int r = 0; r < random_nodes; ++r)
    for (int c = 0; c < 3; ++c) *p++ = rng.open01();

  // No 'p', 'q' or 'a': a plain Delaunay tetrahedralisation adds no Steiner
  // points, so the node count is exactly the input's.
  TetMesh mesh = run_tetgen(in, "", "box model (" + std::to_string(lattice_per_axis) + "^3 lattice + " +
                                        std::to_string(random_nodes) + " random nodes)");
  if (mesh.num_nodes() != static_cast<std::size_t>(total))
    throw std::runtime_error("box model: TetGen returned " + std::to_string(mesh.num_nodes()) +
                             " nodes for " + std::to_string(total) + " input points");
  return mesh;
}

}  // namespace tetsmooth
