#pragma once
// A CUDA event that owns its handle: recorded into a stream, then read as
// the milliseconds since an earlier event of the same stream (both must
// have completed: synchronise first).
#include <cuda_runtime.h>

#include "kernels/cuda/cuda_check.hpp"

namespace tetsmooth::cuda {

class Event {
 public:
  Event() { CUDA_CHECK(cudaEventCreate(&e_)); }
  ~Event() { CUDA_CHECK_NOTHROW(cudaEventDestroy(e_)); }
  Event(const Event&) = delete;
  Event& operator=(const Event&) = delete;
  void record(cudaStream_t s) { CUDA_CHECK(cudaEventRecord(e_, s)); }
  float ms_since(const Event& start) const {
    float ms = 0;
    CUDA_CHECK(cudaEventElapsedTime(&ms, start.e_, e_));
    return ms;
  }

 private:
  cudaEvent_t e_{};
};

}  // namespace tetsmooth::cuda
