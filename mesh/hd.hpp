#pragma once
// TS_HD marks functions that both the host compiler and nvcc build, so the
// per-node math exists once for every backend.
#if defined(__CUDACC__)
#define TS_HD __host__ __device__ __forceinline__
#else
#define TS_HD inline
#endif
