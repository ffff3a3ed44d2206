#pragma once
// Reports for programs: the same content as the text reports, as JSON.
// Keys keep the order written here (ordered_json), so the files read top
// down: what was run, what it did, what came of it. Readers should ignore
// fields they do not know; fields are only added.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "apps/command_line.hpp"
#include "apps/worst_tets.hpp"
#include "kernels/smooth_options.hpp"
#include "mesh/quality_summary.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth::cli {

// Everything a smooth run did besides the smoother's own result.
struct SmoothRecord {
  MeshFormat input_format = MeshFormat::Auto, output_format = MeshFormat::Auto;
  ValidationReport input;       // counts of the mesh as read
  std::size_t curved_tets = 0;  // second-order tets that keep their shape (SmoothingPins)
  Device device = Device::Cpu;  // the device that ran (never Auto)
  SmoothResult result;
  double read_ms = 0, write_ms = 0, total_ms = 0;
  std::vector<std::string> warnings;
};

struct QualityRecord {
  MeshFormat format = MeshFormat::Auto;
  ValidationReport mesh;
  std::size_t boundary_nodes = 0, movable_nodes = 0;
  std::size_t curved_tets = 0;  // second-order tets that smoothing keeps as they are
  QualitySummary summary;
  std::vector<RankedTet> worst;
};

nlohmann::ordered_json summary_json(const QualitySummary& s);
nlohmann::ordered_json smooth_report_json(const SmoothCommand& command, const SmoothRecord& record);
nlohmann::ordered_json quality_report_json(const QualityCommand& command, const QualityRecord& record);

// The document as pretty-printed text. File names and array names are bytes
// from the user's files, not always UTF-8: invalid sequences become U+FFFD
// rather than stopping the report (JSON must be UTF-8).
std::string json_text(const nlohmann::ordered_json& doc);

// Pretty-printed JSON with a final newline, written atomically to `path`.
void write_json_file(const nlohmann::ordered_json& doc, const std::string& path);

}  // namespace tetsmooth::cli
