// Runs the device topology and colouring on a mesh and copies every array
// back, so tests can compare them item by item with the CPU versions.
#include "kernels/cuda/topology_snapshot.hpp"

#include "kernels/cuda/device_buffer.hpp"
#include "kernels/cuda/device_topology.hpp"

namespace tetsmooth::cuda {

TopologySnapshot gpu_topology_snapshot(const TetMesh& mesh, unsigned colour_blocks, bool order_with_topology) {
  const cudaStream_t stream = nullptr;
  DeviceBuffer<index_t> tets;
  DeviceBuffer<std::uint8_t> fixed;
  tets.upload(mesh.tets, stream);
  if (!mesh.fixed.empty()) fixed.upload(mesh.fixed, stream);

  DeviceTopology topo;
  build_device_topology(topo, tets.data(), mesh.num_tets(), mesh.num_nodes(), fixed.data(), stream,
                        order_with_topology);
  colour_device(topo, stream, colour_blocks);

  TopologySnapshot snap;
  snap.neighbours = Csr{topo.nbr_off.download(stream), topo.nbr.download(stream)};
  snap.node_tets = Csr{topo.inc_off.download(stream), topo.inc.download(stream)};
  snap.boundary = topo.boundary.download(stream);
  snap.movable = topo.movable.download(stream);
  snap.colouring.colour = topo.colour.download(stream);
  snap.colouring.num_colours = topo.num_colours;
  snap.colouring.rounds = topo.colour_rounds;
  snap.colouring.classes = Csr{topo.class_off_host, topo.class_nodes.download(stream)};
  return snap;
}

}  // namespace tetsmooth::cuda
