// Jones-Plassmann colouring on the GPU, round for round the CPU's
// colour_nodes() (mesh/colouring.cpp): same priorities, same first-fit rule,
// so the same colours and the same number of rounds.
//
// Each round is one kernel over all nodes. A node's state is round_of[i]:
// 0 for nodes that never move, r >= 1 for the round that coloured it,
// kUncoloured while it waits. Round r only treats a neighbour j as coloured
// when round_of[j] < r, so it sees exactly the colours of earlier rounds:
//  * the only writes of round r are colour[i] and round_of[i] of its
//    winners;
//  * a neighbour reading round_of[i] of such a winner gets kUncoloured or r,
//    both >= r, so it decides the same either way (and it loses to i, which
//    beats all its uncoloured neighbours);
//  * colour[j] is only read when round_of[j] < r, i.e. written by an earlier
//    kernel on the same stream, never by this one;
//  * two winners are never neighbours: colours_before is a strict order.
//
// The host reads the per-round "still waiting" counts back once per batch of
// rounds; rounds past the last one find nothing to do.
//
// Classes: the colours (non-movable nodes as the sentinel num_colours) are
// radix sorted with the node indices as values; the sort is stable, so each
// class lists its nodes ascending, and only the bits of num_colours are sorted.
#include <cub/device/device_radix_sort.cuh>

#include <string>

#include "kernels/cuda/cuda_check.hpp"
#include "kernels/cuda/device_topology.hpp"
#include "kernels/cuda/device_topology_detail.cuh"
#include "mesh/colouring.hpp"
#include "mesh/errors.hpp"

namespace tetsmooth::cuda {
namespace {

using detail::blocks_for;
using detail::kBlock;

constexpr unsigned kUncoloured = 0xffffffffu;
constexpr int kRoundsPerCheck = 8;

struct RoundCounts {
  unsigned waiting[kRoundsPerCheck];  // movable nodes still uncoloured after each round of the batch
  int max_colour;
};

__global__ void init_rounds(std::size_t n, const std::uint8_t* movable, unsigned* round_of) {
  const std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (i < n) round_of[i] = movable[i] ? kUncoloured : 0u;
}

__device__ bool beats_waiting_neighbours(const index_t* nbr, index_t b, index_t e, const unsigned* round_of,
                                         unsigned r, index_t i) {
  for (index_t k = b; k < e; ++k) {
    const index_t j = nbr[k];
    if (round_of[j] >= r && colours_before(static_cast<std::uint32_t>(j), static_cast<std::uint32_t>(i)))
      return false;
  }
  return true;
}

// The smallest colour none of the earlier-coloured neighbours has, looked
// for 64 colours at a time.
__device__ int first_free_colour(const index_t* nbr, index_t b, index_t e, const unsigned* round_of,
                                 const int* colour, unsigned r) {
  for (int base = 0;; base += 64) {
    unsigned long long used = 0;
    for (index_t k = b; k < e; ++k) {
      const index_t j = nbr[k];
      if (round_of[j] >= r) continue;
      const int c = colour[j] - base;
      if (c >= 0 && c < 64) used |= 1ull << c;
    }
    if (~used != 0) return base + __ffsll(static_cast<long long>(~used)) - 1;
  }
}

// Launched over whole blocks: the block and warp reductions need every thread.
__global__ void colour_round(std::size_t n, const index_t* nbr_off, const index_t* nbr, unsigned r,
                             unsigned* round_of, int* colour, unsigned* waiting, int* max_colour) {
  const std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  bool waits = false;
  int picked = -1;
  if (i < n && round_of[i] == kUncoloured) {
    const auto node = static_cast<index_t>(i);
    const index_t b = nbr_off[i], e = nbr_off[i + 1];
    if (beats_waiting_neighbours(nbr, b, e, round_of, r, node)) {
      picked = first_free_colour(nbr, b, e, round_of, colour, r);
      colour[i] = picked;
      round_of[i] = r;
    } else {
      waits = true;
    }
  }
  const int block_waiting = __syncthreads_count(waits);
  if (threadIdx.x == 0 && block_waiting > 0) atomicAdd(waiting, static_cast<unsigned>(block_waiting));
  const int warp_max = __reduce_max_sync(0xffffffffu, picked);
  if (threadIdx.x % 32 == 0 && warp_max >= 0) atomicMax(max_colour, warp_max);
}

__global__ void class_keys(std::size_t n, const int* colour, std::uint32_t sentinel, std::uint32_t* keys,
                           index_t* nodes) {
  const std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (i >= n) return;
  keys[i] = colour[i] >= 0 ? static_cast<std::uint32_t>(colour[i]) : sentinel;
  nodes[i] = static_cast<index_t>(i);
}

struct ColourRows {
  const std::uint32_t* keys;
  const index_t* nodes;
  __device__ std::uint32_t row(unsigned long long k) const { return keys[k]; }
  __device__ index_t item(unsigned long long k) const { return nodes[k]; }
};

void run_rounds(DeviceTopology& topo, cudaStream_t stream) {
  const std::size_t n = topo.num_nodes;
  const auto carve = [n](unsigned char* base, unsigned*& round_of, RoundCounts*& counts) {
    detail::ScratchCarver carver(base);
    round_of = carver.take<unsigned>(n);
    counts = carver.take<RoundCounts>(1);
    return carver.used();
  };
  unsigned* round_of = nullptr;
  RoundCounts* counts = nullptr;
  topo.scratch.resize(carve(nullptr, round_of, counts));
  carve(topo.scratch.data(), round_of, counts);

  init_rounds<<<blocks_for(n), kBlock, 0, stream>>>(n, topo.movable.data(), round_of);
  CUDA_CHECK_LAUNCH();
  CUDA_CHECK(cudaMemsetAsync(&counts->max_colour, 0xff, sizeof(int), stream));
  // Every round colours at least the waiting node of highest priority.
  for (unsigned first = 1; first <= topo.movable_count; first += kRoundsPerCheck) {
    CUDA_CHECK(cudaMemsetAsync(counts->waiting, 0, sizeof(counts->waiting), stream));
    for (int s = 0; s < kRoundsPerCheck; ++s) {
      colour_round<<<blocks_for(n), kBlock, 0, stream>>>(n, topo.nbr_off.data(), topo.nbr.data(), first + s,
                                                         round_of, topo.colour.data(), &counts->waiting[s],
                                                         &counts->max_colour);
      CUDA_CHECK_LAUNCH();
    }
    RoundCounts host{};
    CUDA_CHECK(cudaMemcpyAsync(&host, counts, sizeof(RoundCounts), cudaMemcpyDeviceToHost, stream));
    CUDA_CHECK(cudaStreamSynchronize(stream));
    for (int s = 0; s < kRoundsPerCheck; ++s)
      if (host.waiting[s] == 0) {
        topo.colour_rounds = static_cast<int>(first) + s;
        topo.num_colours = host.max_colour + 1;
        return;
      }
  }
  throw DeviceError("colour_device: Jones-Plassmann left nodes uncoloured after " +
                    std::to_string(topo.movable_count) + " rounds");
}

void build_classes(DeviceTopology& topo, cudaStream_t stream) {
  const std::size_t n = topo.num_nodes;
  const auto nc = static_cast<std::uint32_t>(topo.num_colours);
  const int bits = detail::bits_for(nc);  // keys run 0..nc, nc being the sentinel
  topo.class_off.resize(nc + 1);
  topo.class_nodes.resize(topo.movable_count);

  std::size_t temp_bytes = 0;
  {
    cub::DoubleBuffer<std::uint32_t> keys(nullptr, nullptr);
    cub::DoubleBuffer<index_t> nodes(nullptr, nullptr);
    CUDA_CHECK(cub::DeviceRadixSort::SortPairs(nullptr, temp_bytes, keys, nodes, n, 0, bits));
  }
  const auto carve = [n, temp_bytes](unsigned char* base, cub::DoubleBuffer<std::uint32_t>& keys,
                                     cub::DoubleBuffer<index_t>& nodes, void*& temp) {
    detail::ScratchCarver carver(base);
    std::uint32_t* k0 = carver.take<std::uint32_t>(n);
    std::uint32_t* k1 = carver.take<std::uint32_t>(n);
    index_t* v0 = carver.take<index_t>(n);
    index_t* v1 = carver.take<index_t>(n);
    temp = carver.take<unsigned char>(temp_bytes);
    keys = cub::DoubleBuffer<std::uint32_t>(k0, k1);
    nodes = cub::DoubleBuffer<index_t>(v0, v1);
    return carver.used();
  };
  cub::DoubleBuffer<std::uint32_t> keys;
  cub::DoubleBuffer<index_t> nodes;
  void* temp = nullptr;
  topo.scratch.resize(carve(nullptr, keys, nodes, temp));
  carve(topo.scratch.data(), keys, nodes, temp);

  if (n > 0) {
    class_keys<<<blocks_for(n), kBlock, 0, stream>>>(n, topo.colour.data(), nc, keys.Current(), nodes.Current());
    CUDA_CHECK_LAUNCH();
    CUDA_CHECK(cub::DeviceRadixSort::SortPairs(temp, temp_bytes, keys, nodes, n, 0, bits, stream));
  }
  detail::csr_from_sorted<<<blocks_for(n + 1), kBlock, 0, stream>>>(
      ColourRows{keys.Current(), nodes.Current()}, static_cast<const unsigned long long*>(nullptr), n,
      static_cast<index_t>(nc), topo.class_off.data(), topo.class_nodes.data());
  CUDA_CHECK_LAUNCH();
  topo.class_off_host = topo.class_off.download(stream);
}

}  // namespace

void colour_device(DeviceTopology& topo, cudaStream_t stream) {
  topo.colour.resize(topo.num_nodes);
  if (topo.num_nodes > 0) CUDA_CHECK(cudaMemsetAsync(topo.colour.data(), 0xff, topo.colour.bytes(), stream));
  topo.num_colours = 0;
  topo.colour_rounds = 0;
  if (topo.movable_count > 0) run_rounds(topo, stream);
  build_classes(topo, stream);
}

}  // namespace tetsmooth::cuda
