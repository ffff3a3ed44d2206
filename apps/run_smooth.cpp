// tetsmooth smooth: read, smooth, report before/after, write.
#include <chrono>
#include <sstream>

#include "apps/commands.hpp"
#include "apps/input_warnings.hpp"
#include "apps/on_input_mesh.hpp"
#include "apps/option_names.hpp"
#include "apps/output_check.hpp"
#include "apps/output_fields.hpp"
#include "apps/progress_line.hpp"
#include "apps/report_json.hpp"
#include "apps/report_text.hpp"
#include "apps/smoothing_pins.hpp"
#include "kernels/smoother.hpp"
#include "kernels/sweep_log.hpp"
#include "mesh/errors.hpp"
#include "mesh/io/mesh_io.hpp"
#include "mesh/io/writable_check.hpp"
#include "mesh/quality_summary.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth::cli {
namespace {

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// Auto becomes a concrete device here, before any work, so the run can say
// which one it used and why.
Device choose_device(Device requested, std::string& why_not_cuda) {
  if (requested == Device::Cpu) return Device::Cpu;
  const bool usable = cuda_available(&why_not_cuda);
  if (requested == Device::Cuda && !usable) throw DeviceError("--device cuda: " + why_not_cuda);
  return usable ? Device::Cuda : Device::Cpu;
}

std::vector<std::string> ignored_option_warnings(const SmoothCommand& c, Device device) {
  // --threads is never ignored: a CUDA run builds its host topology on them.
  std::vector<std::string> warnings;
  if (device == Device::Cpu) {
    if (c.strategy_given) warnings.emplace_back("--strategy selects a CUDA launch scheme; ignored on the CPU");
    if (c.layout_given) warnings.emplace_back("--layout selects the CUDA data layout; ignored on the CPU");
    if (c.options.precision == Precision::Float)
      warnings.emplace_back("--precision float is a CUDA variant; the CPU computes in double");
  }
  return warnings;
}

std::string device_line(const SmoothCommand& c, Device device, const std::string& why_not_cuda) {
  const SmoothOptions& o = c.options;
  std::ostringstream s;
  s << "smoothing: " << option_name(o.method) << ", form " << option_name(o.form) << ", on ";
  if (device == Device::Cuda) {
    s << "cuda (strategy " << option_name(o.strategy) << ", layout " << option_name(o.layout) << ", "
      << option_name(o.precision) << ")";
  } else {
    s << "cpu (" << (o.threads == 0 ? std::string("all cores") : std::to_string(o.threads) + " thread(s)");
    if (o.form == Form::B) s << ", " << option_name(o.ordering) << " node order";
    s << ")";
    if (c.device == Device::Auto) s << "; no GPU used: " << why_not_cuda;
  }
  return s.str();
}

std::string stop_phrase(const SmoothResult& r, Method method) {
  // A mesh without a node free to move still takes its one sweep, which
  // accepts nothing: say why, rather than that no node could improve.
  if (r.movable_nodes == 0) return "nothing to smooth: no movable nodes";
  switch (r.stop) {
    case StopReason::NoMoves: return "no node could improve";
    case StopReason::Tolerance: return "moves fell below --tol";
    case StopReason::MaxIterations:
      return method == Method::Adaptive ? "reached --max-iter; more sweeps may improve further" : "reached --max-iter";
    case StopReason::NotStarted: return "no sweep run";
  }
  return "";
}

// What may have inverted tets in this run: ordinary smoothing moves without
// looking, and in-place Form B under CUDA MultiBlock or SingleBlock (the
// paper's racy variants) judges moves against neighbours that are moving.
std::string inversion_warning(const SmoothCommand& c, Device device, const InversionChange& change) {
  const std::string count =
      with_thousands(change.made) + " tets" +
      (change.mended > 0 ? " (and put right " + with_thousands(change.mended) + " that the input had inverted)" : "");
  if (c.options.method == Method::Ordinary) return "ordinary smoothing inverted " + count + "; --method adaptive with "
                                                   "the coloured strategy or --form A never does";
  if (device == Device::Cuda && c.options.form == Form::B && c.options.strategy != Strategy::Coloured)
    return "the " + std::string(option_name(c.options.strategy)) + " strategy in form B inverted " + count +
           ": its threads judge moves while neighbours move (the paper's race); the coloured strategy never does";
  return "smoothing inverted " + count;
}

void print_report(const Console& console, const SmoothCommand& c, const SmoothRecord& record) {
  const SmoothResult& r = record.result;
  std::ostream& os = console.err;
  os << "done: " << r.sweeps << " sweep(s), " << stop_phrase(r, c.options.method) << "\n"
     << "  " << with_thousands(r.movable_nodes) << " of " << with_thousands(record.input.nodes) << " nodes movable";
  if (r.num_colours > 0) os << ", " << r.num_colours << " colours";
  if (r.reverted_moves > 0)
    os << ", " << with_thousands(static_cast<std::size_t>(r.reverted_moves)) << " moves reverted";
  os << "\n  time (ms): read " << fixed_digits(record.read_ms, 1) << ", topology " << fixed_digits(r.topology_ms, 1)
     << ", colouring " << fixed_digits(r.colouring_ms, 1) << ", smoothing " << fixed_digits(r.smoothing_ms, 1)
     << "\n\n";
  const std::vector<SummaryColumn> columns{{"before", &r.before}, {"after", &r.after}};
  write_quality_table(os, columns);
  os << '\n';
  write_histogram(os, columns);
  os << '\n';
}

}  // namespace

void run_smooth(const SmoothCommand& c, const Console& console) {
  const Clock::time_point start = Clock::now();
  SmoothRecord record;
  record.input_format = input_format_of(c.input, c.input_format);
  record.output_format = format_from_path(c.output, c.output_format);
  std::string why_not_cuda;
  record.device = choose_device(c.device, why_not_cuda);
  if (record.device == Device::Cuda) check_gpu_sweeps(c.options);
  check_mesh_output_location(c.output, record.output_format);
  // "-" sends the report to standard output, which smoothing leaves free.
  const bool report_to_stdout = c.report_path == "-";
  if (!c.report_path.empty() && !report_to_stdout) {
    check_report_path(c.report_path, c.input, record.input_format, c.output, record.output_format);
    check_output_location(c.report_path);
  }

  Clock::time_point t0 = Clock::now();
  TetMesh mesh = read_mesh(c.input, record.input_format);
  record.read_ms = ms_since(t0);
  record.input = inspect_input(mesh, c.input);
  check_writable(mesh, c.output, record.output_format);
  const bool racy = record.device == Device::Cuda && c.options.form == Form::B &&
                    c.options.strategy != Strategy::Coloured;
  const std::string them = record.input.inverted == 1 ? "it" : "them";
  const std::string inverted_note =
      c.options.method == Method::Ordinary ? "continuing, but ordinary smoothing may make " + them + " worse"
      : racy ? "continuing, but this strategy's race in form B may make " + them + " worse"
             : "continuing: adaptive smoothing never makes " + them + " worse";
  record.warnings = input_warnings(mesh, record.input, c.input, inverted_note);
  for (const std::string& loss : output_losses(mesh, c.output, record.output_format))
    record.warnings.push_back(c.output + ": " + loss);
  for (std::string& w : ignored_option_warnings(c, record.device)) record.warnings.push_back(std::move(w));
  if (writes_over_input(c.input, record.input_format, c.output, record.output_format))
    record.warnings.push_back(c.output + " is the input mesh: it will be replaced once the whole result is written");
  for (const std::string& w : record.warnings) console.warn(w);
  console.note(c.input + ": " + with_thousands(record.input.nodes) + " nodes, " + with_thousands(record.input.tets) +
               " tets (" + input_format_name(record.input_format) + ")");
  console.note(device_line(c, record.device, why_not_cuda));

  SmoothOptions options = c.options;
  const ProgressLine::Style style = ProgressLine::style_for(c.progress, console.err_is_terminal, console.quiet);
  ProgressLine progress(console.err, style, options.max_iterations, ProgressLine::kDelay,
                        ProgressLine::interval_for(style));
  if (style != ProgressLine::Style::Off) options.progress = [&progress](const SweepProgress& p) { progress.update(p); };
  std::vector<std::uint8_t> inverted_before;  // tet by tet: a net count would hide mended tets behind new ones
  try {
    const SmoothingPins pins(mesh, options.threads);
    const auto stay = [](std::size_t n) { return n == 1 ? " stays fixed" : " stay fixed"; };
    if (const std::size_t n = pins.added_on_interfaces(); n > 0)
      console.note(counted(n, "node", "nodes") +
                   " on interfaces between regions (tets of different region tags, Abaqus sections, Nastran PIDs, FLAC3D groups, Exodus blocks, ANSYS materials, LS-DYNA parts or Gmsh volumes)" + stay(n));
    if (const std::size_t n = pins.added_on_features(); n > 0)
      console.note(counted(n, "node", "nodes") + " on Gmsh points, curves or surfaces inside the mesh" + stay(n));
    const std::size_t curved = record.curved_tets = pins.curved_tets(), corners = pins.added_at_curved_tets();
    // Most tets curved is more likely coordinates rounded coarser than
    // coordinate_resolution can tell than a mesh bent throughout.
    if (curved > 0)
      console.note(counted(curved, "second-order tet has", "second-order tets have") + " curved edges and " +
                   (curved == 1 ? "keeps its" : "keep their") + " shape" +
                   (corners > 0 ? ": " + counted(corners, "corner node", "corner nodes") + " off the boundary" +
                                      stay(corners)
                                : std::string()) +
                   (2 * curved > mesh.num_tets() ? " (most tets: if the file rounds its coordinates to a few "
                                                   "digits, the midside nodes may be off their edges by that rounding)"
                                                 : ""));
    else if (corners > 0)
      console.note(counted(corners, "node", "nodes") + " at the ends of edges whose midside node is pinned" +
                   stay(corners));
    inverted_before = inverted_tets(mesh);
    record.result = on_input_mesh(c.input, [&] { return smooth(mesh, options, record.device); });
  } catch (...) {
    progress.finish();
    throw;
  }
  progress.finish();

  const SmoothResult& r = record.result;
  if (r.second_order_restarts > 0)
    console.note(counted(r.folded_tets, "second-order tet", "second-order tets") +
                 " with midside nodes off their edges' midpoints would have folded (a Jacobian turning "
                 "non-positive): " + (r.folded_tets == 1 ? "its" : "their") + " corners stay, and smoothing started "
                 "again " + counted(static_cast<std::size_t>(r.second_order_restarts), "time", "times"));
  if (const InversionChange change = inversion_change(inverted_before, inverted_tets(mesh)); change.made > 0) {
    record.warnings.push_back(inversion_warning(c, record.device, change));
    console.warn(record.warnings.back());
  }
  if (!console.quiet) print_report(console, c, record);

  t0 = Clock::now();
  write_mesh_with_fields(mesh, c.output, record.output_format);
  record.write_ms = ms_since(t0);
  console.note("wrote " + c.output + " (" + format_name(record.output_format) + ")");
  if (!c.report_path.empty()) {
    record.total_ms = ms_since(start);
    try {
      if (report_to_stdout) {
        console.out << json_text(smooth_report_json(c, record)) << '\n' << std::flush;
        if (!console.out) throw OutputError("cannot write the report to standard output");
      } else {
        write_json_file(smooth_report_json(c, record), c.report_path);
        console.note("wrote report " + c.report_path);
      }
    } catch (const OutputError& e) {
      // Even with -q, say that the mesh itself is done.
      throw OutputError(std::string(e.what()) + " (the smoothed mesh was written to '" + c.output + "')");
    }
  }
}

}  // namespace tetsmooth::cli
