// tetsmooth quality: statistics and the worst tets of one mesh.
#include <algorithm>

#include "apps/commands.hpp"
#include "apps/input_warnings.hpp"
#include "apps/on_input_mesh.hpp"
#include "apps/option_names.hpp"
#include "apps/smoothing_pins.hpp"
#include "apps/report_json.hpp"
#include "apps/report_text.hpp"
#include "mesh/io/mesh_io.hpp"
#include "mesh/topology.hpp"

namespace tetsmooth::cli {

void run_quality(const QualityCommand& c, const Console& console) {
  QualityRecord record;
  record.format = input_format_of(c.input, c.input_format);
  TetMesh mesh = read_mesh(c.input, record.format);
  record.mesh = inspect_input(mesh, c.input);
  for (const std::string& w : input_warnings(mesh, record.mesh, c.input)) console.warn(w);

  // The topology tells which tets smoothing could change (min_movable), with
  // material interfaces and Gmsh features pinned as `smooth` pins them.
  const Topology topology = on_input_mesh(c.input, [&] {
    const SmoothingPins pins(mesh, 0);  // all cores, as the quality summary
    record.curved_tets = pins.curved_tets();
    return build_topology(mesh, 0);
  });
  // Midside nodes of second-order tets on boundary faces count too, as in
  // the `boundary` field of written files.
  const std::vector<std::uint8_t> boundary =
      mesh.midsides.empty() ? topology.boundary : find_boundary_nodes(mesh.tets, mesh.num_nodes(), 0, mesh.midsides);
  record.boundary_nodes = static_cast<std::size_t>(std::count(boundary.begin(), boundary.end(), 1));
  record.movable_nodes = static_cast<std::size_t>(std::count(topology.movable.begin(), topology.movable.end(), 1));
  record.summary = summarize_quality(mesh, topology.movable);
  record.worst = worst_tets(mesh, tet_qualities(mesh), static_cast<std::size_t>(c.worst));

  std::ostream& os = console.out;
  if (c.json) {
    os << json_text(quality_report_json(c, record)) << '\n';
    return;
  }
  os << c.input << ": " << with_thousands(record.mesh.nodes) << " nodes (" << with_thousands(record.boundary_nodes)
     << " on the boundary, " << with_thousands(record.movable_nodes) << " movable), "
     << with_thousands(record.mesh.tets) << " tets (" << input_format_name(record.format) << ")\n\n";
  write_quality_table(os, {{"", &record.summary}});
  os << '\n';
  write_histogram(os, {{"", &record.summary}});
  if (!record.worst.empty()) {
    os << '\n';
    write_worst_tets(os, record.worst);
  }
}

}  // namespace tetsmooth::cli
