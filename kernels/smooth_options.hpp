#pragma once
// What a caller asks of a smoother, and what it gets back. Shared by the CPU
// and CUDA backends and by the CLI and the benchmarks.
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "mesh/quality_summary.hpp"

namespace tetsmooth {

enum class Method { Adaptive, Ordinary };
// A: Jacobi, every node computed from sweep q's coordinates (double buffered).
// B: in place, a node sees the neighbours already moved in this sweep.
enum class Form { A, B };
// Data layout of the coordinates on the device.
enum class Layout { AoS, SoA };
// How sweeps are launched on the GPU (see kernels/cuda/).
enum class Strategy { SingleBlock, MultiBlock, Coloured };
enum class Precision { Float, Double };
enum class Device { Auto, Cpu, Cuda };
// Node order of CPU Form B: the natural order 0..N-1 (the paper's serial
// version) or colour by colour (race-free in parallel, same result for any
// thread count).
enum class Ordering { Natural, Coloured };

enum class StopReason { NoMoves, Tolerance, MaxIterations, NotStarted };

struct SweepProgress {
  int sweep = 0;
  std::int64_t accepted = 0;
  double max_displacement = 0;
  // The mesh's smallest and mean radius ratio as this sweep left it. A pass
  // over every tet, so a function that a display calls only when it will
  // show the values, and only during the callback. Empty where the backend
  // no longer holds that sweep's positions: a CUDA loop reports the sweeps
  // since its last host check together, and gives it to the last of them.
  std::function<MinMeanQuality()> quality;
};

struct SmoothOptions {
  Method method = Method::Adaptive;
  Form form = Form::B;
  Layout layout = Layout::AoS;
  Strategy strategy = Strategy::Coloured;
  Precision precision = Precision::Double;
  Ordering ordering = Ordering::Natural;
  int threads = 1;                // CPU threads; 0 = all cores
  int max_iterations = 100;
  double tolerance = 1e-4;        // relative to the mean edge length
  int check_every = 4;            // CUDA MultiBlock: sweeps between host checks of the stop flag
                                  // (SingleBlock and Coloured run the whole loop in one launch)
  // CUDA Coloured: skip a node when neither it nor a neighbour moved since it
  // was last evaluated; the same inputs would give the same rejection, so the
  // result is unchanged (kernels/cuda/coloured_loop_kernel.cuh).
  bool skip_settled = true;
  // CUDA Coloured: threads per node, 8, 16 or 32; 0 picks by the size of
  // the colour classes (kernels/cuda/coloured_loop_launch.cuh).
  int coloured_lanes = 0;
  // CUDA Coloured: at most this many blocks in the cooperative grid; 0 takes
  // as many as the device holds at once (a study of fewer SMs, or a test
  // that gives each block more nodes of a class than it stages at once).
  int coloured_blocks = 0;
  // CUDA MultiBlock: time each kind of kernel of the sweeps with CUDA events
  // (SmoothResult::phase_ms). A diagnostic: the events cost the GPU a few
  // microseconds a sweep, so bench_smooth takes them in a run of its own,
  // outside the timed ones. The other strategies and the CPU ignore it.
  bool time_phases = false;
  // Called after each sweep when set (CPU: every sweep; CUDA: at each host
  // check, for SingleBlock and Coloured once the loop has ended). Its time
  // counts in smoothing_ms, quality passes included.
  std::function<void(const SweepProgress&)> progress;
};

struct SmoothResult {
  int sweeps = 0;
  StopReason stop = StopReason::NotStarted;
  std::vector<std::int64_t> accepted_per_sweep;
  std::vector<double> max_displacement_per_sweep;
  std::int64_t reverted_moves = 0;  // Form A: accepted moves undone by the conflict repair
  std::int64_t evaluations = 0;     // node evaluations over all sweeps (movable x sweeps unless skipped)
  int num_colours = 0;
  std::size_t movable_nodes = 0;
  double mean_edge_length = 0;
  double topology_ms = 0, colouring_ms = 0, smoothing_ms = 0;
  // CUDA Coloured: milliseconds spent on each colour class (index = colour),
  // summed over the sweeps, barrier waits included; together they are the
  // smoothing phase less the loop's set-up (the tet quality cache). Empty
  // for the other strategies and the CPU.
  std::vector<double> colour_ms;
  std::vector<std::int64_t> colour_sizes;  // nodes of each colour class (Coloured runs, CPU and CUDA)
  // CUDA MultiBlock with time_phases: milliseconds per kind of kernel, in
  // launch order: "tet_quality" (adaptive: the tet quality cache),
  // "node_update" (the sweep kernel), "repair" (Form A: the conflict repair
  // where adaptive, and the move count), "stopping_rule" (the verdict).
  // Summed over every sweep launched, as smoothing_ms is: the sweeps of the
  // last chunk after the stop return at once. The first kernel after each
  // host check carries its launch latency (kernels/cuda/phase_timer.hpp).
  // What they leave of smoothing_ms is the host's checks of the stop flag
  // and, once a run, the loop's set-up (the wait for the tolerance's edge
  // sums). Empty otherwise.
  std::vector<std::pair<std::string, double>> phase_ms;
  QualitySummary before, after;
  std::string backend;  // "cpu-serial", "cpu-threads", "cuda"
  // Second-order meshes (smooth_second_order): how many times the run
  // started again, and the tets whose folding made it (their corners then
  // stayed). The rest of the result is the last run's.
  int second_order_restarts = 0;
  std::size_t folded_tets = 0;
};

const char* to_string(Method m);
const char* to_string(Form f);
const char* to_string(Layout l);
const char* to_string(Strategy s);
const char* to_string(Precision p);
const char* to_string(StopReason r);

}  // namespace tetsmooth
