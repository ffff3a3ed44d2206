#pragma once
// Host-side view of the GPU topology, for tests that compare it with the CPU
// version. Plain C++: callers need no CUDA headers.
#include <cstdint>
#include <vector>

#include "mesh/colouring.hpp"
#include "mesh/csr.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::cuda {

struct TopologySnapshot {
  Csr neighbours, node_tets;
  std::vector<std::uint8_t> boundary, movable;
  Colouring colouring;  // colour per node, classes, num_colours, rounds
};

// Uploads the mesh, builds topology and colouring on the GPU, downloads all.
// colour_blocks > 0 caps the colouring launch (see colour_device);
// order_with_topology has the topology build sort the colouring's priority
// order (see build_device_topology).
TopologySnapshot gpu_topology_snapshot(const TetMesh& mesh, unsigned colour_blocks = 0,
                                       bool order_with_topology = false);

}  // namespace tetsmooth::cuda
