#pragma once
// Registers the benchmark families at run time:
//   <Form>/<Layout>/<Strategy>/<model>      GPU (FormA|FormB, AoS|SoA, SingleBlock|MultiBlock|Coloured)
//   Serial/FormA/<model>, Serial/FormB/<model>, Serial/Ordinary/<model>   one CPU core
//   Threads/FormA/<model>, Threads/FormB/<model>                          all CPU cores
//   Memory/CopyBandwidth                     device-to-device copy, the memory ceiling
// Every family times topology + colouring + smoothing to convergence, the
// mesh already in memory (GPU: on the device), input coordinates restored
// before each iteration outside the timed region.
#include <string>
#include <vector>

#include "kernels/smooth_options.hpp"

namespace tetsmooth::bench {

struct BenchConfig {
  std::vector<std::string> models{"5k", "10k", "59k", "77k", "109k"};  // paper models, by Table 2 label
  std::vector<std::string> scaling;  // lattice-N meshes, GPU Form B only
  Precision precision = Precision::Double;
  int coloured_lanes = 0;  // GPU Coloured threads per node; 0 = automatic (SmoothOptions)
  bool cpu = true;
  bool gpu = true;
};

// The generator name for a benchmark label ("77k" is the slope model).
std::string generator_name(const std::string& label);

// Returns the context entries (key, value) describing the meshes and device.
std::vector<std::pair<std::string, std::string>> register_benchmarks(const BenchConfig& config);

}  // namespace tetsmooth::bench
