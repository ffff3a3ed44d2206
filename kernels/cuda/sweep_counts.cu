// The sweep loop's per-sweep counters read back to the host, for the
// progress reports at each check and for the run's result alike.
#include <cmath>
#include <cstring>

#include "kernels/cuda/cuda_check.hpp"
#include "kernels/cuda/sweep_loop.hpp"

namespace tetsmooth::cuda {

std::vector<SweepCount> read_sweep_counts(const SweepCounters& c, int sweeps, double unit) {
  std::vector<SweepCount> counts;
  if (sweeps <= 0) return counts;
  std::vector<unsigned long long> accepted(sweeps), disp2_bits(sweeps);
  CUDA_CHECK(cudaMemcpy(accepted.data(), c.accepted, sweeps * sizeof(accepted[0]), cudaMemcpyDeviceToHost));
  CUDA_CHECK(cudaMemcpy(disp2_bits.data(), c.max_disp2_bits, sweeps * sizeof(disp2_bits[0]), cudaMemcpyDeviceToHost));
  for (int s = 0; s < sweeps; ++s) {
    double disp2;
    static_assert(sizeof disp2 == sizeof disp2_bits[0]);
    std::memcpy(&disp2, &disp2_bits[s], sizeof disp2);
    counts.push_back({static_cast<std::int64_t>(accepted[s]), std::sqrt(disp2) * unit});
  }
  return counts;
}

}  // namespace tetsmooth::cuda
