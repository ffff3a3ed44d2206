#pragma once
// Template bodies of sweep_loop.hpp, instantiated once per precision in
// sweep_loop_float.cu and sweep_loop_double.cu (splitting keeps nvcc's
// translation units small).
#include <algorithm>

#include "kernels/cuda/coloured_loop_launch.cuh"
#include "kernels/cuda/coords_transfer_kernels.cuh"
#include "kernels/cuda/cuda_check.hpp"
#include "kernels/cuda/form_a_repair_kernels.cuh"
#include "kernels/cuda/min_mean_quality_kernel.cuh"
#include "kernels/cuda/multiblock_kernels.cuh"
#include "kernels/cuda/phase_timer.hpp"
#include "kernels/cuda/single_block_kernel.cuh"
#include "kernels/cuda/stopping_rule_kernels.cuh"
#include "kernels/cuda/tet_quality_pass.cuh"
#include "kernels/cuda/sweep_loop.hpp"
#include "kernels/sweep_log.hpp"
#include "mesh/errors.hpp"

namespace tetsmooth::cuda {
namespace detail {

constexpr int kBlock = 256;
// In 64 bits: count + kBlock - 1 wraps in index_t for counts near 2^31.
inline unsigned blocks_for(std::size_t count) { return static_cast<unsigned>((count + kBlock - 1) / kBlock); }
template <class Real, Layout L>
struct CoordsFor;
template <class Real>
struct CoordsFor<Real, Layout::AoS> {
  using type = AosCoords<Real>;
  static type make(void* p, index_t) { return {static_cast<Real*>(p)}; }
};
template <class Real>
struct CoordsFor<Real, Layout::SoA> {
  using type = SoaCoords<Real>;
  static type make(void* p, index_t n) {
    Real* r = static_cast<Real*>(p);
    return {r, r + n, r + 2 * static_cast<std::size_t>(n)};
  }
};

template <class Real, Layout L, bool kAdaptive, Form F>
class SweepLauncher {
  using Make = CoordsFor<Real, L>;
  using Coords = typename Make::type;

 public:
  SweepLauncher(const SweepLoopArgs& a, const SmoothOptions& o)
      : a_(a),
        o_(o),
        c0_(Make::make(a.buf0, a.n)),
        c1_(Make::make(F == Form::A ? a.buf1 : a.buf0, a.n)),
        phases_(a.stream, o.time_phases) {}  // only the MultiBlock loop records

  SweepLoopStats run() {
    if (o_.max_iterations == 0) return stats_;
    if (o_.strategy == Strategy::SingleBlock) {
      single_block_kernel<Real, kAdaptive, F><<<1, kSingleBlockThreads, 0, a_.stream>>>(
          a_.view, c0_, c1_, a_.n, a_.num_tets, a_.movable, old_min(), a_.moved, a_.revert, a_.state, a_.counters,
          o_.max_iterations);
      CUDA_CHECK_LAUNCH();
      ++stats_.launches;
      return finish_on_device();
    }
    if (o_.strategy == Strategy::Coloured) {
      stats_.lanes_per_node = launch_coloured_loop<Real, kAdaptive>(a_, o_, c0_);
      ++stats_.launches;
      return finish_on_device();
    }
    for (int s = 0; s < o_.max_iterations;) {
      const int chunk = std::min(o_.check_every, o_.max_iterations - s);
      phases_.begin();
      for (int k = 0; k < chunk; ++k, ++s) launch_sweep(s);
      CUDA_CHECK(cudaMemcpyAsync(a_.host_state, a_.state, sizeof(SweepState), cudaMemcpyDeviceToHost, a_.stream));
      CUDA_CHECK(cudaStreamSynchronize(a_.stream));
      phases_.collect();
      ++stats_.host_checks;
      if (o_.progress) report_progress();
      if (a_.host_state->done) break;
    }
    stats_.phase_ms = phases_.totals();
    return stats_;
  }

 private:
  Real* old_min() const { return static_cast<Real*>(a_.old_min); }

  // The buffer that holds the positions after `sweeps` sweeps.
  const Coords& latest(int sweeps) const { return latest_in_buf1(F, sweeps) ? c1_ : c0_; }

  void launch_sweep(int s) {
    const Coords& read = latest(s);
    const Coords& write = latest(s + 1);  // the same buffer in Form B
    Real* tet_q = static_cast<Real*>(a_.tet_quality);
    if (kAdaptive) {
      tet_quality_kernel<<<blocks_for((a_.num_tets + kTetsPerThread - 1) / kTetsPerThread), kBlock, 0, a_.stream>>>(
          a_.view.tets, a_.num_tets, read, tet_q, a_.state);
      launched("tet_quality_kernel");
      phases_.end_of("tet_quality");
    }
    sweep_kernel<Real, kAdaptive, F><<<blocks_for(a_.n), kBlock, 0, a_.stream>>>(
        a_.view, read, write, a_.n, a_.movable, tet_q, old_min(), a_.moved, a_.state, a_.counters);
    launched("sweep_kernel");
    phases_.end_of("node_update");
    stats_.lanes_per_node = 1;
    if (F == Form::A) {
      for (int pass = 0; kAdaptive && pass < kMaxRepairPasses; ++pass) {
        repair_check_kernel<<<blocks_for(a_.num_tets), kBlock, 0, a_.stream>>>(
            a_.view.tets, a_.num_tets, read, write, a_.moved, old_min(), a_.revert, a_.state, a_.counters, pass);
        launched("repair_check_kernel");
        repair_apply_kernel<<<blocks_for(a_.n), kBlock, 0, a_.stream>>>(a_.n, read, write, a_.moved, a_.revert,
                                                                         a_.state, a_.counters, pass);
        launched("repair_apply_kernel");
      }
      count_moves_kernel<<<blocks_for(a_.n), kBlock, 0, a_.stream>>>(a_.n, read, write, a_.moved, a_.state,
                                                                      a_.counters);
      launched("count_moves_kernel");
      phases_.end_of("repair");
    }
    verdict_kernel<<<1, 1, 0, a_.stream>>>(a_.state, a_.counters, o_.max_iterations);
    launched("verdict_kernel");
    phases_.end_of("stopping_rule");
  }

  // After a loop that ran entirely on the device: the host waits only when
  // it has progress to report (the caller reads the final state anyway).
  SweepLoopStats finish_on_device() {
    if (!o_.progress) return stats_;
    CUDA_CHECK(cudaMemcpyAsync(a_.host_state, a_.state, sizeof(SweepState), cudaMemcpyDeviceToHost, a_.stream));
    CUDA_CHECK(cudaStreamSynchronize(a_.stream));
    ++stats_.host_checks;
    report_progress();
    return stats_;
  }

  // Checks the launch just made, naming its kernel: every launch of the
  // loop passes through here, so the line alone would not tell them apart.
  void launched(const char* kernel) {
    const cudaError_t err = cudaGetLastError();
    if (err != cudaSuccess) throw_cuda_error(err, kernel, __FILE__, __LINE__);
    ++stats_.launches;
  }

  // Reports the sweeps finished since the last check (host_state is fresh).
  void report_progress() {
    const int done = a_.host_state->sweep;
    if (done <= reported_) return;
    const std::vector<SweepCount> counts = read_sweep_counts(a_.counters, reported_, done, a_.unit);
    for (int s = reported_; s < done; ++s) {
      const SweepCount& c = counts[static_cast<std::size_t>(s - reported_)];
      SweepProgress p{s + 1, c.accepted, c.max_displacement, {}};
      // Only the last sweep's positions are still in the buffers.
      if (s + 1 == done) p.quality = [this, done] { return quality_after(done); };
      o_.progress(p);
    }
    reported_ = done;
  }

  // The smallest and mean radius ratio after `sweeps` sweeps, with nothing
  // queued behind them.
  MinMeanQuality quality_after(int sweeps) {
    CUDA_CHECK(cudaMemsetAsync(&a_.state->quality_sum, 0, sizeof(double), a_.stream));
    CUDA_CHECK(cudaMemsetAsync(&a_.state->quality_min_key, 0xff, sizeof(unsigned long long), a_.stream));
    const unsigned blocks = std::max(1u, std::min(blocks_for(a_.num_tets), kQualityMaxBlocks));
    min_mean_quality_kernel<Real>
        <<<blocks, kBlock, 0, a_.stream>>>(a_.view.tets, a_.num_tets, latest(sweeps), a_.state);
    launched("min_mean_quality_kernel");
    CUDA_CHECK(cudaMemcpyAsync(a_.host_state, a_.state, sizeof(SweepState), cudaMemcpyDeviceToHost, a_.stream));
    CUDA_CHECK(cudaStreamSynchronize(a_.stream));
    MinMeanQuality q;
    if (a_.num_tets == 0) return q;
    q.min = from_ordered_key(a_.host_state->quality_min_key);
    q.mean = a_.host_state->quality_sum / static_cast<double>(a_.num_tets);
    return q;
  }

  const SweepLoopArgs& a_;
  const SmoothOptions& o_;
  Coords c0_, c1_;
  SweepLoopStats stats_;
  PhaseTimer phases_;
  int reported_ = 0;
};

template <class Real, Layout L, bool kAdaptive>
SweepLoopStats run_form(const SweepLoopArgs& a, const SmoothOptions& o) {
  return o.form == Form::A ? SweepLauncher<Real, L, kAdaptive, Form::A>(a, o).run()
                           : SweepLauncher<Real, L, kAdaptive, Form::B>(a, o).run();
}

template <class Real, Layout L>
SweepLoopStats run_method(const SweepLoopArgs& a, const SmoothOptions& o) {
  return o.method == Method::Adaptive ? run_form<Real, L, true>(a, o) : run_form<Real, L, false>(a, o);
}

template <class Real, class Fn>
void with_layout(Layout layout, void* buf, index_t n, Fn&& fn) {
  if (layout == Layout::AoS)
    fn(CoordsFor<Real, Layout::AoS>::make(buf, n));
  else
    fn(CoordsFor<Real, Layout::SoA>::make(buf, n));
}

}  // namespace detail

template <class Real>
SweepLoopStats run_sweep_loop(const SweepLoopArgs& a, const SmoothOptions& o) {
  check_gpu_strategy(o);
  return o.layout == Layout::AoS ? detail::run_method<Real, Layout::AoS>(a, o)
                                 : detail::run_method<Real, Layout::SoA>(a, o);
}

template <class Real>
void load_working_coords(const double* input, void* buf, index_t n, Layout layout, const double centre[3],
                         double scale, cudaStream_t stream) {
  detail::with_layout<Real>(layout, buf, n, [&](auto coords) {
    load_coords_kernel<Real><<<detail::blocks_for(n), detail::kBlock, 0, stream>>>(input, coords, n,
                                                                                   working_frame(centre, scale));
    CUDA_CHECK_LAUNCH();
  });
}

template <class Real>
void store_movable_coords(const void* buf, const double* input, double* out, const std::uint8_t* movable, index_t n,
                          Layout layout, const double centre[3], double scale, cudaStream_t stream) {
  detail::with_layout<Real>(layout, const_cast<void*>(buf), n, [&](auto coords) {
    store_coords_kernel<Real><<<detail::blocks_for(n), detail::kBlock, 0, stream>>>(coords, input, out, movable, n,
                                                                                    working_frame(centre, scale));
    CUDA_CHECK_LAUNCH();
  });
}

template <class Real>
void count_moved_fixed(const void* working, const double* input, const std::uint8_t* movable, index_t n, Layout layout,
                       const double centre[3], double scale, unsigned long long* count, cudaStream_t stream) {
  detail::with_layout<Real>(layout, const_cast<void*>(working), n, [&](auto coords) {
    count_moved_fixed_kernel<Real><<<detail::blocks_for(n), detail::kBlock, 0, stream>>>(
        coords, input, movable, n, working_frame(centre, scale), count);
    CUDA_CHECK_LAUNCH();
  });
}

template <class Real>
void sum_edge_lengths(const MeshView& view, const void* buf, index_t n, Layout layout, SweepState* state,
                      cudaStream_t stream) {
  detail::with_layout<Real>(layout, const_cast<void*>(buf), n, [&](auto coords) {
    const unsigned blocks =
        std::max(1u, std::min(detail::blocks_for(static_cast<std::size_t>(n) * kEdgeLanes), kEdgeMaxBlocks));
    edge_length_kernel<Real><<<blocks, detail::kBlock, 0, stream>>>(view, coords, n, state);
    CUDA_CHECK_LAUNCH();
  });
}

#define TETSMOOTH_INSTANTIATE_SWEEP_LOOP(Real)                                                                     \
  template SweepLoopStats run_sweep_loop<Real>(const SweepLoopArgs&, const SmoothOptions&);                       \
  template void load_working_coords<Real>(const double*, void*, index_t, Layout, const double*, double,           \
                                          cudaStream_t);                                                           \
  template void store_movable_coords<Real>(const void*, const double*, double*, const std::uint8_t*, index_t,      \
                                           Layout, const double*, double, cudaStream_t);                           \
  template void count_moved_fixed<Real>(const void*, const double*, const std::uint8_t*, index_t, Layout,          \
                                        const double*, double, unsigned long long*, cudaStream_t);                 \
  template void sum_edge_lengths<Real>(const MeshView&, const void*, index_t, Layout, SweepState*, cudaStream_t);

}  // namespace tetsmooth::cuda
