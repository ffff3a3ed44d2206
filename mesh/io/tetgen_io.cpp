#include "mesh/io/tetgen_io.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "mesh/errors.hpp"
#include "mesh/second_order.hpp"
#include "mesh/io/atomic_file.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/number_text.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {
namespace {

// Where TetGen's 10-node tets (its -o2 switch) put the midside node of each
// edge of kTetEdges: TetGen lists the edges (2,3), (0,3), (0,1), (1,2),
// (1,3), (0,2), as libtet 1.5 gives them (TetGenOrderIsLibtets in
// tests/test_io_second_order.cpp checks this against libtet).
constexpr MidsidePlaces kTetGenMidsidePlaces = {6, 7, 9, 5, 8, 4};

bool ends_with(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// A header count, bounded so that a corrupt header cannot ask for more
// entries than 32-bit indices can address.
std::size_t count_field(const TextLines& lines, std::size_t i, const char* what) {
  const long long n = lines.integer(i, what);
  if (n < 0 || n > std::numeric_limits<index_t>::max())
    lines.fail(std::string("invalid ") + what + " " + std::to_string(n));
  return static_cast<std::size_t>(n);
}

// Reserving for a claimed count, capped: a truncated or lying header must end
// in a clean "unexpected end of file", not an allocation failure.
std::size_t capped(std::size_t n) { return std::min<std::size_t>(n, std::size_t{1} << 20); }

// More entries than the header declares means the header is wrong, and
// reading only the declared ones would silently drop part of the mesh.
void expect_end(TextLines& lines, std::size_t count, const char* what) {
  if (lines.next_line())
    lines.fail("more data than the " + std::to_string(count) + " " + what + " the header declares");
}

// The region attribute of each tet (the first of `attrs` a tet) becomes its
// tag: the value itself where all are whole numbers in int range, else its
// rank among the distinct values (1 for the lowest), with a note. What the
// tags cannot give back stays in tet_attributes.
void take_tet_attributes(std::vector<double> values, std::size_t attrs, FileExtras& extras) {
  extras.tet_tags.clear();
  extras.tet_attributes.clear();
  extras.tet_attribute_count = 0;
  if (attrs == 0) return;
  const std::size_t tets = values.size() / attrs;
  std::vector<double> regions(tets);
  for (std::size_t t = 0; t < tets; ++t) regions[t] = values[t * attrs];
  const auto not_whole = std::find_if(regions.begin(), regions.end(), [](double v) {
    return v != std::floor(v) || v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max();
  });
  extras.tet_tags.reserve(tets);
  if (not_whole == regions.end()) {
    for (double v : regions) extras.tet_tags.push_back(static_cast<int>(v));
  } else {
    std::ostringstream example;
    put_real(example, *not_whole);
    std::vector<double> distinct = regions;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    for (double v : regions)
      extras.tet_tags.push_back(
          1 + static_cast<int>(std::lower_bound(distinct.begin(), distinct.end(), v) - distinct.begin()));
    const std::string tagged =
        distinct.size() == 1
            ? "the one region is tagged 1"
            : "the " + std::to_string(distinct.size()) + " regions are tagged 1, 2, ... in ascending order of value";
    extras.read_notes.push_back("region attribute " + example.str() + " is not a whole number in int range: " +
                                tagged + " (TetGen output writes the attributes back as they were)");
  }
  if (not_whole != regions.end() || attrs > 1) {
    extras.tet_attribute_count = static_cast<int>(attrs);
    extras.tet_attributes = std::move(values);
  }
}

// A tet attribute as TetGen and meshio read it: whole numbers as integers
// (meshio reads .ele attributes as ints and fails on "1e+06"), the rest in
// the shortest form that reads back exactly.
void put_attribute(std::ostream& out, double v) {
  if (v == std::floor(v) && std::abs(v) < 0x1p53 && !(v == 0 && std::signbit(v)))
    put_integer(out, static_cast<long long>(v));
  else
    put_real(out, v);
}

}  // namespace

std::string tetgen_base(const std::string& path) {
  for (const char* ext : {".node", ".ele"})
    if (ends_with(path, ext)) return path.substr(0, path.size() - std::char_traits<char>::length(ext));
  return path;
}

int read_tetgen_node(std::istream& in, const std::string& source, TetMesh& mesh) {
  TextLines lines(in, source);
  lines.require_line("the .node header \"<#nodes> 3 <#attributes> <markers 0|1>\"");
  const std::size_t count = count_field(lines, 0, "node count");
  if (count == 0) lines.fail("the .node file declares no nodes");
  if (const long long dim = lines.size() > 1 ? lines.integer(1, "dimension") : 3; dim != 3)
    lines.fail("dimension " + std::to_string(dim) + " is not supported, only 3");
  const std::size_t attrs = lines.size() > 2 ? count_field(lines, 2, "attribute count") : 0;
  const long long markers = lines.size() > 3 ? lines.integer(3, "boundary marker flag") : 0;
  if (markers != 0 && markers != 1) lines.fail("boundary marker flag must be 0 or 1, found " + std::to_string(markers));

  mesh.xyz.clear();
  mesh.xyz.reserve(3 * capped(count));
  mesh.extras.node_attribute_count = static_cast<int>(attrs);
  mesh.extras.node_attributes.clear();
  mesh.extras.node_markers.clear();
  long long first = 0;
  for (std::size_t i = 0; i < count; ++i) {
    lines.require_line("node " + std::to_string(i + 1) + " of " + std::to_string(count));
    const long long number = lines.integer(0, "node number");
    if (i == 0) {
      if (number != 0 && number != 1)
        lines.fail("the first node number must be 0 or 1, found " + std::to_string(number));
      first = number;
    } else if (number != first + static_cast<long long>(i)) {
      lines.fail("node number " + std::to_string(number) + " out of sequence, expected " +
                 std::to_string(first + static_cast<long long>(i)));
    }
    for (std::size_t k = 0; k < 3; ++k) mesh.xyz.push_back(lines.real(1 + k, "coordinate"));
    for (std::size_t k = 0; k < attrs; ++k) mesh.extras.node_attributes.push_back(lines.real(4 + k, "node attribute"));
    if (markers != 0) {
      const long long marker = lines.whole_number(4 + attrs, "boundary marker");
      if (marker < std::numeric_limits<int>::min() || marker > std::numeric_limits<int>::max())
        lines.fail("boundary marker " + std::to_string(marker) + " out of range");
      mesh.extras.node_markers.push_back(static_cast<int>(marker));
    }
  }
  expect_end(lines, count, "nodes");
  return static_cast<int>(first);
}

void read_tetgen_ele(std::istream& in, const std::string& source, int first_index, TetMesh& mesh) {
  TextLines lines(in, source);
  lines.require_line("the .ele header \"<#tets> <4|10> <#attributes>\"");
  const std::size_t count = count_field(lines, 0, "tet count");
  if (count == 0) lines.fail("the .ele file declares no tets");
  const long long per_tet = lines.size() > 1 ? lines.integer(1, "nodes per tet") : 4;
  if (per_tet != 4 && per_tet != 10) lines.fail("nodes per tet must be 4 or 10, found " + std::to_string(per_tet));
  const auto nodes = static_cast<std::size_t>(per_tet);
  const std::size_t attrs = lines.size() > 2 ? count_field(lines, 2, "attribute count") : 0;

  const long long num_nodes = static_cast<long long>(mesh.num_nodes());
  mesh.tets.clear();
  mesh.midsides.clear();
  mesh.tets.reserve(4 * capped(count));
  if (nodes == 10) mesh.midsides.reserve(6 * capped(count));
  std::vector<double> attributes;
  attributes.reserve(capped(capped(count) * attrs));
  index_t tet[10];
  for (std::size_t t = 0; t < count; ++t) {
    lines.require_line("tet " + std::to_string(t + 1) + " of " + std::to_string(count));
    lines.integer(0, "tet number");
    for (std::size_t k = 0; k < nodes; ++k) {
      const long long node = lines.integer(1 + k, "node number");
      if (node < first_index || node - first_index >= num_nodes)
        lines.fail("node number " + std::to_string(node) + " out of range [" + std::to_string(first_index) + ", " +
                   std::to_string(num_nodes + first_index) + ")");
      tet[k] = static_cast<index_t>(node - first_index);
    }
    append_file_tet(mesh, tet, nodes == 10, kTetGenMidsidePlaces);
    for (std::size_t k = 0; k < attrs; ++k)
      attributes.push_back(lines.real(1 + nodes + k, k == 0 ? "region attribute" : "tet attribute"));
  }
  expect_end(lines, count, "tets");
  take_tet_attributes(std::move(attributes), attrs, mesh.extras);
}

TetMesh read_tetgen(std::istream& node, const std::string& node_source, std::istream& ele,
                    const std::string& ele_source) {
  TetMesh mesh;
  const int first = read_tetgen_node(node, node_source, mesh);
  read_tetgen_ele(ele, ele_source, first, mesh);
  validate_mesh(mesh, node_source, ele_source);
  return mesh;
}

TetMesh read_tetgen(const std::string& path) {
  const std::string base = tetgen_base(path);
  std::ifstream node = open_input(base + ".node");
  std::ifstream ele = open_input(base + ".ele");
  return read_tetgen(node, base + ".node", ele, base + ".ele");
}

void write_tetgen_node(const TetMesh& mesh, std::ostream& out) {
  const std::size_t n = mesh.num_nodes();
  const FileExtras& ex = mesh.extras;
  const std::size_t attrs = static_cast<std::size_t>(std::max(ex.node_attribute_count, 0));
  const bool has_attrs = attrs > 0 && ex.node_attributes.size() == attrs * n;
  const bool has_markers = ex.node_markers.size() == n;
  out << n << " 3 " << (has_attrs ? attrs : 0) << ' ' << (has_markers ? 1 : 0) << '\n';
  for (std::size_t i = 0; i < n; ++i) {
    put_integer(out, static_cast<long long>(i) + 1);
    for (int k = 0; k < 3; ++k) {
      out << ' ';
      put_real(out, mesh.xyz[3 * i + k]);
    }
    for (std::size_t k = 0; has_attrs && k < attrs; ++k) {
      out << ' ';
      put_real(out, ex.node_attributes[attrs * i + k]);
    }
    if (has_markers) {
      out << ' ';
      put_integer(out, ex.node_markers[i]);
    }
    out << '\n';
  }
  out << "# Generated by tetsmooth\n";
}

void write_tetgen_ele(const TetMesh& mesh, std::ostream& out) {
  const std::size_t t = mesh.num_tets();
  const FileExtras& ex = mesh.extras;
  const bool has_attrs = has_tet_attributes(ex, t);
  const std::size_t attrs = has_attrs ? static_cast<std::size_t>(ex.tet_attribute_count) : 0;
  const bool has_tags = !has_attrs && ex.tet_tags.size() == t;
  const bool second_order = !mesh.midsides.empty();
  out << t << (second_order ? " 10 " : " 4 ") << (has_attrs ? attrs : has_tags ? 1 : 0) << '\n';
  index_t tet[10];
  for (std::size_t e = 0; e < t; ++e) {
    put_integer(out, static_cast<long long>(e) + 1);
    if (second_order)
      file_tet10(mesh, e, kTetGenMidsidePlaces, tet);
    else
      std::copy(&mesh.tets[4 * e], &mesh.tets[4 * e] + 4, tet);
    for (int k = 0; k < (second_order ? 10 : 4); ++k) {
      out << ' ';
      put_integer(out, static_cast<long long>(tet[k]) + 1);
    }
    for (std::size_t k = 0; k < attrs; ++k) {
      out << ' ';
      put_attribute(out, ex.tet_attributes[attrs * e + k]);
    }
    if (has_tags) {
      out << ' ';
      put_integer(out, ex.tet_tags[e]);
    }
    out << '\n';
  }
  out << "# Generated by tetsmooth\n";
}

void write_tetgen(const TetMesh& mesh, const std::string& path) {
  const std::string base = tetgen_base(path);
  write_atomically({{base + ".node", [&](std::ostream& out) { write_tetgen_node(mesh, out); }},
                    {base + ".ele", [&](std::ostream& out) { write_tetgen_ele(mesh, out); }}});
}

}  // namespace tetsmooth
