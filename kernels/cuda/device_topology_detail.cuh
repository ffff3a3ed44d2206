#pragma once
// Pieces shared by the device topology and colouring translation units:
// launch sizing, key widths, carving DeviceTopology::scratch, and the kernel
// that turns items sorted by row into CSR offsets.
#include <cuda_runtime.h>

#include <cstddef>
#include <cstdint>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth::cuda::detail {

inline constexpr unsigned kBlock = 256;

inline unsigned blocks_for(std::size_t threads) { return static_cast<unsigned>((threads + kBlock - 1) / kBlock); }

// Bits needed to write x in binary (0 for 0). Packed sort keys use exactly
// these widths so the radix sorts skip the always-zero high bits.
inline int bits_for(std::uint64_t x) {
  int b = 0;
  while (b < 64 && (x >> b) != 0) ++b;
  return b;
}

// Hands out 256-byte aligned pieces of one allocation, in order. Run once
// with a null base to measure, grow the buffer, then again to carve: both
// runs take the same pieces, so the pointers fit the measured size.
class ScratchCarver {
 public:
  explicit ScratchCarver(unsigned char* base) : base_(base) {}
  template <class T>
  T* take(std::size_t count) {
    T* piece = base_ ? reinterpret_cast<T*>(base_ + used_) : nullptr;
    used_ += (count * sizeof(T) + 255) / 256 * 256;
    return piece;
  }
  std::size_t used() const { return used_; }

 private:
  unsigned char* base_;
  std::size_t used_ = 0;
};

// CSR from n items sorted by row: offsets[s] = number of items whose row is
// below s, for s in 0..rows, so rows with no items get empty ranges. Items
// may end with a run of row == rows (a sentinel for dropped entries); they
// are counted in no row and not written. Launch with n_max + 1 threads; when
// n_dev is given, n is read from the device (a count not known on the host),
// otherwise n = n_max. Thread k fills the offsets between item k-1's row and
// item k's, so every offset is written exactly once.
template <class Source>
__global__ void csr_from_sorted(Source src, const unsigned long long* n_dev, unsigned long long n_max, index_t rows,
                                index_t* offsets, index_t* items) {
  const unsigned long long n = n_dev ? *n_dev : n_max;
  const unsigned long long k = blockIdx.x * static_cast<unsigned long long>(blockDim.x) + threadIdx.x;
  if (k > n) return;
  const long long prev = k == 0 ? -1 : static_cast<long long>(src.row(k - 1));
  const long long cur = k == n ? rows : static_cast<long long>(src.row(k));
  for (long long s = prev + 1; s <= cur; ++s) offsets[s] = static_cast<index_t>(k);
  if (items && k < n && cur < rows) items[k] = src.item(k);
}

// Items packed as row << shift | item, the layout of every topology key.
struct PackedRows {
  const std::uint64_t* keys;
  int shift;
  __device__ std::uint64_t row(unsigned long long k) const { return keys[k] >> shift; }
  __device__ index_t item(unsigned long long k) const {
    return static_cast<index_t>(keys[k] & ((1ull << shift) - 1));
  }
};

// Boundary flags from the tets' faces (device_topology_boundary.cu).
// `hash_work` and `id_work` must each hold 2 * 4 32-bit words per tet
// (32 B/tet); `temp` is CUB storage of face_temp_bytes().
std::size_t face_temp_bytes(std::size_t num_tets);
void mark_boundary_nodes(const index_t* d_tets, std::size_t num_tets, std::size_t num_nodes, void* hash_work,
                         void* id_work, void* temp, std::size_t temp_bytes, std::uint8_t* boundary,
                         cudaStream_t stream);

// The nodes in descending colouring priority (colouring_priority in
// mesh/colouring.hpp, ties by index), n entries into `order`: a function of
// n alone. keys0, keys1 and alt hold n entries each, temp
// priority_order_temp_bytes(n) (device_colouring.cu).
std::size_t priority_order_temp_bytes(std::size_t n);
void sort_priority_order(std::size_t n, index_t* order, std::uint32_t* keys0, std::uint32_t* keys1, index_t* alt,
                         void* temp, std::size_t temp_bytes, cudaStream_t stream);

}  // namespace tetsmooth::cuda::detail
