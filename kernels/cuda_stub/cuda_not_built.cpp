// Stands in for the CUDA backend when the build has no CUDA compiler.
#include "kernels/smoother.hpp"
#include "mesh/errors.hpp"

namespace tetsmooth {

bool cuda_available(std::string* why) {
  if (why) *why = "CUDA support not built (no CUDA compiler was found when configuring)";
  return false;
}

SmoothResult smooth_cuda(TetMesh&, const SmoothOptions&, const Colouring*) {
  throw DeviceError("CUDA support not built: reconfigure with a CUDA toolkit (nvcc) to use --device cuda");
}

}  // namespace tetsmooth
