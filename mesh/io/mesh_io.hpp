#pragma once
// Reading and writing meshes by file format. Every reader validates what it
// reads (mesh/validate.hpp) and throws InputError naming the file and the
// line (text formats) or byte offset (binary formats) at fault. Every writer
// writes to a temporary file beside the target and renames it into place, so
// a failed write never leaves a partial file; failures throw OutputError.
#include <string>
#include <utility>
#include <vector>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

enum class MeshFormat {
  Auto,         // from the file name
  TetGen,       // X.node + X.ele (either name given, or the base name)
  Vtu,          // VTK XML UnstructuredGrid .vtu
  Vtk,          // legacy VTK .vtk (ASCII)
  Msh41,        // Gmsh MSH 4.1 ASCII .msh (reading detects any MSH version/binary)
  Msh41Binary,  // Gmsh MSH 4.1 binary
  Msh22,        // Gmsh MSH 2.2 ASCII
  Medit,        // Medit .mesh ASCII
  Cache,        // tetsmooth binary cache .tsm
  Abaqus,       // Abaqus/CalculiX input deck .inp
  Nastran,      // Nastran bulk data .bdf, .nas
  Flac3d,       // FLAC3D grid .f3grid, .flac3d (text or binary; new grids are text)
  Exodus,       // Exodus II .exo, .e, .ex2, .g, .gen (netCDF; exodus_io.hpp)
  Ansys,        // ANSYS Mechanical APDL archive .cdb (ansys_io.hpp)
  Lsdyna,       // LS-DYNA keyword deck .k, .key, .dyn (lsdyna_io.hpp)
};

// Parses a --format value ("tetgen", "vtu", "vtk", "msh", "msh41", "msh41-binary",
// "msh22", "medit", "tsm", "abaqus" or "inp", "nastran" or "bdf", "flac3d" or "f3grid", "exodus" or "exo", "ansys" or "cdb", "lsdyna" or "k"); throws UsageError for anything else.
MeshFormat parse_format(const std::string& name);
const char* format_name(MeshFormat f);

// Resolves Auto from the extension; throws UsageError for an unknown one.
MeshFormat format_from_path(const std::string& path, MeshFormat requested = MeshFormat::Auto);

// The same for a file to be read, which may also be a TetGen base name: a
// path without extension beside which path.node exists is TetGen.
MeshFormat input_format_of(const std::string& path, MeshFormat requested = MeshFormat::Auto);

// Per-node and per-tet scalar fields for writers that can carry them (VTU, VTK,
// MSH as $NodeData/$ElementData); others ignore them.
struct MeshFields {
  std::vector<std::pair<std::string, std::vector<double>>> node_scalars;
  std::vector<std::pair<std::string, std::vector<double>>> tet_scalars;
};

TetMesh read_mesh(const std::string& path, MeshFormat format = MeshFormat::Auto);
void write_mesh(const TetMesh& mesh, const std::string& path, MeshFormat format = MeshFormat::Auto,
                const MeshFields& fields = {});

}  // namespace tetsmooth
