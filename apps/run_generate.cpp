// tetsmooth generate: build one of the test meshes and write it.
#include "apps/commands.hpp"
#include "apps/output_check.hpp"
#include "apps/output_fields.hpp"
#include "apps/report_text.hpp"
#include "generators/models.hpp"
#include "mesh/io/mesh_io.hpp"
#include "mesh/quality_summary.hpp"

namespace tetsmooth::cli {

void run_generate(const GenerateCommand& c, const Console& console) {
  const MeshFormat format = format_from_path(c.output, c.output_format);
  check_mesh_output_location(c.output, format);
  const TetMesh mesh = generate_model(c.model, c.seed);
  write_mesh_with_fields(mesh, c.output, format);
  if (console.quiet) return;
  const QualitySummary q = summarize_quality(mesh);
  const std::string seed =
      model_uses_seed(c.model) ? "seed " + std::to_string(c.seed) : "fixed: --seed does not change it";
  console.note("wrote " + c.output + ": " + c.model + " (" + seed + "), " +
               with_thousands(mesh.num_nodes()) + " nodes, " + with_thousands(mesh.num_tets()) +
               " tets, radius ratio min " + quality_text(q.min) + " mean " + quality_text(q.mean) + " (" +
               format_name(format) + ")");
}

}  // namespace tetsmooth::cli
