#include "bench/bench_registry.hpp"

#include <benchmark/benchmark.h>
#include <omp.h>

#include <cstdio>
#include <map>
#include <memory>

#include "bench/bench_counters.hpp"
#include "bench/mesh_cache.hpp"
#include "kernels/smoother.hpp"
#include "mesh/errors.hpp"
#include "mesh/quality_summary.hpp"
#include "mesh/topology.hpp"
#ifdef TETSMOOTH_HAVE_CUDA
#include "kernels/cuda/gpu_pipeline.hpp"
#endif

namespace tetsmooth::bench {
namespace {

struct BenchMesh {
  TetMesh mesh;
  std::vector<std::uint8_t> movable;  // empty for scaling meshes (no host topology)
  SweepFootprint footprint;
  QualitySummary before;
};

// Meshes are loaded (or generated into the cache) on first use, before any
// timed region.
BenchMesh& bench_mesh(const std::string& label, bool with_host_topology) {
  static std::map<std::string, std::unique_ptr<BenchMesh>> meshes;
  auto& slot = meshes[label];
  if (!slot) {
    slot = std::make_unique<BenchMesh>();
    slot->mesh = cached_model(generator_name(label));
    slot->footprint.nodes = slot->mesh.num_nodes();
    slot->footprint.tets = slot->mesh.num_tets();
    if (with_host_topology) {
      const Topology topo = build_topology(slot->mesh);
      slot->movable = topo.movable;
      const MovableRows rows = movable_rows(topo);
      slot->footprint.movable_nodes = rows.nodes;
      slot->footprint.neighbour_entries = rows.neighbour_entries;
      slot->footprint.incidence_entries = rows.incidence_entries;
      slot->before = summarize_quality(slot->mesh, slot->movable);
    }
  }
  return *slot;
}

void cpu_family(benchmark::State& state, std::string label, SmoothOptions o) {
  BenchMesh& bm = bench_mesh(label, true);
  SmoothResult r;
  TetMesh work = bm.mesh;
  for (auto _ : state) {
    work.xyz = bm.mesh.xyz;
    r = smooth_cpu(work, o);
    state.SetIterationTime((r.topology_ms + r.colouring_ms + r.smoothing_ms) / 1000.0);
  }
  SweepFootprint f = bm.footprint;
  f.stars = o.method == Method::Adaptive;
  f.in_place = o.form == Form::B;
  set_run_counters(state, r, f);
  set_quality_counters(state, r.before, r.after);
}

void register_cpu(const std::string& label) {
  struct Variant {
    const char* name;
    Method method;
    Form form;
    int threads;
  };
  const Variant variants[] = {{"Serial/FormA/", Method::Adaptive, Form::A, 1},
                              {"Serial/FormB/", Method::Adaptive, Form::B, 1},
                              {"Serial/Ordinary/", Method::Ordinary, Form::B, 1},
                              {"Threads/FormA/", Method::Adaptive, Form::A, 0},
                              {"Threads/FormB/", Method::Adaptive, Form::B, 0}};
  for (const Variant& v : variants) {
    SmoothOptions o;
    o.method = v.method;
    o.form = v.form;
    o.threads = v.threads;
    benchmark::RegisterBenchmark((v.name + label).c_str(), cpu_family, label, o)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  }
}

#ifdef TETSMOOTH_HAVE_CUDA
cuda::GpuPipeline& pipeline_for(const std::string& label, const TetMesh& mesh) {
  static std::map<std::string, std::unique_ptr<cuda::GpuPipeline>> pipelines;
  auto& slot = pipelines[label];
  if (!slot) slot = std::make_unique<cuda::GpuPipeline>(mesh);
  return *slot;
}

void gpu_family(benchmark::State& state, std::string label, SmoothOptions o, bool scaling) {
  BenchMesh& bm = bench_mesh(label, !scaling);
  cuda::GpuPipeline& p = pipeline_for(label, bm.mesh);
  SmoothResult r;
  for (auto _ : state) {
    p.restore_coordinates(o);
    r = p.run(o);
    state.SetIterationTime(p.last_times().total_ms / 1000.0);
  }
  SweepFootprint f = bm.footprint;
  f.real_bytes = o.precision == Precision::Float ? 4 : 8;
  const MovableRows rows = p.movable_rows();  // the device's own topology, for the scaling meshes too
  f.movable_nodes = rows.nodes;
  f.neighbour_entries = rows.neighbour_entries;
  f.incidence_entries = rows.incidence_entries;
  f.stars = o.method == Method::Adaptive;
  f.in_place = o.form == Form::B;
  set_run_counters(state, r, f);
  state.counters["launches"] = p.last_times().launches;
  state.counters["host_checks"] = p.last_times().host_checks;
  state.counters["lanes_per_node"] = p.last_times().lanes_per_node;
  if (!scaling) {
    TetMesh after = bm.mesh;
    after.xyz = p.download_xyz();
    set_quality_counters(state, bm.before, summarize_quality(after, bm.movable));
  }
  // Where a MultiBlock sweep's time goes, kernel by kernel: a run of its own,
  // since the events that time it would add to the timed ones.
  if (o.strategy == Strategy::MultiBlock) {
    SmoothOptions phased = o;
    phased.time_phases = true;
    p.restore_coordinates(phased);
    for (const auto& [name, value] : phase_counter_values(p.run(phased))) state.counters[name] = value;
  }
}

void register_gpu(const std::string& label, const BenchConfig& c, bool scaling) {
  const auto add = [&](const std::string& prefix, SmoothOptions o) {
    o.precision = c.precision;
    o.coloured_lanes = c.coloured_lanes;
    const std::string name = prefix + to_string(o.layout) + "/" + to_string(o.strategy) + "/" + label;
    benchmark::RegisterBenchmark(name.c_str(), gpu_family, label, o, scaling)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
  };
  for (Form form : {Form::A, Form::B})
    for (Layout layout : {Layout::AoS, Layout::SoA})
      for (Strategy strategy : {Strategy::SingleBlock, Strategy::MultiBlock, Strategy::Coloured}) {
        if (strategy == Strategy::Coloured && form == Form::A) continue;  // Form A needs no colouring
        if (scaling && (form == Form::A || strategy == Strategy::SingleBlock)) continue;
        SmoothOptions o;
        o.form = form;
        o.layout = layout;
        o.strategy = strategy;
        add(form == Form::A ? "FormA/" : "FormB/", o);
      }
  // On the scaling meshes, ordinary Laplacian smoothing (Form B) as well: the
  // same sweep without the adaptive test, so the share of the time the star
  // takes shows beside the memory floor.
  if (scaling)
    for (Strategy strategy : {Strategy::MultiBlock, Strategy::Coloured}) {
      SmoothOptions o;
      o.method = Method::Ordinary;
      o.form = Form::B;
      o.layout = Layout::AoS;
      o.strategy = strategy;
      add("Ordinary/", o);
    }
}

void copy_bandwidth(benchmark::State& state) {
  const std::size_t bytes = std::size_t(1) << 30;
  double bw = 0;
  for (auto _ : state) {
    bw = cuda::measure_copy_bandwidth(bytes);
    state.SetIterationTime(2.0 * static_cast<double>(bytes) / bw);
  }
  state.counters["bytes_per_s"] = bw;
}
#endif

}  // namespace

std::string generator_name(const std::string& label) { return label == "77k" ? "slope-77k" : label; }

std::vector<std::pair<std::string, std::string>> register_benchmarks(const BenchConfig& c) {
  std::vector<std::pair<std::string, std::string>> context;
  context.emplace_back("host_threads", std::to_string(omp_get_max_threads()));
  context.emplace_back("gpu_precision", to_string(c.precision));
  std::string why;
  const bool gpu = c.gpu && cuda_available(&why);
  if (!gpu && !c.cpu)
    throw UsageError("nothing to run: --no-cpu, and no GPU families (" + (c.gpu ? why : std::string("--no-gpu")) + ")");
  if (!gpu) std::fprintf(stderr, "bench_smooth: GPU families not registered: %s\n", c.gpu ? why.c_str() : "--no-gpu");
#ifdef TETSMOOTH_HAVE_CUDA
  if (gpu) {
    const cuda::DeviceInfo d = cuda::device_info();
    context.emplace_back("gpu_name", d.name);
    context.emplace_back("sm_count", std::to_string(d.sm_count));
    context.emplace_back("compute_capability", std::to_string(d.cc_major) + "." + std::to_string(d.cc_minor));
    context.emplace_back("cuda_version", std::to_string(d.runtime_version));
    context.emplace_back("cuda_driver_version", std::to_string(d.driver_version));
    benchmark::RegisterBenchmark("Memory/CopyBandwidth", copy_bandwidth)->UseManualTime()->Unit(benchmark::kMillisecond);
  }
#endif
  for (const std::string& label : c.models) {
    const BenchMesh& bm = bench_mesh(label, true);
    context.emplace_back("model_" + label + "_nodes", std::to_string(bm.mesh.num_nodes()));
    context.emplace_back("model_" + label + "_tets", std::to_string(bm.mesh.num_tets()));
    if (c.cpu) register_cpu(label);
#ifdef TETSMOOTH_HAVE_CUDA
    if (gpu) register_gpu(label, c, false);
#endif
  }
#ifdef TETSMOOTH_HAVE_CUDA
  if (gpu)
    for (const std::string& label : c.scaling) register_gpu(label, c, true);
#endif
  return context;
}

}  // namespace tetsmooth::bench
