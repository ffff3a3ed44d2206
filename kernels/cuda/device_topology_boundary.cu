// Boundary nodes on the GPU (paper §3.3): every tet's 4 faces as sorted node
// triples, one radix sort, and a face that equals neither sorted neighbour
// is used once, so it is a boundary face and its 3 nodes are boundary nodes.
//
// A face (a <= b <= c) is packed as the integer a << 2w | b << w | c with
// w = bits of the largest node index. When 3w <= 64 that is one 64-bit key;
// beyond 2^21 nodes (the 10M-node lattice needs 3 * 24 = 72 bits) it is a
// 96-bit key of three 32-bit words that CUB sorts through a decomposer. Either
// way the sort only visits the 3w bits that can be non-zero.
#include <cub/device/device_radix_sort.cuh>
#include <cuda/std/tuple>

#include "kernels/cuda/cuda_check.hpp"
#include "kernels/cuda/device_topology_detail.cuh"

namespace tetsmooth::cuda::detail {
namespace {

struct Face96 {
  std::uint32_t hi, mid, lo;  // the packed integer, most significant word first
};

// CUB reads a Face96 as the three words, leftmost most significant.
struct Face96Words {
  __host__ __device__ ::cuda::std::tuple<std::uint32_t&, std::uint32_t&, std::uint32_t&> operator()(
      Face96& f) const {
    return {f.hi, f.mid, f.lo};
  }
};

__device__ bool same_face(std::uint64_t x, std::uint64_t y) { return x == y; }
__device__ bool same_face(const Face96& x, const Face96& y) { return x.hi == y.hi && x.mid == y.mid && x.lo == y.lo; }

// The low 64 bits of the packed face, and (for Face96) the bits above.
__device__ void pack_face(std::uint32_t a, std::uint32_t b, std::uint32_t c, int w, std::uint64_t& key) {
  key = (static_cast<std::uint64_t>(a) << 2 * w) | (static_cast<std::uint64_t>(b) << w) | c;
}
__device__ void pack_face(std::uint32_t a, std::uint32_t b, std::uint32_t c, int w, Face96& key) {
  const std::uint64_t low = (static_cast<std::uint64_t>(a) << 2 * w) | (static_cast<std::uint64_t>(b) << w) | c;
  key.hi = static_cast<std::uint32_t>(static_cast<std::uint64_t>(a) >> (64 - 2 * w));  // 2w <= 62
  key.mid = static_cast<std::uint32_t>(low >> 32);
  key.lo = static_cast<std::uint32_t>(low);
}

__device__ void unpack_face(std::uint64_t key, int w, std::uint32_t (&n)[3]) {
  const std::uint64_t mask = (1ull << w) - 1;
  n[0] = static_cast<std::uint32_t>(key >> 2 * w);
  n[1] = static_cast<std::uint32_t>((key >> w) & mask);
  n[2] = static_cast<std::uint32_t>(key & mask);
}
__device__ void unpack_face(const Face96& key, int w, std::uint32_t (&n)[3]) {
  const std::uint64_t low = (static_cast<std::uint64_t>(key.mid) << 32) | key.lo;
  const std::uint64_t mask = (1ull << w) - 1;
  n[0] = static_cast<std::uint32_t>((low >> 2 * w) | (static_cast<std::uint64_t>(key.hi) << (64 - 2 * w)));
  n[1] = static_cast<std::uint32_t>((low >> w) & mask);
  n[2] = static_cast<std::uint32_t>(low & mask);
}

__device__ void sort3(std::uint32_t& a, std::uint32_t& b, std::uint32_t& c) {
  const auto swap_if = [](std::uint32_t& x, std::uint32_t& y) {
    if (y < x) {
      const std::uint32_t t = x;
      x = y;
      y = t;
    }
  };
  swap_if(a, b);
  swap_if(b, c);
  swap_if(a, b);
}

// Face f of a tet is the triple without local vertex f; only the sorted
// triple matters here, so the orientation of mesh/tet_mesh.hpp is not needed.
template <class Key>
__global__ void emit_faces(const index_t* tets, std::size_t num_tets, int w, Key* faces) {
  const std::size_t t = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (t >= num_tets) return;
  std::uint32_t v[4];
  for (int k = 0; k < 4; ++k) v[k] = static_cast<std::uint32_t>(tets[4 * t + k]);
  for (int f = 0; f < 4; ++f) {
    std::uint32_t a = v[f == 0 ? 1 : 0], b = v[f <= 1 ? 2 : 1], c = v[f <= 2 ? 3 : 2];
    sort3(a, b, c);
    pack_face(a, b, c, w, faces[4 * t + f]);
  }
}

// Stores of 1 from several threads to one flag are race-free.
template <class Key>
__global__ void mark_single_faces(const Key* faces, std::size_t n, int w, std::uint8_t* boundary) {
  const std::size_t k = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (k >= n) return;
  const bool same_prev = k > 0 && same_face(faces[k - 1], faces[k]);
  const bool same_next = k + 1 < n && same_face(faces[k + 1], faces[k]);
  if (same_prev || same_next) return;
  std::uint32_t nodes[3];
  unpack_face(faces[k], w, nodes);
  for (std::uint32_t i : nodes) boundary[i] = 1;
}

int face_width(std::size_t num_nodes) { return bits_for(num_nodes > 0 ? num_nodes - 1 : 0); }
bool fits_64(std::size_t num_nodes) { return 3 * face_width(num_nodes) <= 64; }

cudaError_t sort_faces(void* temp, std::size_t& temp_bytes, cub::DoubleBuffer<std::uint64_t>& keys, std::size_t n,
                       int w, cudaStream_t stream) {
  return cub::DeviceRadixSort::SortKeys(temp, temp_bytes, keys, n, 0, 3 * w, stream);
}
cudaError_t sort_faces(void* temp, std::size_t& temp_bytes, cub::DoubleBuffer<Face96>& keys, std::size_t n, int w,
                       cudaStream_t stream) {
  return cub::DeviceRadixSort::SortKeys(temp, temp_bytes, keys, n, Face96Words{}, 0, 3 * w, stream);
}

template <class Key>
std::size_t temp_bytes_for(std::size_t num_tets, std::size_t num_nodes) {
  cub::DoubleBuffer<Key> keys(nullptr, nullptr);
  std::size_t bytes = 0;
  CUDA_CHECK(sort_faces(nullptr, bytes, keys, 4 * num_tets, face_width(num_nodes), nullptr));
  return bytes;
}

template <class Key>
void mark_with(const index_t* d_tets, std::size_t num_tets, std::size_t num_nodes, void* work, void* temp,
               std::size_t temp_bytes, std::uint8_t* boundary, cudaStream_t stream) {
  const std::size_t n = 4 * num_tets;
  const int w = face_width(num_nodes);
  Key* first = static_cast<Key*>(work);
  cub::DoubleBuffer<Key> keys(first, first + n);
  emit_faces<<<blocks_for(num_tets), kBlock, 0, stream>>>(d_tets, num_tets, w, first);
  CUDA_CHECK_LAUNCH();
  CUDA_CHECK(sort_faces(temp, temp_bytes, keys, n, w, stream));
  mark_single_faces<<<blocks_for(n), kBlock, 0, stream>>>(keys.Current(), n, w, boundary);
  CUDA_CHECK_LAUNCH();
}

}  // namespace

std::size_t face_temp_bytes(std::size_t num_tets, std::size_t num_nodes) {
  return fits_64(num_nodes) ? temp_bytes_for<std::uint64_t>(num_tets, num_nodes)
                            : temp_bytes_for<Face96>(num_tets, num_nodes);
}

void mark_boundary_nodes(const index_t* d_tets, std::size_t num_tets, std::size_t num_nodes, void* work, void* temp,
                         std::size_t temp_bytes, std::uint8_t* boundary, cudaStream_t stream) {
  if (num_nodes > 0) CUDA_CHECK(cudaMemsetAsync(boundary, 0, num_nodes, stream));
  if (num_tets == 0) return;
  if (fits_64(num_nodes))
    mark_with<std::uint64_t>(d_tets, num_tets, num_nodes, work, temp, temp_bytes, boundary, stream);
  else
    mark_with<Face96>(d_tets, num_tets, num_nodes, work, temp, temp_bytes, boundary, stream);
}

}  // namespace tetsmooth::cuda::detail
