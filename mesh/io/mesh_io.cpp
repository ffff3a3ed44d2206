#include "mesh/io/mesh_io.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>

#include "mesh/errors.hpp"
#include "mesh/io/abaqus_io.hpp"
#include "mesh/io/ansys_io.hpp"
#include "mesh/io/exodus_io.hpp"
#include "mesh/io/flac3d_io.hpp"
#include "mesh/io/gmsh_io.hpp"
#include "mesh/io/lsdyna_io.hpp"
#include "mesh/io/medit_io.hpp"
#include "mesh/io/nastran_io.hpp"
#include "mesh/io/tetgen_io.hpp"
#include "mesh/io/tsm_cache.hpp"
#include "mesh/io/vtk_legacy.hpp"
#include "mesh/io/vtu_io.hpp"

namespace tetsmooth {
namespace {

struct FormatName {
  const char* name;
  MeshFormat format;
};
// The first name of each format is the one format_name gives.
constexpr FormatName kNames[] = {
    {"auto", MeshFormat::Auto},
    {"tetgen", MeshFormat::TetGen},
    {"vtu", MeshFormat::Vtu},
    {"vtk", MeshFormat::Vtk},
    {"msh41", MeshFormat::Msh41},
    {"msh", MeshFormat::Msh41},
    {"msh41-binary", MeshFormat::Msh41Binary},
    {"msh22", MeshFormat::Msh22},
    {"medit", MeshFormat::Medit},
    {"tsm", MeshFormat::Cache},
    {"abaqus", MeshFormat::Abaqus},
    {"inp", MeshFormat::Abaqus},
    {"nastran", MeshFormat::Nastran},
    {"bdf", MeshFormat::Nastran},
    {"flac3d", MeshFormat::Flac3d},
    {"f3grid", MeshFormat::Flac3d},
    {"exodus", MeshFormat::Exodus},
    {"exo", MeshFormat::Exodus},
    {"ansys", MeshFormat::Ansys},
    {"cdb", MeshFormat::Ansys},
    {"lsdyna", MeshFormat::Lsdyna},
    {"k", MeshFormat::Lsdyna},
};

struct Extension {
  const char* ext;
  MeshFormat format;
};
constexpr Extension kExtensions[] = {
    {".node", MeshFormat::TetGen}, {".ele", MeshFormat::TetGen}, {".vtu", MeshFormat::Vtu},   {".vtk", MeshFormat::Vtk},
    {".msh", MeshFormat::Msh41},   {".mesh", MeshFormat::Medit}, {".tsm", MeshFormat::Cache},
    {".inp", MeshFormat::Abaqus},  {".bdf", MeshFormat::Nastran}, {".nas", MeshFormat::Nastran},
    {".f3grid", MeshFormat::Flac3d}, {".flac3d", MeshFormat::Flac3d},
    {".exo", MeshFormat::Exodus},  {".e", MeshFormat::Exodus}, {".ex2", MeshFormat::Exodus},
    {".g", MeshFormat::Exodus},    {".gen", MeshFormat::Exodus}, {".cdb", MeshFormat::Ansys},
    {".k", MeshFormat::Lsdyna},    {".key", MeshFormat::Lsdyna}, {".dyn", MeshFormat::Lsdyna},
};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

std::string extension_of(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  const std::size_t dot = path.rfind('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  return lower(path.substr(dot));
}

bool is_file(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

}  // namespace

MeshFormat parse_format(const std::string& name) {
  const std::string key = lower(name);
  for (const FormatName& f : kNames)
    if (key == f.name) return f.format;
  throw UsageError("unknown mesh format '" + name +
                   "' (expected tetgen, vtu, vtk, msh, msh41, msh41-binary, msh22, medit, tsm, abaqus, nastran, flac3d, exodus, ansys or lsdyna)");
}

const char* format_name(MeshFormat f) {
  for (const FormatName& n : kNames)
    if (n.format == f) return n.name;
  return "unknown";
}

MeshFormat format_from_path(const std::string& path, MeshFormat requested) {
  if (requested != MeshFormat::Auto) return requested;
  const std::string ext = extension_of(path);
  for (const Extension& e : kExtensions)
    if (ext == e.ext) return e.format;
  throw UsageError("cannot tell the mesh format of '" + path +
                   "' from its name: use .node/.ele, .vtu, .vtk, .msh, .mesh, .inp, .bdf/.nas, .f3grid/.flac3d, .exo/.e/.g, .cdb, .k/.key/.dyn or .tsm, or name the format "
                   "(--format for an input, --output-format for an output)");
}

MeshFormat input_format_of(const std::string& path, MeshFormat requested) {
  // A TetGen base name ("box" for box.node + box.ele) has no extension.
  if (requested == MeshFormat::Auto && extension_of(path).empty() && is_file(path + ".node")) return MeshFormat::TetGen;
  return format_from_path(path, requested);
}

TetMesh read_mesh(const std::string& path, MeshFormat format) {
  switch (input_format_of(path, format)) {
    case MeshFormat::TetGen:
      return read_tetgen(path);
    case MeshFormat::Vtu:
      return read_vtu_file(path);
    case MeshFormat::Vtk:
      return read_vtk_file(path);
    case MeshFormat::Msh41:
    case MeshFormat::Msh41Binary:
    case MeshFormat::Msh22:
      return read_gmsh_file(path);
    case MeshFormat::Medit:
      return read_medit_file(path);
    case MeshFormat::Cache:
      return read_cache_file(path);
    case MeshFormat::Abaqus:
      return read_abaqus_file(path);
    case MeshFormat::Nastran:
      return read_nastran_file(path);
    case MeshFormat::Flac3d:
      return read_flac3d_file(path);
    case MeshFormat::Exodus:
      return read_exodus_file(path);
    case MeshFormat::Ansys:
      return read_ansys_file(path);
    case MeshFormat::Lsdyna:
      return read_lsdyna_file(path);
    case MeshFormat::Auto:
      break;
  }
  throw UsageError("no reader for format " + std::string(format_name(format)));
}

void write_mesh(const TetMesh& mesh, const std::string& path, MeshFormat format, const MeshFields& fields) {
  switch (format_from_path(path, format)) {
    case MeshFormat::TetGen:
      return write_tetgen(mesh, path);
    case MeshFormat::Vtu:
      return write_vtu_file(mesh, path, fields);
    case MeshFormat::Vtk:
      return write_vtk_file(mesh, path, fields);
    case MeshFormat::Msh41:
      return write_gmsh_file(mesh, path, MshFlavour::V41Ascii, fields);
    case MeshFormat::Msh41Binary:
      return write_gmsh_file(mesh, path, MshFlavour::V41Binary, fields);
    case MeshFormat::Msh22:
      return write_gmsh_file(mesh, path, MshFlavour::V22Ascii, fields);
    case MeshFormat::Medit:
      return write_medit_file(mesh, path);
    case MeshFormat::Cache:
      return write_cache_file(mesh, path);
    case MeshFormat::Abaqus:
      return write_abaqus_file(mesh, path);
    case MeshFormat::Nastran:
      return write_nastran_file(mesh, path);
    case MeshFormat::Flac3d:
      return write_flac3d_file(mesh, path);
    case MeshFormat::Exodus:
      return write_exodus_file(mesh, path);
    case MeshFormat::Ansys:
      return write_ansys_file(mesh, path);
    case MeshFormat::Lsdyna:
      return write_lsdyna_file(mesh, path);
    case MeshFormat::Auto:
      break;
  }
  throw UsageError("no writer for format " + std::string(format_name(format)));
}

}  // namespace tetsmooth
