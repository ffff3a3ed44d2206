#include <algorithm>
#include <cstdio>
#include <limits>
#include <utility>
#include <vector>

#include "mesh/io/atomic_file.hpp"
#include "mesh/io/field_check.hpp"
#include "mesh/io/number_text.hpp"
#include "mesh/io/vtk_cells.hpp"
#include "mesh/io/vtk_legacy.hpp"

namespace tetsmooth {
namespace {

// Legacy VTK names are single tokens: VTK percent-encodes what would break
// them, and its reader decodes the same way.
std::string encode_name(const std::string& name) {
  std::string out;
  for (unsigned char c : name) {
    if (c <= ' ' || c == '%' || c >= 0x7F) {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += hex;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out.empty() ? "unnamed" : out;
}

// n tuples of `components` values, get(out, i) writing tuple i.
template <class Get>
void write_scalars(std::ostream& out, const std::string& name, const char* type, std::size_t n, Get get,
                   int components = 1) {
  out << "SCALARS " << encode_name(name) << ' ' << type << ' ' << components << "\nLOOKUP_TABLE default\n";
  for (std::size_t i = 0; i < n; ++i) {
    get(out, i);
    out << '\n';
  }
}

}  // namespace

void write_vtk(const TetMesh& mesh, std::ostream& out, const MeshFields& fields) {
  check_field_sizes(mesh, fields);
  const VtkCells cells = vtk_cells_of(mesh);
  const std::size_t n = mesh.num_nodes();
  out << "# vtk DataFile Version 4.2\ntetsmooth mesh\nASCII\nDATASET UNSTRUCTURED_GRID\n";
  out << "POINTS " << n << " double\n";
  for (std::size_t i = 0; i < n; ++i) {
    for (int k = 0; k < 3; ++k) {
      if (k) out << ' ';
      put_real(out, mesh.xyz[3 * i + k]);
    }
    out << '\n';
  }
  out << "CELLS " << cells.size() << ' ' << cells.size() + cells.connectivity.size() << '\n';
  for (std::size_t c = 0; c < cells.size(); ++c) {
    put_integer(out, cells.offsets[c + 1] - cells.offsets[c]);
    for (auto k = cells.offsets[c]; k < cells.offsets[c + 1]; ++k) {
      out << ' ';
      put_integer(out, cells.connectivity[static_cast<std::size_t>(k)]);
    }
    out << '\n';
  }
  out << "CELL_TYPES " << cells.size() << '\n';
  for (std::uint8_t t : cells.types) out << static_cast<int>(t) << '\n';

  if (!fields.tet_scalars.empty() || !cells.tags.empty() || !cells.entities.empty()) {
    out << "CELL_DATA " << cells.size() << '\n';
    const std::size_t tets = mesh.num_tets();
    for (const auto& [name, values] : fields.tet_scalars)
      write_scalars(out, name, "double", cells.size(), [&v = values, tets](std::ostream& o, std::size_t i) {
        put_real(o, i < tets ? v[i] : std::numeric_limits<double>::quiet_NaN());
      });
    for (const auto& [name, values] : cells.named_int_arrays())
      if (!values->empty())
        write_scalars(out, name, "int", cells.size(),
                      [&t = *values](std::ostream& o, std::size_t i) { put_integer(o, t[i]); });
  }
  const bool any_fixed = std::any_of(mesh.fixed.begin(), mesh.fixed.end(), [](std::uint8_t f) { return f != 0; });
  const FileExtras& e = mesh.extras;
  const bool classified = e.node_entity_dims.size() == n && e.node_entity_tags.size() == n;
  if (!fields.node_scalars.empty() || any_fixed || classified) {
    out << "POINT_DATA " << n << '\n';
    for (const auto& [name, values] : fields.node_scalars)
      write_scalars(out, name, "double", n, [&v = values](std::ostream& o, std::size_t i) { put_real(o, v[i]); });
    if (any_fixed)
      write_scalars(out, kVtkFixedArray, "int", n,
                    [&f = mesh.fixed](std::ostream& o, std::size_t i) { put_integer(o, f[i] != 0); });
    if (classified)
      write_scalars(
          out, kVtkNodeEntityArray, "int", n,
          [&e](std::ostream& o, std::size_t i) {
            put_integer(o, e.node_entity_dims[i]);
            o << ' ';
            put_integer(o, e.node_entity_tags[i]);
          },
          2);
  }
}

void write_vtk_file(const TetMesh& mesh, const std::string& path, const MeshFields& fields) {
  check_vtk_blocks(mesh, "cannot write '" + path + "'");
  write_atomically(path, [&](std::ostream& out) { write_vtk(mesh, out, fields); });
}

}  // namespace tetsmooth
