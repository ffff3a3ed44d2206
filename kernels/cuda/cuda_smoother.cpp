// smooth_cuda(): the library entry point for the CUDA backend. Plain C++
// around GpuPipeline; the quality summaries are computed on the host.
#include <cuda_runtime.h>

#include <algorithm>

#include "kernels/cuda/gpu_pipeline.hpp"
#include "kernels/smoother.hpp"
#include "mesh/errors.hpp"
#include "mesh/quality_summary.hpp"
#include "mesh/topology.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {

bool cuda_available(std::string* why) {
  int count = 0;
  const cudaError_t err = cudaGetDeviceCount(&count);
  if (err != cudaSuccess) {
    if (why) *why = std::string("no usable CUDA device: ") + cudaGetErrorString(err);
    static_cast<void>(cudaGetLastError());  // clear the sticky-free error so later calls start clean
    return false;
  }
  if (count == 0) {
    if (why) *why = "no CUDA device found";
    return false;
  }
  return true;
}

SmoothResult smooth_cuda(TetMesh& mesh, const SmoothOptions& options, const Colouring* colouring) {
  std::string why;
  if (!cuda_available(&why)) throw DeviceError(why);
  // The device trusts the mesh's shape: an index out of range, or a fixed
  // array of another length, would be read out of bounds there, and a mesh
  // without tets launches kernels of no blocks. The host's check names them.
  validate_mesh(mesh, "the mesh given to smooth_cuda");
  // The summaries need the movable flags; the host topology, on the CPU
  // threads the options ask for, is cheap next to reading and writing the
  // mesh files around this call.
  const Topology topo = build_topology(mesh, options.threads);
  // The coloured loop trusts its classes: a node listed there moves.
  if (colouring && options.strategy == Strategy::Coloured) {
    const std::string flaw = colouring_flaw(topo.neighbours, topo.movable, *colouring);
    if (!flaw.empty()) throw UsageError("the colouring given to smooth_cuda does not fit this mesh: " + flaw);
  }
  const QualitySummary before = summarize_quality(mesh, topo.movable);
  cuda::GpuPipeline pipeline(mesh);
  pipeline.restore_coordinates(options);
  SmoothResult r = pipeline.run(options, colouring);
  mesh.xyz = pipeline.download_xyz();
  r.before = before;
  r.after = summarize_quality(mesh, topo.movable);
  return r;
}

}  // namespace tetsmooth
