#include "mesh/io/vtk_arrays.hpp"

#include <charconv>
#include <cmath>
#include <iterator>
#include <limits>

#include "mesh/errors.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth {
namespace {

// Position of `name` in kVtkTagArrays, or kNoVtkArray.
std::size_t tag_rank(const std::string& name) {
  for (std::size_t r = 0; r < std::size(kVtkTagArrays); ++r)
    if (name == kVtkTagArrays[r]) return r;
  return kNoVtkArray;
}

bool is_tag_array(const VtkArrayDecl& a) { return a.on_cells && a.components == 1 && tag_rank(a.name) != kNoVtkArray; }

bool is_fixed_array(const VtkArrayDecl& a) { return !a.on_cells && a.components == 1 && a.name == kVtkFixedArray; }

bool is_entity_array(const VtkArrayDecl& a) { return a.on_cells && a.components == 1 && a.name == kVtkEntityArray; }

bool is_node_entity_array(const VtkArrayDecl& a) {
  return !a.on_cells && (a.components == 2 || a.components == 3) && a.name == kVtkNodeEntityArray;
}

// The fields the command line writes with every VTU/VTK file (per-tet
// "quality", per-node "boundary"; apps/output_fields.cpp) are computed
// afresh from the mesh on each write, so reading them loses nothing, and a
// note on them would warn about every file tetsmooth wrote.
bool is_recomputed_field(const VtkArrayDecl& a) {
  return a.components == 1 && (a.on_cells ? a.name == "quality" : a.name == "boundary");
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + quoted_token(name);
  return out;
}

// "point data array 'x' is ignored ...", "cell data arrays 'x', 'y' are ...".
std::string dropped_note(const char* kind, const std::vector<std::string>& names) {
  const bool one = names.size() == 1;
  return std::string(kind) + (one ? " array " : " arrays ") + quoted_list(names) + (one ? " is" : " are") +
         " ignored and not written back";
}

std::string value_text(double v) {
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, result.ptr);
}

// InputError "<item> <i>: <name> value <v> <what>".
[[noreturn]] void bad_value(double v, const std::string& name, const char* item, std::size_t i, const char* what,
                            const std::string& where) {
  throw InputError(where,
                   std::string(item) + " " + std::to_string(i) + ": " + name + " value " + value_text(v) + " " + what);
}

bool is_integer(double v) { return std::isfinite(v) && v == std::trunc(v); }

void check_count(const std::vector<double>& values, std::size_t expected, const std::string& name, const char* items,
                 const std::string& where) {
  if (values.size() != expected)
    throw InputError(where, name + " has " + std::to_string(values.size()) + " values for " + std::to_string(expected) +
                                " " + items);
}

}  // namespace

bool vtk_array_wanted(const VtkArrayDecl& a) {
  return is_tag_array(a) || is_entity_array(a) || is_node_entity_array(a) || is_fixed_array(a);
}

VtkArrayPick pick_vtk_arrays(const std::vector<VtkArrayDecl>& arrays, std::vector<std::string>& notes) {
  VtkArrayPick pick;
  for (std::size_t i = 0; i < arrays.size(); ++i) {
    if (is_tag_array(arrays[i]) &&
        (pick.tags == kNoVtkArray || tag_rank(arrays[i].name) < tag_rank(arrays[pick.tags].name)))
      pick.tags = i;
    if (is_entity_array(arrays[i]) && pick.entities == kNoVtkArray) pick.entities = i;
    if (is_node_entity_array(arrays[i]) && pick.node_entities == kNoVtkArray) pick.node_entities = i;
    if (is_fixed_array(arrays[i]) && pick.fixed == kNoVtkArray) pick.fixed = i;
  }
  std::vector<std::string> dropped[2];  // point data, cell data
  for (std::size_t i = 0; i < arrays.size(); ++i)
    if (i != pick.tags && i != pick.entities && i != pick.node_entities && i != pick.fixed &&
        !is_recomputed_field(arrays[i]))
      dropped[arrays[i].on_cells].push_back(arrays[i].name);
  if (!dropped[0].empty()) notes.push_back(dropped_note("point data", dropped[0]));
  if (!dropped[1].empty()) notes.push_back(dropped_note("cell data", dropped[1]));
  return pick;
}

void note_vtk_field_data(const std::vector<std::string>& names, std::vector<std::string>& notes) {
  if (!names.empty()) notes.push_back(dropped_note("field data", names));
}

std::vector<int> vtk_region_tags(const std::vector<double>& values, std::size_t cells, const std::string& name,
                                 const std::string& where) {
  check_count(values, cells, name, "cells", where);
  std::vector<int> tags(values.size());
  for (std::size_t c = 0; c < values.size(); ++c) {
    const double v = values[c];
    if (!is_integer(v)) bad_value(v, name, "cell", c, "is not an integer", where);
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
      bad_value(v, name, "cell", c, "is out of range", where);
    tags[c] = static_cast<int>(v);
  }
  return tags;
}

void classify_vtk_nodes(TetMesh& mesh, const std::vector<double>& values, std::size_t components,
                        const std::string& name, const std::string& where) {
  const std::size_t nodes = mesh.num_nodes();
  if (values.size() != components * nodes)
    throw InputError(where, name + " has " + std::to_string(values.size()) + " values for " + std::to_string(nodes) +
                                " points of " + std::to_string(components) + " values");
  FileExtras& e = mesh.extras;
  e.node_entity_dims.resize(nodes);
  e.node_entity_tags.resize(nodes);
  for (std::size_t i = 0; i < nodes; ++i) {
    const double dim = values[components * i], tag = values[components * i + 1];
    if (!is_integer(dim) || dim < 0 || dim > 3) bad_value(dim, name, "point", i, "is no dimension 0 to 3", where);
    if (!is_integer(tag) || tag < std::numeric_limits<int>::min() || tag > std::numeric_limits<int>::max())
      bad_value(tag, name, "point", i, "is no whole entity tag in the range of int", where);
    if (components == 3 && values[3 * i + 2] != 0)
      bad_value(values[3 * i + 2], name, "point", i, "in its third component is not 0", where);
    e.node_entity_dims[i] = static_cast<int>(dim);
    e.node_entity_tags[i] = static_cast<int>(tag);
  }
}

void fix_vtk_nodes(TetMesh& mesh, const std::vector<double>& values, const std::string& name,
                   const std::string& where) {
  check_count(values, mesh.num_nodes(), name, "points", where);
  mesh.fixed.resize(mesh.num_nodes(), 0);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!is_integer(values[i])) bad_value(values[i], name, "point", i, "is not an integer", where);
    if (values[i] != 0) mesh.fixed[i] = 1;
  }
}

}  // namespace tetsmooth
