// The GPU pipeline: device memory for one mesh, and a run = topology +
// colouring + sweeps, each phase bracketed by CUDA events.
#include "kernels/cuda/gpu_pipeline.hpp"

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "kernels/sweep_log.hpp"
#include "kernels/cuda/cuda_check.hpp"
#include "kernels/cuda/cuda_event.hpp"
#include "kernels/cuda/device_topology.hpp"
#include "kernels/cuda/stopping_rule_kernels.cuh"
#include "kernels/cuda/sweep_loop.hpp"
#include "mesh/bounding_box.hpp"

namespace tetsmooth::cuda {

struct GpuPipeline::Impl {
  std::size_t n = 0, t = 0;
  cudaStream_t stream{};
  DeviceBuffer<index_t> tets;
  DeviceBuffer<std::uint8_t> fixed;
  DeviceBuffer<double> input;           // 3n, AoS, mesh units
  DeviceBuffer<double> buf0, buf1;      // working coordinates (3n Real)
  DeviceBuffer<double> old_min;         // n Real
  // Allocated by the first run that needs them: tet qualities for MultiBlock
  // and Coloured (8 B per tet, 0.5 GB for the 60M-tet lattice), the changed
  // flags for Coloured (1 B per node).
  DeviceBuffer<double> tet_quality;     // t Real
  DeviceBuffer<std::uint8_t> changed;   // n
  DeviceBuffer<std::uint8_t> moved, revert;
  DeviceBuffer<SweepState> state;
  DeviceBuffer<unsigned long long> accepted, max_disp2;
  DeviceBuffer<int> repair_found;
  DeviceBuffer<unsigned long long> colour_ns;  // Coloured: per colour, see SweepCounters
  DeviceBuffer<double> output;          // 3n, for download
  SweepState* host_state = nullptr;     // pinned
  DeviceTopology topo;
  std::vector<index_t> override_off;
  DeviceBuffer<index_t> override_off_dev, override_nodes;
  // What restore_coordinates loaded, and where the result of the last run is.
  Precision precision = Precision::Double;
  Layout layout = Layout::AoS;
  bool loaded = false;  // buf0 and buf1 hold coordinates: until then they are uninitialised
  double centre[3] = {0, 0, 0};
  double scale = 1;
  bool result_in_buf1 = false;
  GpuRunTimes times;

  // The working frame of the last restore_coordinates (sweep_loop.hpp).
  const double* frame_centre() const;
  double frame_scale() const;

  ~Impl() {
    if (host_state) CUDA_CHECK_NOTHROW(cudaFreeHost(host_state));
    if (stream) CUDA_CHECK_NOTHROW(cudaStreamDestroy(stream));
  }
};

DeviceInfo device_info() {
  int count = 0;
  CUDA_CHECK(cudaGetDeviceCount(&count));
  if (count == 0) throw DeviceError("no CUDA device found");
  int dev = 0;
  CUDA_CHECK(cudaGetDevice(&dev));
  cudaDeviceProp p{};
  CUDA_CHECK(cudaGetDeviceProperties(&p, dev));
  DeviceInfo info;
  info.name = p.name;
  info.sm_count = p.multiProcessorCount;
  info.cc_major = p.major;
  info.cc_minor = p.minor;
  info.memory_bytes = p.totalGlobalMem;
  CUDA_CHECK(cudaRuntimeGetVersion(&info.runtime_version));
  CUDA_CHECK(cudaDriverGetVersion(&info.driver_version));
  return info;
}

GpuPipeline::GpuPipeline(const TetMesh& mesh) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.n = mesh.num_nodes();
  m.t = mesh.num_tets();
  CUDA_CHECK(cudaStreamCreateWithFlags(&m.stream, cudaStreamNonBlocking));
  CUDA_CHECK(cudaMallocHost(reinterpret_cast<void**>(&m.host_state), sizeof(SweepState)));
  m.tets.upload(mesh.tets, m.stream);
  if (!mesh.fixed.empty()) m.fixed.upload(mesh.fixed, m.stream);
  m.input.upload(mesh.xyz, m.stream);
  m.buf0.resize(3 * m.n);
  m.buf1.resize(3 * m.n);
  m.old_min.resize(m.n);
  m.moved.resize(m.n);
  m.revert.resize(m.n);
  m.output.resize(3 * m.n);
  m.state.resize(1);
  m.repair_found.resize(kMaxRepairPasses);
  // Centre and half-extent of the tets' box: float runs work in [-1, 1].
  const BoundingBox box = tet_corners_bounding_box(mesh);
  for (int k = 0; k < 3; ++k) m.centre[k] = box.centre(k);
  const double half = 0.5 * box.largest_side();
  m.scale = half > 0 ? half : 1.0;
  CUDA_CHECK(cudaStreamSynchronize(m.stream));
}

GpuPipeline::~GpuPipeline() = default;

std::size_t GpuPipeline::num_nodes() const { return impl_->n; }
std::size_t GpuPipeline::num_tets() const { return impl_->t; }
const GpuRunTimes& GpuPipeline::last_times() const { return impl_->times; }

// Double works in mesh units, so it does the CPU's arithmetic; float works
// in the unit box around the mesh, where its precision is best.
const double* GpuPipeline::Impl::frame_centre() const {
  static const double origin[3] = {0, 0, 0};
  return precision == Precision::Float ? centre : origin;
}
double GpuPipeline::Impl::frame_scale() const { return precision == Precision::Float ? scale : 1.0; }

void GpuPipeline::restore_coordinates(const SmoothOptions& o) {
  Impl& m = *impl_;
  m.precision = o.precision;
  m.layout = o.layout;
  const index_t n = static_cast<index_t>(m.n);
  for (DeviceBuffer<double>* b : {&m.buf0, &m.buf1}) {
    if (o.precision == Precision::Float)
      load_working_coords<float>(m.input.data(), b->data(), n, o.layout, m.frame_centre(), m.frame_scale(), m.stream);
    else
      load_working_coords<double>(m.input.data(), b->data(), n, o.layout, m.frame_centre(), m.frame_scale(), m.stream);
  }
  m.result_in_buf1 = false;
  CUDA_CHECK(cudaStreamSynchronize(m.stream));
  m.loaded = true;
}

SmoothResult GpuPipeline::run(const SmoothOptions& o, const Colouring* colouring) {
  check_smooth_options(o);
  check_gpu_sweeps(o);
  Impl& m = *impl_;
  if (!m.loaded) throw UsageError("GpuPipeline::run: restore_coordinates() has not been called");
  if (o.precision != m.precision || o.layout != m.layout)
    throw UsageError("GpuPipeline::run: restore_coordinates() was called for another precision or layout");
  check_gpu_strategy(o);
  const index_t n = static_cast<index_t>(m.n);
  const bool is_float = o.precision == Precision::Float;
  const std::size_t cap = static_cast<std::size_t>(std::max(o.max_iterations, 1));
  m.accepted.resize(cap);
  m.max_disp2.resize(cap);

  // Form A continues from whichever buffer holds the latest coordinates.
  if (m.result_in_buf1) {
    CUDA_CHECK(cudaMemcpyAsync(m.buf0.data(), m.buf1.data(), m.buf0.bytes(), cudaMemcpyDeviceToDevice, m.stream));
    m.result_in_buf1 = false;
  }
  if (o.form == Form::A)
    CUDA_CHECK(cudaMemcpyAsync(m.buf1.data(), m.buf0.data(), m.buf0.bytes(), cudaMemcpyDeviceToDevice, m.stream));

  Event e_start, e_topo, e_colour, e_end;
  e_start.record(m.stream);
  build_device_topology(m.topo, m.tets.data(), m.t, m.n, m.fixed.size() ? m.fixed.data() : nullptr, m.stream,
                        o.strategy == Strategy::Coloured && !colouring);
  const MeshView view = m.topo.view(m.tets.data());
  CUDA_CHECK(cudaMemsetAsync(m.state.data(), 0, sizeof(SweepState), m.stream));
  CUDA_CHECK(cudaMemsetAsync(m.accepted.data(), 0, m.accepted.bytes(), m.stream));
  CUDA_CHECK(cudaMemsetAsync(m.max_disp2.data(), 0, m.max_disp2.bytes(), m.stream));
  CUDA_CHECK(cudaMemsetAsync(m.repair_found.data(), 0, m.repair_found.bytes(), m.stream));
  CUDA_CHECK(cudaMemsetAsync(m.moved.data(), 0, m.moved.bytes(), m.stream));
  CUDA_CHECK(cudaMemsetAsync(m.revert.data(), 0, m.revert.bytes(), m.stream));
  // The tolerance (a multiple of the mean edge length) on the topology's side
  // stream, beside the colouring; the sweeps wait for it.
  const cudaStream_t side = m.topo.side.begin(m.stream);
  if (is_float)
    sum_edge_lengths<float>(view, m.buf0.data(), n, o.layout, m.state.data(), side);
  else
    sum_edge_lengths<double>(view, m.buf0.data(), n, o.layout, m.state.data(), side);
  set_tolerance_kernel<<<1, 1, 0, side>>>(m.state.data(), o.tolerance);
  CUDA_CHECK_LAUNCH();
  m.topo.side.end();
  e_topo.record(m.stream);

  const std::vector<index_t>* class_off = nullptr;  // host copy
  const index_t* class_off_dev = nullptr;
  const index_t* class_nodes = nullptr;
  int num_colours = 0;
  if (o.strategy == Strategy::Coloured) {
    if (colouring) {
      m.override_off = colouring->classes.offsets;
      m.override_nodes.upload(colouring->classes.items, m.stream);
      m.override_off_dev.upload(m.override_off, m.stream);
      class_off = &m.override_off;
      class_off_dev = m.override_off_dev.data();
      class_nodes = m.override_nodes.data();
      num_colours = colouring->num_colours;
    } else {
      colour_device(m.topo, m.stream);
      class_off = &m.topo.class_off_host;
      class_off_dev = m.topo.class_off.data();
      class_nodes = m.topo.class_nodes.data();
      num_colours = m.topo.num_colours;
    }
  }
  e_colour.record(m.stream);
  m.topo.side.await(m.stream);

  SweepLoopArgs a;
  a.view = view;
  a.n = n;
  a.num_tets = static_cast<index_t>(m.t);
  a.movable = m.topo.movable.data();
  a.buf0 = m.buf0.data();
  a.buf1 = m.buf1.data();
  a.old_min = m.old_min.data();
  a.moved = m.moved.data();
  a.revert = m.revert.data();
  a.state = m.state.data();
  a.host_state = m.host_state;
  a.counters = SweepCounters{m.accepted.data(), m.max_disp2.data(), m.repair_found.data(), nullptr};
  a.class_nodes = class_nodes;
  a.class_off = class_off_dev;
  a.num_colours = class_off ? static_cast<int>(class_off->size()) - 1 : 0;
  std::vector<std::int64_t> class_sizes;
  for (int c = 0; c < a.num_colours; ++c) {
    class_sizes.push_back((*class_off)[c + 1] - (*class_off)[c]);
    a.largest_class = std::max<index_t>(a.largest_class, static_cast<index_t>(class_sizes.back()));
  }
  if (o.method == Method::Adaptive && o.strategy != Strategy::SingleBlock) {
    m.tet_quality.resize(m.t);
    a.tet_quality = m.tet_quality.data();
  }
  if (o.strategy == Strategy::Coloured) {
    m.changed.resize(m.n);
    a.changed = m.changed.data();
    m.colour_ns.resize(static_cast<std::size_t>(std::max(a.num_colours, 1)));
    CUDA_CHECK(cudaMemsetAsync(m.colour_ns.data(), 0, m.colour_ns.bytes(), m.stream));
    a.counters.colour_ns = m.colour_ns.data();
  }
  a.stream = m.stream;
  a.unit = is_float ? m.scale : 1.0;
  SweepLoopStats loop;
  try {
    loop = is_float ? run_sweep_loop<float>(a, o) : run_sweep_loop<double>(a, o);
  } catch (...) {
    // Stopped part way (a progress callback that cancels, say): the sweeps
    // made stand, so download_xyz and a later run() must take the buffer
    // that holds their result. At best effort: a device in error leaves the
    // flag as it was, and the first error is the one passed on.
    if (cudaMemcpyAsync(m.host_state, m.state.data(), sizeof(SweepState), cudaMemcpyDeviceToHost, m.stream) ==
            cudaSuccess &&
        cudaStreamSynchronize(m.stream) == cudaSuccess)
      m.result_in_buf1 = latest_in_buf1(o.form, m.host_state->sweep);
    throw;
  }
  e_end.record(m.stream);
  CUDA_CHECK(cudaMemcpyAsync(m.host_state, m.state.data(), sizeof(SweepState), cudaMemcpyDeviceToHost, m.stream));
  CUDA_CHECK(cudaStreamSynchronize(m.stream));

  m.times.topology_ms = e_topo.ms_since(e_start);
  m.times.colouring_ms = e_colour.ms_since(e_topo);
  m.times.smoothing_ms = e_end.ms_since(e_colour);
  m.times.total_ms = e_end.ms_since(e_start);
  m.times.launches = loop.launches;
  m.times.host_checks = loop.host_checks;
  m.times.lanes_per_node = loop.lanes_per_node;

  const SweepState st = *m.host_state;
  SmoothResult r;
  r.backend = "cuda";
  r.sweeps = st.sweep;
  r.stop = o.max_iterations == 0 ? StopReason::MaxIterations : to_stop_reason(static_cast<SweepVerdict>(st.verdict));
  r.reverted_moves = static_cast<std::int64_t>(st.reverted);
  // Only the coloured loop skips nodes; the other strategies evaluate every
  // movable node in every sweep.
  r.evaluations = o.strategy == Strategy::Coloured
                      ? static_cast<std::int64_t>(st.evaluated)
                      : static_cast<std::int64_t>(m.topo.movable_count) * st.sweep;
  r.num_colours = num_colours;
  r.movable_nodes = m.topo.movable_count;
  r.mean_edge_length = (st.edge_count ? st.edge_sum / static_cast<double>(st.edge_count) : 0.0) * a.unit;
  r.topology_ms = m.times.topology_ms;
  r.colouring_ms = m.times.colouring_ms;
  r.smoothing_ms = m.times.smoothing_ms;
  r.phase_ms = loop.phase_ms;
  for (const SweepCount& c : read_sweep_counts(a.counters, 0, r.sweeps, a.unit)) {
    r.accepted_per_sweep.push_back(c.accepted);
    r.max_displacement_per_sweep.push_back(c.max_displacement);
  }
  r.colour_sizes = std::move(class_sizes);
  if (a.num_colours > 0) {
    std::vector<unsigned long long> ns(static_cast<std::size_t>(a.num_colours));
    CUDA_CHECK(cudaMemcpy(ns.data(), m.colour_ns.data(), ns.size() * sizeof(ns[0]), cudaMemcpyDeviceToHost));
    for (unsigned long long v : ns) r.colour_ms.push_back(static_cast<double>(v) / 1e6);
  }
  m.result_in_buf1 = latest_in_buf1(o.form, r.sweeps);
  return r;
}

std::vector<double> GpuPipeline::download_xyz() const {
  Impl& m = *impl_;
  if (m.topo.movable.size() != m.n)
    throw UsageError("GpuPipeline::download_xyz: run() has not been called");
  const index_t n = static_cast<index_t>(m.n);
  const void* src = m.result_in_buf1 ? m.buf1.data() : m.buf0.data();
  CUDA_CHECK(cudaMemcpyAsync(m.output.data(), m.input.data(), m.input.bytes(), cudaMemcpyDeviceToDevice, m.stream));
  if (m.precision == Precision::Float)
    store_movable_coords<float>(src, m.input.data(), m.output.data(), m.topo.movable.data(), n, m.layout,
                                m.frame_centre(), m.frame_scale(), m.stream);
  else
    store_movable_coords<double>(src, m.input.data(), m.output.data(), m.topo.movable.data(), n, m.layout,
                                 m.frame_centre(), m.frame_scale(), m.stream);
  return m.output.download(m.stream);
}

MovableRows GpuPipeline::movable_rows() const {
  Impl& m = *impl_;
  if (m.topo.movable.size() != m.n) throw UsageError("GpuPipeline::movable_rows: run() has not been called");
  const std::vector<index_t> nbr_off = m.topo.nbr_off.download(m.stream), inc_off = m.topo.inc_off.download(m.stream);
  const std::vector<std::uint8_t> movable = m.topo.movable.download(m.stream);
  return tetsmooth::movable_rows(nbr_off.data(), inc_off.data(), movable.data(), m.n);
}

std::size_t GpuPipeline::fixed_nodes_moved() const {
  Impl& m = *impl_;
  if (m.topo.movable.size() != m.n)
    throw UsageError("GpuPipeline::fixed_nodes_moved: run() has not been called");
  const index_t n = static_cast<index_t>(m.n);
  DeviceBuffer<unsigned long long> count(1);
  CUDA_CHECK(cudaMemsetAsync(count.data(), 0, sizeof(unsigned long long), m.stream));
  const void* working = m.result_in_buf1 ? m.buf1.data() : m.buf0.data();
  if (m.precision == Precision::Float)
    count_moved_fixed<float>(working, m.input.data(), m.topo.movable.data(), n, m.layout, m.frame_centre(),
                             m.frame_scale(), count.data(), m.stream);
  else
    count_moved_fixed<double>(working, m.input.data(), m.topo.movable.data(), n, m.layout, m.frame_centre(),
                              m.frame_scale(), count.data(), m.stream);
  return static_cast<std::size_t>(count.download(m.stream).front());
}

double measure_copy_bandwidth(std::size_t bytes, int repetitions) {
  DeviceBuffer<unsigned char> a(bytes), b(bytes);
  CUDA_CHECK(cudaMemset(a.data(), 1, bytes));
  CUDA_CHECK(cudaMemcpy(b.data(), a.data(), bytes, cudaMemcpyDeviceToDevice));  // warm-up
  Event start, stop;
  start.record(nullptr);
  for (int r = 0; r < repetitions; ++r) CUDA_CHECK(cudaMemcpyAsync(b.data(), a.data(), bytes, cudaMemcpyDeviceToDevice));
  stop.record(nullptr);
  CUDA_CHECK(cudaDeviceSynchronize());
  const double seconds = stop.ms_since(start) / 1000.0;
  return 2.0 * static_cast<double>(bytes) * repetitions / seconds;
}

}  // namespace tetsmooth::cuda
