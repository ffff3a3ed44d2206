// Compiled with approximate float square roots and divisions (CMakeLists.txt).
#include "kernels/cuda/sweep_loop_impl.cuh"

namespace tetsmooth::cuda {
TETSMOOTH_INSTANTIATE_SWEEP_LOOP(float)
}
