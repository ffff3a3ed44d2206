// compare_warp_star_test: both forms of the adaptive test's second pass on
// one thread per node, so that they see identical inputs and must agree bit
// for bit (the warp form changes only which lane computes a tet, and when).
#include "kernels/cuda/star_test_check.hpp"

#include "kernels/coords.hpp"
#include "kernels/cuda/cuda_check.hpp"
#include "kernels/cuda/device_buffer.hpp"
#include "kernels/cuda/multiblock_kernels.cuh"
#include "kernels/cuda/warp_star_test.cuh"
#include "mesh/errors.hpp"
#include "mesh/topology.hpp"

namespace tetsmooth::cuda {
namespace {

// A mesh and its topology copied to the device, with double AoS coordinates.
struct DeviceMeshCopy {
  DeviceBuffer<index_t> tets, nbr_off, nbr, inc_off, inc;
  DeviceBuffer<double> xyz;
  DeviceMeshCopy(const TetMesh& mesh, const Topology& topo) {
    tets.upload(mesh.tets);
    nbr_off.upload(topo.neighbours.offsets);
    nbr.upload(topo.neighbours.items);
    inc_off.upload(topo.node_tets.offsets);
    inc.upload(topo.node_tets.items);
    xyz.upload(mesh.xyz);
  }
  MeshView view() const { return MeshView{tets.data(), nbr_off.data(), nbr.data(), inc_off.data(), inc.data()}; }
  AosCoords<double> coords() const { return AosCoords<double>{const_cast<double*>(xyz.data())}; }
};

// counts: judged, accepted, disagreements.
__global__ void compare_star_tests_kernel(MeshView m, AosCoords<double> xyz, const double* targets,
                                          const std::uint8_t* movable, index_t n, LeadRule rule,
                                          unsigned long long* counts) {
  const std::size_t gid = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  const index_t i = static_cast<index_t>(gid);
  const bool active = gid < static_cast<std::size_t>(n) && movable[i];
  Vec3<double> p{0, 0, 0}, target{0, 0, 0};
  double old_min = 2;
  index_t lead = 0;
  bool reference = false;
  if (active) {
    p = xyz.get(i);
    target = {targets[3 * gid], targets[3 * gid + 1], targets[3 * gid + 2]};
    old_min = star_old_min(m, xyz, i, p, 0, 1, FreshOldQuality{}, &lead);
    const index_t begin = m.inc_off[i], size = m.inc_off[i + 1] - begin;
    if (rule == LeadRule::Rotating && size > 0) lead = begin + i % size;
    reference = star_improves(m, xyz, i, p, target, old_min, 0, 1);
  }
  const bool shared = warp_star_improves(m, xyz, active ? i : 0, p, target, old_min, lead, active, FreshOldQuality{});
  if (!active) return;
  atomicAdd(&counts[0], 1ull);
  if (reference) atomicAdd(&counts[1], 1ull);
  if (reference != shared) atomicAdd(&counts[2], 1ull);
}

// One round of the deal (deal_round) for warps whose lanes have
// pseudo-random pending counts (0 to 40, so that a warp holds from one busy
// node to 32, some short of their share), against the rule written out with
// integer division: counts [0] busy nodes dealt to, [1] nodes whose number
// of slots breaks the rule, [2] nodes whose slots are not those of their
// mask, not where the rule puts them, or not in the order of their tets.
__global__ void deal_check_kernel(unsigned seed, unsigned long long* counts) {
  __shared__ unsigned char rows[32][32];
  const int lane = static_cast<int>(threadIdx.x & 31u);
  unsigned h = (seed * 0x9e3779b9u) ^ ((blockIdx.x * blockDim.x + threadIdx.x) * 0x85ebca6bu);
  h ^= h >> 15;
  h *= 0x2c1b3c6du;
  h ^= h >> 12;
  const unsigned w = __shfl_sync(kFullWarp, h, 0);           // one draw per warp:
  const int span = 1 + static_cast<int>((w >> 8) % 41);      // how many tets its nodes have at most,
  const bool idle = static_cast<int>((w >> 16) % 33) > lane;  // and how many of its lanes have none
  const int pending = idle ? 0 : static_cast<int>(h % 64) % span;
  const unsigned busy = __ballot_sync(kFullWarp, pending > 0);
  if (busy == 0) return;
  const RoundDeal d = deal_round(busy, pending, lane, rows[threadIdx.x >> 5]);
  const int nodes = __popc(busy), rank = __popc(busy & ((1u << lane) - 1u));
  const int share = 32 / nodes, extra = 32 % nodes;
  const int take = pending > 0 ? min(pending, share + (rank < extra ? 1 : 0)) : 0;
  const int first = share * rank + min(rank, extra);
  const int owner_take = __shfl_sync(kFullWarp, d.take, d.owner);
  const bool dealt = d.offset >= 0 && d.offset < owner_take;
  bool bad_slots = pending > 0 && d.mine != (take >= 32 ? kFullWarp : ((1u << take) - 1u) << first);
  for (int node = 0; node < 32; ++node) {
    const bool serves = dealt && d.owner == node;
    const int node_first = __shfl_sync(kFullWarp, first, node);
    const unsigned served = __ballot_sync(kFullWarp, serves);
    const bool misplaced = __any_sync(kFullWarp, serves && d.offset != lane - node_first) != 0;
    if (lane == node && (served != d.mine || misplaced)) bad_slots = true;
  }
  if (pending > 0) atomicAdd(&counts[0], 1ull);
  if (d.take != take) atomicAdd(&counts[1], 1ull);
  if (bad_slots) atomicAdd(&counts[2], 1ull);
}

// Each node's neighbour sum, old minimum and the minimum's entry, walked as
// sweep_kernel walks them (incidence rows in quads) and entry by entry;
// counts [0] nodes, [1] nodes where the two walks differ. Both on the
// device: the host's radius ratio rounds differently (nvcc contracts its
// products into FMAs).
__global__ void row_walk_kernel(MeshView m, AosCoords<double> xyz, index_t n, unsigned long long* counts) {
  const std::size_t gid = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (gid >= static_cast<std::size_t>(n)) return;
  const index_t i = static_cast<index_t>(gid), nb_begin = m.nbr_off[i], nb_end = m.nbr_off[i + 1];
  const Vec3<double> sum = row_sum<double, kMultiBlockChunk>(m, xyz, nb_begin, nb_end, 0, 1);
  const Vec3<double> sum1 = row_sum<double, 1>(m, xyz, nb_begin, nb_end, 0, 1);
  index_t at = 0, at1 = 0;
  const double q = star_old_min<double, kOldMinChunk>(m, xyz, i, xyz.get(i), 0, 1, FreshOldQuality{}, &at);
  const double q1 = star_old_min<double, 1>(m, xyz, i, xyz.get(i), 0, 1, FreshOldQuality{}, &at1);
  atomicAdd(&counts[0], 1ull);
  if (sum.x != sum1.x || sum.y != sum1.y || sum.z != sum1.z || q != q1 || at != at1) atomicAdd(&counts[1], 1ull);
}

template <class Real>
__global__ void radius_ratio_kernel(const double* corners, std::size_t tets, double* q) {
  const std::size_t t = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (t >= tets) return;
  Vec3<Real> v[4];
  for (int k = 0; k < 4; ++k) {
    const double* p = corners + 12 * t + 3 * k;
    v[k] = {static_cast<Real>(p[0]), static_cast<Real>(p[1]), static_cast<Real>(p[2])};
  }
  q[t] = radius_ratio(v[0], v[1], v[2], v[3]);
}

}  // namespace

StarTestAgreement compare_warp_star_test(const TetMesh& mesh, const std::vector<double>& targets, LeadRule lead) {
  if (targets.size() != 3 * mesh.num_nodes())
    throw UsageError("compare_warp_star_test: " + std::to_string(targets.size()) + " target values for " +
                     std::to_string(mesh.num_nodes()) + " nodes");
  const Topology topo = build_topology(mesh);
  const DeviceMeshCopy d(mesh, topo);
  DeviceBuffer<double> target;
  DeviceBuffer<std::uint8_t> movable;
  DeviceBuffer<unsigned long long> counts(3);
  target.upload(targets);
  movable.upload(topo.movable);
  CUDA_CHECK(cudaMemset(counts.data(), 0, counts.bytes()));
  const MeshView view = d.view();
  const index_t n = static_cast<index_t>(mesh.num_nodes());
  constexpr unsigned kBlock = 128;
  if (n > 0) {
    compare_star_tests_kernel<<<(static_cast<unsigned>(n) + kBlock - 1) / kBlock, kBlock>>>(
        view, d.coords(), target.data(), movable.data(), n, lead, counts.data());
    CUDA_CHECK_LAUNCH();
  }
  const std::vector<unsigned long long> c = counts.download();
  return {static_cast<std::size_t>(c[0]), static_cast<std::size_t>(c[1]), static_cast<std::size_t>(c[2])};
}

RowWalkCheck check_row_walks(const TetMesh& mesh) {
  const DeviceMeshCopy d(mesh, build_topology(mesh));
  DeviceBuffer<unsigned long long> counts(2);
  CUDA_CHECK(cudaMemset(counts.data(), 0, counts.bytes()));
  const std::size_t n = mesh.num_nodes();
  constexpr unsigned kBlock = 128;
  if (n > 0) {
    row_walk_kernel<<<static_cast<unsigned>((n + kBlock - 1) / kBlock), kBlock>>>(d.view(), d.coords(),
                                                                                  static_cast<index_t>(n), counts.data());
    CUDA_CHECK_LAUNCH();
  }
  const std::vector<unsigned long long> c = counts.download();
  return {static_cast<std::size_t>(c[0]), static_cast<std::size_t>(c[1])};
}

std::vector<double> device_radius_ratios(const std::vector<double>& corners, Precision precision) {
  if (corners.size() % 12 != 0)
    throw UsageError("device_radius_ratios: " + std::to_string(corners.size()) + " corner values, not 12 a tet");
  const std::size_t tets = corners.size() / 12;
  if (tets == 0) return {};
  DeviceBuffer<double> d_corners, q(tets);
  d_corners.upload(corners);
  constexpr unsigned kBlock = 128;
  const unsigned blocks = static_cast<unsigned>((tets + kBlock - 1) / kBlock);
  if (precision == Precision::Float)
    radius_ratio_kernel<float><<<blocks, kBlock>>>(d_corners.data(), tets, q.data());
  else
    radius_ratio_kernel<double><<<blocks, kBlock>>>(d_corners.data(), tets, q.data());
  CUDA_CHECK_LAUNCH();
  return q.download();
}

DealCheck check_deal() {
  constexpr unsigned kSeeds = 8, kBlocks = 256, kBlock = 256;
  DeviceBuffer<unsigned long long> counts(3);
  CUDA_CHECK(cudaMemset(counts.data(), 0, counts.bytes()));
  for (unsigned seed = 0; seed < kSeeds; ++seed) {
    deal_check_kernel<<<kBlocks, kBlock>>>(seed, counts.data());
    CUDA_CHECK_LAUNCH();
  }
  const std::vector<unsigned long long> c = counts.download();
  return {static_cast<std::size_t>(c[0]), static_cast<std::size_t>(c[1] + c[2])};
}

}  // namespace tetsmooth::cuda
