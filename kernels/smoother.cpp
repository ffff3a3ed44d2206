#include "kernels/smoother.hpp"

#include "kernels/second_order_smoothing.hpp"

namespace tetsmooth {

SmoothResult smooth(TetMesh& mesh, const SmoothOptions& options, Device device) {
  const auto run = [&] {
    if (device == Device::Cuda || (device == Device::Auto && cuda_available())) return smooth_cuda(mesh, options);
    return smooth_cpu(mesh, options);
  };
  return mesh.midsides.empty() ? run() : smooth_second_order(mesh, run);
}

}  // namespace tetsmooth
