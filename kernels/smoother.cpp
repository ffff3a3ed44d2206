#include "kernels/smoother.hpp"

namespace tetsmooth {

SmoothResult smooth(TetMesh& mesh, const SmoothOptions& options, Device device) {
  if (device == Device::Cuda || (device == Device::Auto && cuda_available())) return smooth_cuda(mesh, options);
  return smooth_cpu(mesh, options);
}

}  // namespace tetsmooth
