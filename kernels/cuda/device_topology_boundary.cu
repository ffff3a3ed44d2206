// Boundary nodes on the GPU (paper §3.3): every tet's 4 faces as sorted node
// triples, one radix sort, and a face that equals no other face is used
// once, so it is a boundary face and its 3 nodes are boundary nodes. As on
// the CPU (find_boundary_nodes in mesh/topology.hpp), an equal face whose
// tet has the same fourth node is the same tet listed again, not a
// neighbour, so it does not make the face interior.
//
// The sort key is a 32-bit hash of the sorted triple, with the face's index
// (4t + f) as the value, sorted on its top kSortedBits bits only: three
// radix passes over 8 bytes a face, whatever the node count, where the
// packed triple needs 3w bits (51 for the 109k model, 72 for the 10M-node
// lattice). Equal faces have equal hashes, so after the sort they lie in one
// run of equal sorted bits; a face is single when no other face of its run
// has the same triple. Different faces that share those bits only make a
// run longer (with 2^24 values, about one face in six of the 109k model's
// 2.9M meets such a stranger in its run): the full hash screens them
// cheaply, and the triples, not the hashes, decide.
#include <cub/device/device_radix_sort.cuh>

#include <string>

#include "kernels/cuda/cuda_check.hpp"
#include "kernels/cuda/device_topology_detail.cuh"
#include "mesh/errors.hpp"

namespace tetsmooth::cuda::detail {
namespace {

struct Triple {
  std::uint32_t a, b, c;  // ascending
};

__device__ bool operator==(const Triple& x, const Triple& y) { return x.a == y.a && x.b == y.b && x.c == y.c; }

// Face f of a tet is the triple without local vertex f; only the sorted
// triple matters here, so the orientation of mesh/tet_mesh.hpp is not needed.
__device__ Triple face_triple(const index_t* tets, std::size_t face) {
  const std::size_t t = face / 4;
  const int f = static_cast<int>(face % 4);
  std::uint32_t v[3];
  for (int k = 0, out = 0; k < 4; ++k)
    if (k != f) v[out++] = static_cast<std::uint32_t>(tets[4 * t + k]);
  const auto swap_if = [](std::uint32_t& x, std::uint32_t& y) {
    if (y < x) {
      const std::uint32_t s = x;
      x = y;
      y = s;
    }
  };
  swap_if(v[0], v[1]);
  swap_if(v[1], v[2]);
  swap_if(v[0], v[1]);
  return {v[0], v[1], v[2]};
}

// Any fixed mix of the three indices does; this is the splitmix64
// finaliser of a polynomial in them, high half.
__device__ std::uint32_t face_hash(const Triple& f) {
  std::uint64_t x = (static_cast<std::uint64_t>(f.a) * 0x9E3779B97F4A7C15ull + f.b) * 0xC2B2AE3D27D4EB4Full + f.c;
  x ^= x >> 30;
  x *= 0xBF58476D1CE4E5B9ull;
  x ^= x >> 27;
  x *= 0x94D049BB133111EBull;
  x ^= x >> 31;
  return static_cast<std::uint32_t>(x >> 32);
}

__global__ void emit_faces(const index_t* tets, std::size_t num_faces, std::uint32_t* hashes, std::uint32_t* ids) {
  const std::size_t k = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (k >= num_faces) return;
  hashes[k] = face_hash(face_triple(tets, k));
  ids[k] = static_cast<std::uint32_t>(k);
}

constexpr int kSortedBits = 24;
constexpr int kUnsortedBits = 32 - kSortedBits;

// The node of face `face`'s tet that the face leaves out (its local vertex f).
__device__ index_t opposite_node(const index_t* tets, std::size_t face) { return tets[face]; }

// Stores of 1 from several threads to one flag are race-free.
__global__ void mark_single_faces(const index_t* tets, const std::uint32_t* hashes, const std::uint32_t* ids,
                                  std::size_t n, std::uint8_t* boundary) {
  const std::size_t k = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (k >= n) return;
  const Triple mine = face_triple(tets, ids[k]);
  const index_t opposite = opposite_node(tets, ids[k]);
  const std::uint32_t h = hashes[k], run = h >> kUnsortedBits;
  // Another tet's use of this face: the same triple, another fourth node.
  const auto neighbour = [&](std::size_t j) {
    return hashes[j] == h && face_triple(tets, ids[j]) == mine && opposite_node(tets, ids[j]) != opposite;
  };
  for (std::size_t j = k; j > 0 && hashes[j - 1] >> kUnsortedBits == run; --j)
    if (neighbour(j - 1)) return;
  for (std::size_t j = k + 1; j < n && hashes[j] >> kUnsortedBits == run; ++j)
    if (neighbour(j)) return;
  boundary[mine.a] = 1;
  boundary[mine.b] = 1;
  boundary[mine.c] = 1;
}

}  // namespace

std::size_t face_temp_bytes(std::size_t num_tets) {
  cub::DoubleBuffer<std::uint32_t> keys(nullptr, nullptr), values(nullptr, nullptr);
  std::size_t bytes = 0;
  CUDA_CHECK(cub::DeviceRadixSort::SortPairs(nullptr, bytes, keys, values, 4 * num_tets, kUnsortedBits, 32));
  return bytes;
}

void mark_boundary_nodes(const index_t* d_tets, std::size_t num_tets, std::size_t num_nodes, void* hash_work,
                         void* id_work, void* temp, std::size_t temp_bytes, std::uint8_t* boundary,
                         cudaStream_t stream) {
  if (num_nodes > 0) CUDA_CHECK(cudaMemsetAsync(boundary, 0, num_nodes, stream));
  if (num_tets == 0) return;
  const std::size_t n = 4 * num_tets;
  if (n > 0xffffffffull)  // far past what the scratch of a GPU holds, but named rather than wrapped
    throw DeviceError("GPU topology: " + std::to_string(num_tets) + " tets give more faces than 32-bit face indices");
  auto* h = static_cast<std::uint32_t*>(hash_work);
  auto* id = static_cast<std::uint32_t*>(id_work);
  cub::DoubleBuffer<std::uint32_t> hashes(h, h + n), ids(id, id + n);
  emit_faces<<<blocks_for(n), kBlock, 0, stream>>>(d_tets, n, hashes.Current(), ids.Current());
  CUDA_CHECK_LAUNCH();
  CUDA_CHECK(cub::DeviceRadixSort::SortPairs(temp, temp_bytes, hashes, ids, n, kUnsortedBits, 32, stream));
  mark_single_faces<<<blocks_for(n), kBlock, 0, stream>>>(d_tets, hashes.Current(), ids.Current(), n, boundary);
  CUDA_CHECK_LAUNCH();
}

}  // namespace tetsmooth::cuda::detail
