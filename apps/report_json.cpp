#include "apps/report_json.hpp"

#include "apps/option_names.hpp"
#include "mesh/io/atomic_file.hpp"

namespace tetsmooth::cli {
namespace {

nlohmann::ordered_json mesh_counts_json(const ValidationReport& v) {
  return {{"nodes", v.nodes},
          {"tets", v.tets},
          {"nodes_per_tet", v.nodes_per_tet},
          {"inverted_tets", v.inverted},
          {"degenerate_tets", v.degenerate},
          {"unreferenced_nodes", v.unreferenced},
          {"repeated_tets", v.repeated}};
}

nlohmann::ordered_json options_json(const SmoothCommand& c) {
  const SmoothOptions& o = c.options;
  return {{"method", option_name(o.method)},       {"form", option_name(o.form)},
          {"strategy", option_name(o.strategy)},   {"layout", option_name(o.layout)},
          {"device", option_name(c.device)},       {"threads", o.threads},
          {"precision", option_name(o.precision)}, {"cpu_ordering", option_name(o.ordering)},
          {"max_iterations", o.max_iterations},    {"tolerance", o.tolerance}};
}

}  // namespace

nlohmann::ordered_json summary_json(const QualitySummary& s) {
  nlohmann::ordered_json lower_edges = nlohmann::ordered_json::array();
  for (int bin = 0; bin < 10; ++bin) lower_edges.push_back(bin / 10.0);
  return {{"tets", s.tets},
          {"min", s.min},
          {"mean", s.mean},
          {"max", s.max},
          {"min_movable", s.movable_tets > 0 ? nlohmann::ordered_json(s.min_movable) : nlohmann::ordered_json()},
          {"movable_tets", s.movable_tets},
          {"below_0_1", s.below_0_1},
          {"inverted", s.inverted},
          {"degenerate", s.degenerate},
          {"min_dihedral_deg", s.min_dihedral_deg},
          {"mean_ratio_mean", s.mean_ratio_mean},
          {"histogram", {{"lower_edges", lower_edges}, {"counts", s.histogram}}}};
}

nlohmann::ordered_json smooth_report_json(const SmoothCommand& command, const SmoothRecord& record) {
  const SmoothResult& r = record.result;
  nlohmann::ordered_json input = mesh_counts_json(record.input);
  input["path"] = command.input;
  input["format"] = input_format_name(record.input_format);
  input["curved_tets"] = record.curved_tets;
  return {{"tool", "tetsmooth"},
          {"version", TETSMOOTH_VERSION},
          {"command", "smooth"},
          {"input", input},
          {"output", {{"path", command.output}, {"format", format_name(record.output_format)}}},
          {"options", options_json(command)},
          {"device", option_name(record.device)},
          {"backend", r.backend},
          {"sweeps", r.sweeps},
          {"stop_reason", to_string(r.stop)},
          {"accepted_per_sweep", r.accepted_per_sweep},
          {"max_displacement_per_sweep", r.max_displacement_per_sweep},
          {"reverted_moves", r.reverted_moves},
          {"node_evaluations", r.evaluations},
          {"colours", r.num_colours},
          {"movable_nodes", r.movable_nodes},
          {"second_order_restarts", r.second_order_restarts},
          {"folded_tets", r.folded_tets},
          {"mean_edge_length", r.mean_edge_length},
          {"timings_ms",
           {{"read", record.read_ms},
            {"topology", r.topology_ms},
            {"colouring", r.colouring_ms},
            {"smoothing", r.smoothing_ms},
            {"write", record.write_ms},
            {"total", record.total_ms}}},
          {"quality", {{"before", summary_json(r.before)}, {"after", summary_json(r.after)}}},
          {"warnings", record.warnings}};
}

nlohmann::ordered_json quality_report_json(const QualityCommand& command, const QualityRecord& record) {
  nlohmann::ordered_json worst = nlohmann::ordered_json::array();
  for (const RankedTet& t : record.worst) {
    nlohmann::ordered_json entry = {{"tet", t.tet}, {"quality", t.quality}, {"nodes", t.nodes}};
    // The file's own numbers, where it has them (worst_tets.hpp).
    if (t.element != 0) entry["element_number"] = t.element;
    if (t.node_numbers[0] != 0) entry["node_numbers"] = t.node_numbers;
    worst.push_back(std::move(entry));
  }
  nlohmann::ordered_json input = mesh_counts_json(record.mesh);
  input["path"] = command.input;
  input["format"] = input_format_name(record.format);
  input["boundary_nodes"] = record.boundary_nodes;
  input["movable_nodes"] = record.movable_nodes;
  input["curved_tets"] = record.curved_tets;
  return {{"tool", "tetsmooth"},  {"version", TETSMOOTH_VERSION},
          {"command", "quality"}, {"input", input},
          {"index_base", 0},      {"quality", summary_json(record.summary)},
          {"worst_tets", worst}};
}

std::string json_text(const nlohmann::ordered_json& doc) {
  return doc.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

void write_json_file(const nlohmann::ordered_json& doc, const std::string& path) {
  write_atomically(path, [&](std::ostream& os) { os << json_text(doc) << '\n'; });
}

}  // namespace tetsmooth::cli
