#pragma once
// How many blocks of a kernel the device holds at once: the most a
// cooperative launch (grid-wide barriers) may start.
#include <cuda_runtime.h>

#include "kernels/cuda/cuda_check.hpp"
#include "mesh/errors.hpp"

namespace tetsmooth::cuda {

template <class Kernel>
unsigned resident_blocks(Kernel kernel, int block_threads) {
  int device = 0, sms = 0, per_sm = 0;
  CUDA_CHECK(cudaGetDevice(&device));
  CUDA_CHECK(cudaDeviceGetAttribute(&sms, cudaDevAttrMultiProcessorCount, device));
  CUDA_CHECK(cudaOccupancyMaxActiveBlocksPerMultiprocessor(&per_sm, kernel, block_threads, 0));
  if (per_sm < 1) throw DeviceError("a cooperative kernel does not fit on a multiprocessor");
  return static_cast<unsigned>(per_sm) * static_cast<unsigned>(sms);
}

}  // namespace tetsmooth::cuda
