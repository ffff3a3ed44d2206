#include "apps/output_fields.hpp"

#include "mesh/quality_summary.hpp"
#include "mesh/topology.hpp"

namespace tetsmooth::cli {

bool format_carries_fields(MeshFormat format) {
  switch (format) {
    case MeshFormat::Vtu:
    case MeshFormat::Vtk:
    case MeshFormat::Msh41:
    case MeshFormat::Msh41Binary:
    case MeshFormat::Msh22: return true;
    default: return false;
  }
}

MeshFields quality_fields(const TetMesh& mesh) {
  MeshFields fields;
  fields.tet_scalars.emplace_back("quality", tet_qualities(mesh));
  // On all cores, as tet_qualities.
  const std::vector<std::uint8_t> boundary = find_boundary_nodes(mesh.tets, mesh.num_nodes(), 0, mesh.midsides);
  fields.node_scalars.emplace_back("boundary", std::vector<double>(boundary.begin(), boundary.end()));
  return fields;
}

void write_mesh_with_fields(const TetMesh& mesh, const std::string& path, MeshFormat format) {
  write_mesh(mesh, path, format, format_carries_fields(format) ? quality_fields(mesh) : MeshFields{});
}

}  // namespace tetsmooth::cli
