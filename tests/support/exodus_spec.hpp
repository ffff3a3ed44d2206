#pragma once
// Exodus II files built from a plain description, for the tests and the
// fuzz target of the Exodus reader: any shape the netCDF data model allows,
// right or wrong as an Exodus file (node numbers out of range, sides that
// do not exist, types tetsmooth does not carry, ...). Header-only, so that
// the fuzz build (which compiles no test support library) can use it.
#include <netcdf.h>

#include <string>
#include <vector>

#include "mesh/io/netcdf/netcdf_dataset.hpp"

namespace tetsmooth::testing {

// An Exodus file as the tests build it: 1-based node numbers, as the file has them.
struct ExodusBlock {
  std::string type;
  int per = 4;
  std::vector<int> connect;
  int id = 0;
  std::string name;
};
struct ExodusSideSet {
  std::vector<int> elements, sides;
};
struct ExodusSpec {
  std::vector<double> xyz;  // packed x, y, z
  std::vector<ExodusBlock> blocks;
  std::vector<std::vector<int> > node_sets;
  std::vector<ExodusSideSet> side_sets;
  std::vector<int> node_map, element_map;
  bool coord = false;   // the older coord variable
  bool floats = false;  // 4-byte coordinates
  int dims = 3;
  bool results = false;  // a nodal variable over two time steps
};

inline std::string build_exodus(const ExodusSpec& s) {
  netcdf::NewDataset f(false);
  const std::size_t nodes = s.xyz.size() / 3;
  std::size_t elements = 0;
  for (const ExodusBlock& b : s.blocks) elements += b.connect.size() / static_cast<std::size_t>(b.per);
  f.int_attribute(-1, "floating_point_word_size", s.floats ? 4 : 8);
  f.text_attribute(-1, "title", "a test file");
  const int len_name = f.define_dimension("len_name", 33);
  // Two steps of results, else none (0 defines the unlimited dimension).
  const int time_step = f.define_dimension("time_step", s.results ? 2 : 0);
  const int num_dim = f.define_dimension("num_dim", static_cast<std::size_t>(s.dims));
  const int num_nodes = f.define_dimension("num_nodes", nodes);
  // Dimensions of length 0 are left out (0 would define the unlimited one).
  const int num_elem = elements == 0 ? -1 : f.define_dimension("num_elem", elements);
  const int num_el_blk = f.define_dimension("num_el_blk", s.blocks.size());
  const int real = s.floats ? NC_FLOAT : NC_DOUBLE;
  std::vector<int> coords;
  if (s.coord)
    coords.push_back(f.define_variable("coord", real, {num_dim, num_nodes}));
  else
    for (const char* name : {"coordx", "coordy", "coordz"})
      coords.push_back(f.define_variable(name, real, {num_nodes}));
  const int eb_prop1 = f.define_variable("eb_prop1", NC_INT, {num_el_blk});
  const int eb_names = f.define_variable("eb_names", NC_CHAR, {num_el_blk, len_name});
  std::vector<int> connect;
  for (std::size_t b = 0; b < s.blocks.size(); ++b) {
    const std::string n = std::to_string(b + 1);
    if (s.blocks[b].connect.empty()) {  // a null block has neither (a dimension of 0 would be the unlimited one)
      connect.push_back(-1);
      continue;
    }
    const int count =
        f.define_dimension("num_el_in_blk" + n, s.blocks[b].connect.size() / static_cast<std::size_t>(s.blocks[b].per));
    const int per = f.define_dimension("num_nod_per_el" + n, static_cast<std::size_t>(s.blocks[b].per));
    connect.push_back(f.define_variable("connect" + n, NC_INT, {count, per}));
    f.text_attribute(connect.back(), "elem_type", s.blocks[b].type);
  }
  const int node_map = s.node_map.empty() ? -1 : f.define_variable("node_num_map", NC_INT, {num_nodes});
  const int element_map =
      s.element_map.empty() || num_elem < 0 ? -1 : f.define_variable("elem_num_map", NC_INT, {num_elem});
  std::vector<int> node_sets, elem_ss, side_ss;
  if (!s.node_sets.empty()) f.define_dimension("num_node_sets", s.node_sets.size());
  for (std::size_t k = 0; k < s.node_sets.size(); ++k) {
    if (s.node_sets[k].empty()) {  // an empty set has neither (a dimension of 0 would be the unlimited one)
      node_sets.push_back(-1);
      continue;
    }
    const int d = f.define_dimension("num_nod_ns" + std::to_string(k + 1), s.node_sets[k].size());
    node_sets.push_back(f.define_variable("node_ns" + std::to_string(k + 1), NC_INT, {d}));
  }
  if (!s.side_sets.empty()) f.define_dimension("num_side_sets", s.side_sets.size());
  for (std::size_t k = 0; k < s.side_sets.size(); ++k) {
    const std::string n = std::to_string(k + 1);
    if (s.side_sets[k].elements.empty()) {
      elem_ss.push_back(-1);
      side_ss.push_back(-1);
      continue;
    }
    const int d = f.define_dimension("num_side_ss" + n, s.side_sets[k].elements.size());
    elem_ss.push_back(f.define_variable("elem_ss" + n, NC_INT, {d}));
    side_ss.push_back(f.define_variable("side_ss" + n, NC_INT, {d}));
  }
  int time_whole = -1, values = -1;
  if (s.results) {
    time_whole = f.define_variable("time_whole", NC_DOUBLE, {time_step});
    values = f.define_variable("vals_nod_var1", NC_DOUBLE, {time_step, num_nodes});
  }
  f.end_definitions();
  for (std::size_t c = 0; c < 3 && !s.coord; ++c) {
    std::vector<double> v(nodes);
    for (std::size_t i = 0; i < nodes; ++i) v[i] = s.xyz[3 * i + c];
    f.put(coords[c], v);
  }
  if (s.coord) {
    std::vector<double> v(static_cast<std::size_t>(s.dims) * nodes);
    for (std::size_t c = 0; c < static_cast<std::size_t>(s.dims); ++c)
      for (std::size_t i = 0; i < nodes; ++i) v[c * nodes + i] = s.xyz[3 * i + c];
    f.put(coords[0], v);
  }
  std::vector<int> ids;
  std::vector<std::string> names;
  for (const ExodusBlock& b : s.blocks) {
    ids.push_back(b.id);
    names.push_back(b.name);
  }
  f.put(eb_prop1, ids);
  f.put_rows(eb_names, names, 33);
  for (std::size_t b = 0; b < s.blocks.size(); ++b)
    if (connect[b] >= 0) f.put(connect[b], s.blocks[b].connect);
  if (node_map >= 0) f.put(node_map, s.node_map);
  if (element_map >= 0) f.put(element_map, s.element_map);
  for (std::size_t k = 0; k < s.node_sets.size(); ++k)
    if (node_sets[k] >= 0) f.put(node_sets[k], s.node_sets[k]);
  for (std::size_t k = 0; k < s.side_sets.size(); ++k) {
    if (elem_ss[k] < 0) continue;
    f.put(elem_ss[k], s.side_sets[k].elements);
    f.put(side_ss[k], s.side_sets[k].sides);
  }
  if (s.results) {
    f.put(time_whole, std::vector<double>{0.0, 1.0});
    std::vector<double> v(2 * nodes);
    for (std::size_t i = 0; i < v.size(); ++i) v[i] = 0.5 * static_cast<double>(i);
    f.put(values, v);
  }
  return f.bytes();
}

}  // namespace tetsmooth::testing
