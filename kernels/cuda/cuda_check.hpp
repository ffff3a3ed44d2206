#pragma once
// CUDA error checks that name the failing call and its error string.
#include <cuda_runtime.h>

#include <string>

#include "mesh/errors.hpp"

namespace tetsmooth::cuda {

[[noreturn]] inline void throw_cuda_error(cudaError_t err, const char* call, const char* file, int line) {
  throw DeviceError(std::string(call) + " failed at " + file + ":" + std::to_string(line) + ": " +
                    cudaGetErrorName(err) + " (" + cudaGetErrorString(err) + ")");
}

}  // namespace tetsmooth::cuda

// Throws DeviceError when `call` fails.
#define CUDA_CHECK(call)                                                                     \
  do {                                                                                       \
    const cudaError_t err_ = (call);                                                         \
    if (err_ != cudaSuccess) ::tetsmooth::cuda::throw_cuda_error(err_, #call, __FILE__, __LINE__); \
  } while (0)

// For destructors: never throws, drops the error.
#define CUDA_CHECK_NOTHROW(call) static_cast<void>(call)

// After a kernel launch: catches bad launch configurations at once.
#define CUDA_CHECK_LAUNCH() CUDA_CHECK(cudaGetLastError())
