#include "bench/bench_flags.hpp"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <sstream>

#include "generators/models.hpp"
#include "mesh/errors.hpp"

namespace tetsmooth::bench {
namespace {

// The comma-separated items of a list flag, in order.
std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

// A model named twice (77k and slope-77k) would register its benchmarks twice.
void add_once(std::vector<std::string>& list, std::string item) {
  if (std::find(list.begin(), list.end(), item) == list.end()) list.push_back(std::move(item));
}

std::string checked_lattice(const std::string& name) {
  const std::string prefix = "lattice-";
  int n = 0;
  const char* first = name.data() + std::min(prefix.size(), name.size());
  const char* last = name.data() + name.size();
  const auto [end, ec] = std::from_chars(first, last, n);
  if (name.rfind(prefix, 0) != 0 || ec != std::errc() || end != last || n < 1)
    throw UsageError("--scaling: '" + name + "' is not a lattice-N mesh (N cubes a side, N >= 1)");
  // Checked here, not when a GPU family first builds the mesh mid-run.
  if (n > kMaxLatticeN)
    throw UsageError("--scaling: '" + name + "' is too large: the largest lattice is lattice-" +
                     std::to_string(kMaxLatticeN));
  return name;
}

int checked_lanes(const std::string& text) {
  int lanes = -1;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), lanes);
  if (ec != std::errc() || end != text.data() + text.size() ||
      (lanes != 0 && lanes != 8 && lanes != 16 && lanes != 32))
    throw UsageError("--coloured-lanes: '" + text + "' is not 0 (automatic), 8, 16 or 32");
  return lanes;
}

}  // namespace

std::string model_label(const std::string& name) {
  if (name == "77k" || name == "slope-77k") return "77k";
  std::string known;
  for (const std::string& model : paper_model_names()) {
    if (name == model) return name;
    // The label the benchmark names and the README use, then the generator's.
    known += (known.empty() ? "" : ", ") + (model == "slope-77k" ? std::string("77k (or slope-77k)") : model);
  }
  throw UsageError("--models: unknown model '" + name + "'; expected some of " + known +
                   "; lattice meshes go in --scaling");
}

BenchConfig take_own_flags(int& argc, char** argv) {
  BenchConfig c;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* prefix) { return a.substr(std::strlen(prefix)); };
    if (a.rfind("--models=", 0) == 0) {
      c.models.clear();
      for (const std::string& name : split_list(value("--models="))) add_once(c.models, model_label(name));
      if (c.models.empty()) throw UsageError("--models: empty list");
    } else if (a.rfind("--scaling=", 0) == 0) {
      // "none" (or nothing) turns off scaling meshes a script asked for earlier.
      c.scaling.clear();
      const std::string list = value("--scaling=");
      if (list != "none")
        for (const std::string& name : split_list(list)) add_once(c.scaling, checked_lattice(name));
    } else if (a.rfind("--precision=", 0) == 0) {
      const std::string p = value("--precision=");
      if (p != "double" && p != "float") throw UsageError("--precision: '" + p + "' is not double or float");
      c.precision = p == "float" ? Precision::Float : Precision::Double;
    } else if (a.rfind("--coloured-lanes=", 0) == 0) {
      c.coloured_lanes = checked_lanes(value("--coloured-lanes="));
    } else if (a == "--models" || a == "--scaling" || a == "--precision" || a == "--coloured-lanes") {
      // Google Benchmark would call "--models 5k" two unrecognized flags.
      const char* example = a == "--models"      ? "--models=5k,10k"
                            : a == "--scaling"   ? "--scaling=lattice-215"
                            : a == "--precision" ? "--precision=float"
                                                 : "--coloured-lanes=8";
      throw UsageError(a + ": the value follows '=', as in " + example);
    } else if (a == "--no-cpu") {
      c.cpu = false;
    } else if (a == "--no-gpu") {
      c.gpu = false;
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  return c;
}

const char* own_flags_help() {
  return "bench_smooth: the study of the paper's Tables 3-6 and Figures 9-13.\n"
         "Each benchmark times topology + colouring + smoothing to convergence.\n"
         "\n"
         "bench_smooth's own flags:\n"
         "  --models=LIST          paper models to run, comma-separated (default 5k,10k,59k,77k,109k;\n"
         "                         slope-77k is accepted for 77k)\n"
         "  --scaling=LIST         lattice-N meshes for the GPU scaling runs, e.g. lattice-215 (10M nodes);\n"
         "                         default none; --scaling=none drops those an earlier flag named\n"
         "  --precision=P          GPU precision, double (default) or float\n"
         "  --coloured-lanes=N     GPU Coloured threads per node: 0 automatic (default), 8, 16 or 32\n"
         "  --no-cpu               skip the serial and threaded CPU baselines\n"
         "  --no-gpu               skip the GPU families\n"
         "Environment: TETSMOOTH_MESH_CACHE (generated meshes, default ./meshes),\n"
         "TETSMOOTH_GIT_SHA (the commit written into the JSON's context).\n"
         "Exit status: 0 done, 1 a run failed, 2 a bad flag or no benchmark selected.\n"
         "\n"
         "Google Benchmark's flags follow.\n\n";
}

}  // namespace tetsmooth::bench
