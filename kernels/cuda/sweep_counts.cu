// The sweep loop's per-sweep counters read back to the host, for the
// progress reports at each check and for the run's result alike.
#include <cmath>
#include <cstring>

#include "kernels/cuda/cuda_check.hpp"
#include "kernels/cuda/sweep_loop.hpp"

namespace tetsmooth::cuda {

std::vector<SweepCount> read_sweep_counts(const SweepCounters& c, int first, int last, double unit) {
  std::vector<SweepCount> counts;
  if (last <= first) return counts;
  const std::size_t n = static_cast<std::size_t>(last - first);
  std::vector<unsigned long long> accepted(n), disp2_bits(n);
  CUDA_CHECK(cudaMemcpy(accepted.data(), c.accepted + first, n * sizeof(accepted[0]), cudaMemcpyDeviceToHost));
  CUDA_CHECK(
      cudaMemcpy(disp2_bits.data(), c.max_disp2_bits + first, n * sizeof(disp2_bits[0]), cudaMemcpyDeviceToHost));
  for (std::size_t k = 0; k < n; ++k) {
    double disp2;
    static_assert(sizeof disp2 == sizeof disp2_bits[0]);
    std::memcpy(&disp2, &disp2_bits[k], sizeof disp2);
    counts.push_back({static_cast<std::int64_t>(accepted[k]), std::sqrt(disp2) * unit});
  }
  return counts;
}

}  // namespace tetsmooth::cuda
