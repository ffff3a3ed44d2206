#include "mesh/io/writable_check.hpp"

#include <ostream>
#include <streambuf>

#include "mesh/errors.hpp"
#include "mesh/io/gmsh_io.hpp"
#include "mesh/io/medit_io.hpp"
#include "mesh/io/tetgen_io.hpp"
#include "mesh/io/tsm_cache.hpp"
#include "mesh/io/vtk_legacy.hpp"
#include "mesh/io/vtu_io.hpp"

namespace tetsmooth {
namespace {

// Accepts and drops every byte, so a writer runs to the end without failing.
class NullBuf : public std::streambuf {
 protected:
  int_type overflow(int_type ch) override { return traits_type::not_eof(ch); }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

// One tet over four nodes, and each of the mesh's blocks with its kind and
// no elements; tags are kept where the mesh has them, one per element.
TetMesh probe_of(const TetMesh& mesh) {
  TetMesh probe;
  probe.xyz = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  probe.tets = {0, 1, 2, 3};
  const FileExtras& e = mesh.extras;
  if (!e.tet_tags.empty()) probe.extras.tet_tags = {e.tet_tags.front()};
  if (!e.tet_entity_tags.empty()) probe.extras.tet_entity_tags = {e.tet_entity_tags.front()};
  for (const PassThroughBlock& b : e.blocks)
    probe.extras.blocks.push_back(PassThroughBlock{b.kind, b.nodes_per_element, {}, {}, {}});
  return probe;
}

void write_probe(const TetMesh& probe, MeshFormat format, std::ostream& out) {
  switch (format) {
    case MeshFormat::TetGen:
      write_tetgen_node(probe, out);
      return write_tetgen_ele(probe, out);
    case MeshFormat::Vtu:
      return write_vtu(probe, out, {});
    case MeshFormat::Vtk:
      return write_vtk(probe, out, {});
    case MeshFormat::Msh41:
      return write_gmsh(probe, out, MshFlavour::V41Ascii, {});
    case MeshFormat::Msh41Binary:
      return write_gmsh(probe, out, MshFlavour::V41Binary, {});
    case MeshFormat::Msh22:
      return write_gmsh(probe, out, MshFlavour::V22Ascii, {});
    case MeshFormat::Medit:
      return write_medit(probe, out);
    case MeshFormat::Cache:
      return write_cache(probe, out);
    case MeshFormat::Auto:
      break;
  }
}

}  // namespace

void check_writable(const TetMesh& mesh, const std::string& path, MeshFormat format) {
  NullBuf nowhere;
  std::ostream out(&nowhere);
  try {
    write_probe(probe_of(mesh), format_from_path(path, format), out);
  } catch (const OutputError& e) {
    throw OutputError("cannot write '" + path + "': " + e.what());
  }
}

}  // namespace tetsmooth
