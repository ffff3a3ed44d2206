#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <string_view>
#include <utility>
#include <vector>

#include "mesh/io/atomic_file.hpp"
#include "mesh/io/field_check.hpp"
#include "mesh/io/little_endian.hpp"
#include "mesh/io/vtk_cells.hpp"
#include "mesh/io/vtu_io.hpp"
#include "mesh/io/xml_scan.hpp"

namespace tetsmooth {
namespace {

// One appended array: where it is declared, how it is typed, and how its
// values are produced.
struct Array {
  const char* section;  // PointData, CellData, Points, Cells
  std::string name;
  const char* vtk_type;
  int components;
  std::size_t bytes;
  std::function<void(std::ostream&)> write;
};

// Writes the UInt64 byte count, then n values of type T from get(i).
template <class T, class Get>
void write_block(std::ostream& out, std::size_t n, Get get) {
  unsigned char header[8];
  store_le<std::uint64_t>(header, n * sizeof(T));
  out.write(reinterpret_cast<const char*>(header), sizeof header);
  constexpr std::size_t kChunk = 1 << 14;
  std::vector<unsigned char> buf(kChunk * sizeof(T));
  for (std::size_t i = 0; i < n; i += kChunk) {
    const std::size_t m = std::min(kChunk, n - i);
    for (std::size_t k = 0; k < m; ++k) store_le<T>(&buf[k * sizeof(T)], get(i + k));
    out.write(reinterpret_cast<const char*>(buf.data()), static_cast<std::streamsize>(m * sizeof(T)));
  }
}

template <class T, class Get>
Array make_array(const char* section, std::string name, const char* vtk_type, int components, std::size_t n, Get get) {
  return Array{section,    std::move(name), vtk_type,
               components, n * sizeof(T),   [n, get](std::ostream& out) { write_block<T>(out, n, get); }};
}

std::vector<Array> arrays_of(const TetMesh& mesh, const VtkCells& cells, const MeshFields& fields) {
  std::vector<Array> arrays;
  for (const auto& [name, values] : fields.node_scalars)
    arrays.push_back(make_array<double>("PointData", name, "Float64", 1, values.size(),
                                        [&v = values](std::size_t i) { return v[i]; }));
  if (std::any_of(mesh.fixed.begin(), mesh.fixed.end(), [](std::uint8_t f) { return f != 0; }))
    arrays.push_back(make_array<std::uint8_t>("PointData", kVtkFixedArray, "UInt8", 1, mesh.fixed.size(),
                                              [&f = mesh.fixed](std::size_t i) { return std::uint8_t(f[i] != 0); }));
  const FileExtras& e = mesh.extras;
  const std::size_t n = mesh.num_nodes();
  if (e.node_entity_dims.size() == n && e.node_entity_tags.size() == n)
    arrays.push_back(make_array<std::int32_t>("PointData", kVtkNodeEntityArray, "Int32", 2, 2 * n, [&e](std::size_t i) {
      return std::int32_t(i % 2 == 0 ? e.node_entity_dims[i / 2] : e.node_entity_tags[i / 2]);
    }));
  const std::size_t tets = mesh.num_tets();
  for (const auto& [name, values] : fields.tet_scalars)
    arrays.push_back(make_array<double>(
        "CellData", name, "Float64", 1, cells.size(),
        [&v = values, tets](std::size_t i) { return i < tets ? v[i] : std::numeric_limits<double>::quiet_NaN(); }));
  for (const auto& [name, values] : cells.named_int_arrays())
    if (!values->empty())
      arrays.push_back(make_array<std::int32_t>("CellData", name, "Int32", 1, values->size(),
                                                [&t = *values](std::size_t i) { return std::int32_t(t[i]); }));
  arrays.push_back(make_array<double>("Points", "Points", "Float64", 3, mesh.xyz.size(),
                                      [&x = mesh.xyz](std::size_t i) { return x[i]; }));
  arrays.push_back(make_array<std::int32_t>("Cells", "connectivity", "Int32", 1, cells.connectivity.size(),
                                            [&c = cells.connectivity](std::size_t i) { return c[i]; }));
  // VTK XML offsets are the end of each cell: the leading 0 is implicit.
  arrays.push_back(make_array<std::int64_t>("Cells", "offsets", "Int64", 1, cells.size(),
                                            [&o = cells.offsets](std::size_t i) { return o[i + 1]; }));
  arrays.push_back(make_array<std::uint8_t>("Cells", "types", "UInt8", 1, cells.size(),
                                            [&t = cells.types](std::size_t i) { return t[i]; }));
  return arrays;
}

}  // namespace

void write_vtu(const TetMesh& mesh, std::ostream& out, const MeshFields& fields) {
  check_field_sizes(mesh, fields);
  const VtkCells cells = vtk_cells_of(mesh);
  const std::vector<Array> arrays = arrays_of(mesh, cells, fields);

  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
         "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << mesh.num_nodes() << "\" NumberOfCells=\"" << cells.size() << "\">\n";
  for (const std::string_view section : {"PointData", "CellData", "Points", "Cells"}) {
    out << "      <" << section << ">\n";
    std::uint64_t at = 0;  // the array's offset: the bytes of all arrays before it
    for (const Array& a : arrays) {
      if (a.section == section)
        out << "        <DataArray type=\"" << a.vtk_type << "\" Name=\"" << xml_escape(a.name)
            << "\" NumberOfComponents=\"" << a.components << "\" format=\"appended\" offset=\"" << at << "\"/>\n";
      at += 8 + a.bytes;
    }
    out << "      </" << section << ">\n";
  }
  out << "    </Piece>\n"
         "  </UnstructuredGrid>\n"
         "  <AppendedData encoding=\"raw\">\n"
         "   _";
  for (const Array& a : arrays) a.write(out);
  out << "\n  </AppendedData>\n"
         "</VTKFile>\n";
}

void write_vtu_file(const TetMesh& mesh, const std::string& path, const MeshFields& fields) {
  check_vtk_blocks(mesh, "cannot write '" + path + "'");
  write_atomically(
      path, [&](std::ostream& out) { write_vtu(mesh, out, fields); }, true);
}

}  // namespace tetsmooth
