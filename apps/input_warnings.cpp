#include "apps/input_warnings.hpp"

#include <cstdio>
#include <string>

#include "apps/report_text.hpp"
#include "mesh/bounding_box.hpp"
#include "mesh/topology.hpp"

namespace tetsmooth::cli {

namespace {

std::string three_digits(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// Edges the double radius ratio holds (mesh/tet_quality.hpp: it forms
// products of up to eight edge lengths).
constexpr double kLargestEdge = 1e35, kSmallestEdge = 1e-35;

}  // namespace

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
    warnings.push_back(source + ": " + counted(report.inverted, "inverted tet", "inverted tets") +
                       " (negative volume)" +
                       (all_inverted ? std::string(report.tets == 1 ? ", the only one" : ", all of them") +
                                           ": the file probably lists each tet's nodes in the opposite order "
                                           "(tetsmooth expects (b-a).((c-a)x(d-a)) > 0)"
                                     : "") +
                       (inverted_note.empty() ? "" : "; " + inverted_note));
  if (report.degenerate > 0)
    warnings.push_back(source + ": " + counted(report.degenerate, "degenerate tet", "degenerate tets") +
                       " (zero volume or a repeated node)");
  if (report.repeated > 0)
    warnings.push_back(source + ": " + counted(report.repeated, "tet repeats", "tets repeat") +
                       " the nodes of an earlier tet (Gmsh's MSH 2.2 writer lists a volume in two "
                       "physical groups twice); each node set counts as one tet for the boundary, and the "
                       "quality statistics count the tets as listed");
  const double span = bounding_box(mesh).largest_side();
  if (span > kLargestEdge || (span > 0 && span < kSmallestEdge))
    warnings.push_back(source + ": the nodes span " + three_digits(span) +
                       " units; the radius ratio, computed from products of up to eight edge lengths, "
                       "overflows or underflows double for edges beyond 1e35 or below 1e-35, and such tets "
                       "read q = 0 and never improve: scale the mesh (the quality does not depend on its size)");
  if (report.unreferenced > 0) {
    const std::string is = report.unreferenced == 1 ? "it is" : "they are";
    warnings.push_back(source + ": " + counted(report.unreferenced, "node belongs", "nodes belong") + " to no tet; " +
                       is + " kept as " + is);
  }
  return warnings;
}

}  // namespace tetsmooth::cli
