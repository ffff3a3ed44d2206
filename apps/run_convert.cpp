// tetsmooth convert: read in one format, write in another.
#include "apps/commands.hpp"
#include "apps/input_warnings.hpp"
#include "apps/option_names.hpp"
#include "apps/output_check.hpp"
#include "apps/output_fields.hpp"
#include "apps/report_text.hpp"
#include "mesh/io/mesh_io.hpp"
#include "mesh/io/writable_check.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth::cli {

void run_convert(const ConvertCommand& c, const Console& console) {
  const MeshFormat input_format = input_format_of(c.input, c.input_format);
  const MeshFormat output_format = format_from_path(c.output, c.output_format);
  check_mesh_output_location(c.output, output_format);
  const TetMesh mesh = read_mesh(c.input, input_format);
  check_writable(mesh, c.output, output_format);
  for (const std::string& loss : output_losses(mesh, c.output, output_format)) console.warn(c.output + ": " + loss);
  for (const std::string& w : input_warnings(mesh, inspect_input(mesh, c.input), c.input)) console.warn(w);
  if (writes_over_input(c.input, input_format, c.output, output_format))
    console.warn(c.output + " is the input mesh: it will be replaced once the whole result is written");
  write_mesh_with_fields(mesh, c.output, output_format);
  console.note("wrote " + c.output + ": " + with_thousands(mesh.num_nodes()) + " nodes, " +
               with_thousands(mesh.num_tets()) + " tets (" + input_format_name(input_format) + " -> " +
               format_name(output_format) + ")");
}

}  // namespace tetsmooth::cli
