#pragma once
// Mesh topology built on the GPU the paper's way (§3.2-3.3), item for item
// equal to the CPU version in mesh/topology.hpp and mesh/colouring.hpp.
// Everything stays on the device; the smoother reads it through MeshView.
#include <cuda_runtime.h>

#include <cstdint>
#include <vector>

#include "kernels/cuda/device_buffer.hpp"
#include "kernels/cuda/side_stream.hpp"
#include "kernels/node_update.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::cuda {

struct DeviceTopology {
  std::size_t num_nodes = 0, num_tets = 0;
  DeviceBuffer<index_t> nbr_off, nbr;   // node -> neighbours (CSR, rows ascending)
  DeviceBuffer<index_t> inc_off, inc;   // node -> incident tets (CSR, rows ascending)
  DeviceBuffer<std::uint8_t> boundary;  // 1 on a face used once
  DeviceBuffer<std::uint8_t> movable;   // !boundary && !fixed && has a neighbour
  DeviceBuffer<std::int32_t> colour;    // per node, -1 when not movable (after colour_device)
  DeviceBuffer<index_t> class_off, class_nodes;  // colour -> nodes ascending (CSR)
  std::vector<index_t> class_off_host;  // the same offsets on the host, for launching per colour
  // The nodes in descending colouring priority; priority_order_built says
  // the topology build left it for this mesh (else colour_device sorts it).
  DeviceBuffer<index_t> priority_order;
  bool priority_order_built = false;
  int num_colours = 0, colour_rounds = 0;
  std::size_t movable_count = 0;
  // Scratch reused across calls so a benchmark loop allocates once.
  DeviceBuffer<unsigned char> scratch;
  // Where the incidence rows and the boundary are built while the main
  // stream builds the neighbour rows (device_topology.cu).
  SideStream side;

  MeshView view(const index_t* d_tets) const {
    return MeshView{d_tets, nbr_off.data(), nbr.data(), inc_off.data(), inc.data()};
  }
};

// Builds neighbours, incidence, boundary and movable flags from tets already
// on the device. d_fixed may be null (no file-pinned nodes). With
// priority_order, also the colouring's priority order, on the side stream
// (where it costs the run nothing but memory traffic), for a colour_device
// that follows.
void build_device_topology(DeviceTopology& topo, const index_t* d_tets, std::size_t num_tets, std::size_t num_nodes,
                           const std::uint8_t* d_fixed, cudaStream_t stream, bool priority_order = false);

// Jones-Plassmann colouring with the same priorities and first-fit rule as
// mesh/colouring.hpp, so the result equals colour_nodes() exactly.
// max_blocks > 0 caps the launch (tests use it so that each thread group
// colours many nodes, waiting on others' results); 0 starts all the device
// holds.
void colour_device(DeviceTopology& topo, cudaStream_t stream, unsigned max_blocks = 0);

}  // namespace tetsmooth::cuda
