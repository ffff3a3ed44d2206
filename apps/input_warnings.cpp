#include "apps/input_warnings.hpp"

#include "apps/report_text.hpp"
#include "mesh/topology.hpp"

namespace tetsmooth::cli {

ValidationReport inspect_input(const TetMesh& mesh, const std::string& source) {
  ValidationReport report = validate_mesh(mesh, source);
  report.repeated = count_repeated_tets(mesh.tets);
  return report;
}

std::vector<std::string> input_warnings(const TetMesh& mesh, const ValidationReport& report, const std::string& source,
                                        const std::string& inverted_note) {
  std::vector<std::string> warnings;
  for (const std::string& note : mesh.extras.read_notes) warnings.push_back(source + ": " + note);
  // Every tet inverted is a mesh in the other orientation rather than a
  // tangled one: worth saying, since no smoothing can help it.
  const bool all_inverted = report.inverted > 0 && report.inverted == report.tets;
  if (report.inverted > 0)
    warnings.push_back(source + ": " + with_thousands(report.inverted) + " inverted tets (negative volume)" +
                       (all_inverted ? ", all of them: the file probably lists each tet's nodes in the opposite "
                                       "order (tetsmooth expects (b-a).((c-a)x(d-a)) > 0)"
                                     : "") +
                       (inverted_note.empty() ? "" : "; " + inverted_note));
  if (report.degenerate > 0)
    warnings.push_back(source + ": " + with_thousands(report.degenerate) +
                       " degenerate tets (zero volume or a repeated node)");
  if (report.repeated > 0)
    warnings.push_back(source + ": " + with_thousands(report.repeated) +
                       " tets repeat the nodes of an earlier tet (Gmsh's MSH 2.2 writer lists a volume in two "
                       "physical groups twice); each node set counts as one tet for the boundary, and the "
                       "quality statistics count the tets as listed");
  if (report.unreferenced > 0)
    warnings.push_back(source + ": " + with_thousands(report.unreferenced) +
                       " nodes belong to no tet; they are kept as they are");
  return warnings;
}

}  // namespace tetsmooth::cli
