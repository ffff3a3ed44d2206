// Jones-Plassmann colouring on the GPU, round for round the CPU's
// colour_nodes() (mesh/colouring.cpp): same priorities, same first-fit rule,
// so the same colours and the same number of rounds.
//
// All rounds run in one cooperative launch, a grid barrier between rounds,
// kColourLanes threads per node. A node's state is round_of[i]:
// 0 for nodes that never move, r >= 1 for the round that coloured it,
// kUncoloured while it waits. Round r only treats a neighbour j as coloured
// when round_of[j] < r, so it sees exactly the colours of earlier rounds:
//  * the only writes of round r are colour[i] and round_of[i] of its
//    winners;
//  * a neighbour reading round_of[i] of such a winner gets kUncoloured or r,
//    both >= r, so it decides the same either way (and it loses to i, which
//    beats all its uncoloured neighbours);
//  * colour[j] is only read when round_of[j] < r, i.e. written before an
//    earlier barrier, never in this round;
//  * two winners are never neighbours: colours_before is a strict order.
//
// The device stops after the first round that leaves no node waiting; the
// host reads the numbers of rounds and colours back once.
//
// Classes: the colours (non-movable nodes as the sentinel num_colours) are
// radix sorted with the node indices as values; the sort is stable, so each
// class lists its nodes ascending, and only the bits of num_colours are sorted.
#include <cooperative_groups.h>
#include <cub/device/device_radix_sort.cuh>

#include <algorithm>

#include <string>

#include "kernels/cuda/cuda_check.hpp"
#include "kernels/cuda/device_topology.hpp"
#include "kernels/cuda/device_topology_detail.cuh"
#include "kernels/cuda/lane_groups.cuh"
#include "kernels/cuda/resident_blocks.cuh"
#include "mesh/colouring.hpp"
#include "mesh/errors.hpp"

namespace tetsmooth::cuda {
namespace {

using detail::blocks_for;
using detail::kBlock;

constexpr unsigned kUncoloured = 0xffffffffu;

// Written by the device, read back once. Round r counts its waiting nodes
// into waiting[r % 3]: a slot is cleared two rounds after it was read.
struct RoundCounts {
  unsigned waiting[3];
  int max_colour;
  unsigned rounds;  // rounds taken; 0 if the loop gave up
};

__global__ void init_rounds(std::size_t n, const std::uint8_t* movable, unsigned* round_of) {
  const std::size_t i = blockIdx.x * static_cast<std::size_t>(blockDim.x) + threadIdx.x;
  if (i < n) round_of[i] = movable[i] ? kUncoloured : 0u;
}

// Threads per node in a round, and neighbours each lane reads at once: a
// lane loads kColourChunk neighbour indices, then all their rounds, then all
// their colours, so a node's ~14 neighbours cost three dependent loads, not
// three per neighbour. Four lanes: ~440k threads for the 109k model, near the
// ~270k an H100 holds at once.
constexpr int kColourLanes = 4;
constexpr int kColourChunk = 4;

// The smallest colour none of the earlier-coloured neighbours has, looked
// for 64 colours at a time, on one thread (the rare case of 64+ colours).
__device__ int first_free_colour(const index_t* nbr, index_t b, index_t e, const unsigned* round_of,
                                 const int* colour, unsigned r, int from) {
  for (int base = from;; base += 64) {
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

// Round r for node i on the G lanes of its group (mask: those lanes).
// Returns whether i must wait for a later round. When i takes a colour now,
// lane 0 raises `picked` to it: a group may colour several nodes in a round,
// and the largest colour of all of them must reach the colour count.
__device__ bool colour_node(std::size_t i, const index_t* nbr_off, const index_t* nbr, unsigned r,
                            unsigned* round_of, int* colour, int lane, unsigned mask, int& picked) {
  constexpr int G = kColourLanes;
  const bool candidate = round_of[i] == kUncoloured;
  if (!candidate) return false;  // the whole group leaves together
  const index_t b = nbr_off[i], e = nbr_off[i + 1];
  bool beaten = false;
  unsigned long long used = 0;  // colours 0..63 of neighbours coloured in earlier rounds
  for (index_t first = b + lane; first < e; first += G * kColourChunk) {
    index_t j[kColourChunk];
    unsigned rj[kColourChunk];
    int cj[kColourChunk];
#pragma unroll
    for (int u = 0; u < kColourChunk; ++u) j[u] = first + u * G < e ? nbr[first + u * G] : -1;
#pragma unroll
    for (int u = 0; u < kColourChunk; ++u) rj[u] = j[u] >= 0 ? round_of[j[u]] : 0u;
#pragma unroll
    for (int u = 0; u < kColourChunk; ++u) cj[u] = j[u] >= 0 && rj[u] < r ? colour[j[u]] : -1;  // -1: never moves
#pragma unroll
    for (int u = 0; u < kColourChunk; ++u) {
      if (j[u] < 0) continue;
      if (rj[u] >= r)
        beaten = beaten || colours_before(static_cast<std::uint32_t>(j[u]), static_cast<std::uint32_t>(i));
      else if (cj[u] >= 0 && cj[u] < 64)
        used |= 1ull << cj[u];
    }
  }
  beaten = group_or<G>(static_cast<unsigned>(beaten), mask) != 0;
  used = group_or<G>(used, mask);
  if (beaten) return true;
  if (lane == 0) {
    const int c = ~used != 0 ? __ffsll(static_cast<long long>(~used)) - 1
                             : first_free_colour(nbr, b, e, round_of, colour, r, 64);
    colour[i] = c;
    round_of[i] = r;
    picked = max(picked, c);
  }
  return false;
}

// Every round in one cooperative launch, a grid barrier between rounds;
// stops after the first round that leaves no node waiting. Groups of G
// lanes take the nodes in a grid-stride loop. Eight blocks of 256 fill a
// multiprocessor (the bound keeps the kernel within 32 registers).
__global__ void __launch_bounds__(kBlock, 8) colour_rounds_kernel(std::size_t n, const index_t* nbr_off,
                                                               const index_t* nbr, unsigned* round_of, int* colour,
                                                               RoundCounts* counts, unsigned max_rounds) {
  namespace cg = cooperative_groups;
  constexpr int G = kColourLanes;
  cg::grid_group grid = cg::this_grid();
  const unsigned long long tid = grid.thread_rank(), groups = grid.size() / G;
  const int lane = static_cast<int>(tid % G);
  const unsigned mask = group_mask<G>();
  for (unsigned r = 1; r <= max_rounds; ++r) {
    unsigned waiting = 0;
    int picked = -1;
    for (unsigned long long i = tid / G; i < n; i += groups)
      waiting += colour_node(i, nbr_off, nbr, r, round_of, colour, lane, mask, picked) && lane == 0;
    __syncwarp();
    warp_atomic_add(&counts->waiting[r % 3], waiting);
    const int warp_max = __reduce_max_sync(0xffffffffu, picked);
    if ((threadIdx.x & 31) == 0 && warp_max >= 0) atomicMax(&counts->max_colour, warp_max);
    if (tid == 0) counts->waiting[(r + 1) % 3] = 0;
    grid.sync();
    if (__ldcg(&counts->waiting[r % 3]) == 0) {
      if (tid == 0) counts->rounds = r;
      return;
    }
  }
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

void run_rounds(DeviceTopology& topo, cudaStream_t stream, unsigned max_blocks) {
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
  CUDA_CHECK(cudaMemsetAsync(counts, 0, sizeof(RoundCounts), stream));
  CUDA_CHECK(cudaMemsetAsync(&counts->max_colour, 0xff, sizeof(int), stream));
  // As many blocks as can be resident at once (the grid barrier needs that),
  // or fewer when asked.
  unsigned blocks = std::min(blocks_for(n * kColourLanes), resident_blocks(colour_rounds_kernel, kBlock));
  if (max_blocks > 0) blocks = std::min(blocks, max_blocks);
  blocks = std::max(blocks, 1u);
  const index_t* nbr_off = topo.nbr_off.data();
  const index_t* nbr = topo.nbr.data();
  int* colour = topo.colour.data();
  // Every round colours at least the waiting node of highest priority.
  auto max_rounds = static_cast<unsigned>(topo.movable_count);
  void* params[] = {const_cast<std::size_t*>(&n), &nbr_off, &nbr, &round_of, &colour, &counts, &max_rounds};
  CUDA_CHECK(cudaLaunchCooperativeKernel(reinterpret_cast<const void*>(colour_rounds_kernel), dim3(blocks),
                                         dim3(kBlock), params, 0, stream));
  RoundCounts host{};
  CUDA_CHECK(cudaMemcpyAsync(&host, counts, sizeof(RoundCounts), cudaMemcpyDeviceToHost, stream));
  CUDA_CHECK(cudaStreamSynchronize(stream));
  if (host.rounds > 0) {
    topo.colour_rounds = static_cast<int>(host.rounds);
    topo.num_colours = host.max_colour + 1;
    return;
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

void colour_device(DeviceTopology& topo, cudaStream_t stream, unsigned max_blocks) {
  topo.colour.resize(topo.num_nodes);
  if (topo.num_nodes > 0) CUDA_CHECK(cudaMemsetAsync(topo.colour.data(), 0xff, topo.colour.bytes(), stream));
  topo.num_colours = 0;
  topo.colour_rounds = 0;
  if (topo.movable_count > 0) run_rounds(topo, stream, max_blocks);
  build_classes(topo, stream);
}

}  // namespace tetsmooth::cuda
