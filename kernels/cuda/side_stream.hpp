#pragma once
// A second stream for work that need not wait on the main stream's latest
// work: begun after everything enqueued on the main stream so far, and
// awaited by the main stream where it needs the result. Created on first
// use, so an object that never forks costs nothing.
#include <cuda_runtime.h>

#include <utility>

#include "kernels/cuda/cuda_check.hpp"

namespace tetsmooth::cuda {

class SideStream {
 public:
  SideStream() = default;
  SideStream(const SideStream&) = delete;
  SideStream& operator=(const SideStream&) = delete;
  SideStream(SideStream&& o) noexcept
      : side_(std::exchange(o.side_, nullptr)),
        begun_(std::exchange(o.begun_, nullptr)),
        ended_(std::exchange(o.ended_, nullptr)) {}
  SideStream& operator=(SideStream&& o) noexcept {
    if (this != &o) {
      release();
      side_ = std::exchange(o.side_, nullptr);
      begun_ = std::exchange(o.begun_, nullptr);
      ended_ = std::exchange(o.ended_, nullptr);
    }
    return *this;
  }
  ~SideStream() { release(); }

  // The side stream, ordered after the work enqueued on `main` so far.
  cudaStream_t begin(cudaStream_t main) {
    if (!side_) {
      CUDA_CHECK(cudaStreamCreateWithFlags(&side_, cudaStreamNonBlocking));
      CUDA_CHECK(cudaEventCreateWithFlags(&begun_, cudaEventDisableTiming));
      CUDA_CHECK(cudaEventCreateWithFlags(&ended_, cudaEventDisableTiming));
    }
    CUDA_CHECK(cudaEventRecord(begun_, main));
    CUDA_CHECK(cudaStreamWaitEvent(side_, begun_, 0));
    return side_;
  }
  // Marks the end of the side's work: what await() waits for.
  void end() { CUDA_CHECK(cudaEventRecord(ended_, side_)); }
  // Orders the work enqueued on `main` from now on after the side's work.
  void await(cudaStream_t main) const { CUDA_CHECK(cudaStreamWaitEvent(main, ended_, 0)); }

 private:
  void release() noexcept {
    if (ended_) CUDA_CHECK_NOTHROW(cudaEventDestroy(ended_));
    if (begun_) CUDA_CHECK_NOTHROW(cudaEventDestroy(begun_));
    if (side_) CUDA_CHECK_NOTHROW(cudaStreamDestroy(side_));
    side_ = nullptr;
    begun_ = ended_ = nullptr;
  }
  cudaStream_t side_ = nullptr;
  cudaEvent_t begun_ = nullptr, ended_ = nullptr;
};

}  // namespace tetsmooth::cuda
