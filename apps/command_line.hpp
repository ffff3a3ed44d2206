#pragma once
// What the user asked for, parsed and checked but not yet run.
#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "apps/progress_line.hpp"
#include "kernels/smooth_options.hpp"
#include "mesh/io/mesh_io.hpp"

namespace tetsmooth::cli {

struct HelpRequest {
  std::string command;  // empty for the top-level help
};

struct VersionRequest {};

struct GenerateCommand {
  std::string model;
  std::string output;
  MeshFormat output_format = MeshFormat::Auto;
  std::uint64_t seed = 1;
  bool quiet = false;
};

struct SmoothCommand {
  std::string input, output, report_path;  // report_path empty: no JSON report
  MeshFormat input_format = MeshFormat::Auto, output_format = MeshFormat::Auto;
  SmoothOptions options;
  Device device = Device::Auto;
  ProgressMode progress = ProgressMode::Auto;
  bool quiet = false;
  // Options only one backend uses, remembered so a run can say it ignored them.
  bool strategy_given = false, layout_given = false;
};

struct QualityCommand {
  std::string input;
  MeshFormat input_format = MeshFormat::Auto;
  bool json = false;
  int worst = 10;
  bool quiet = false;
};

struct ConvertCommand {
  std::string input, output;
  MeshFormat input_format = MeshFormat::Auto, output_format = MeshFormat::Auto;
  bool quiet = false;
};

using Command =
    std::variant<HelpRequest, VersionRequest, GenerateCommand, SmoothCommand, QualityCommand, ConvertCommand>;

// `args` excludes the program name. Throws UsageError with a one-line
// message for anything malformed.
Command parse_command_line(const std::vector<std::string>& args);

// The subcommands, in the order --help lists them.
const std::vector<std::string>& command_names();

}  // namespace tetsmooth::cli
