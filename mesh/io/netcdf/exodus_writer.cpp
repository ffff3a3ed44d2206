// Exodus II writing (exodus_io.hpp), through netCDF: a file read with the
// mesh comes back with new coordinates and nothing else changed; any other
// mesh gets a new file of its blocks, names, ids and pins.
#include <netcdf.h>

#include <algorithm>
#include <climits>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

#include "mesh/errors.hpp"
#include "mesh/io/exodus_element_types.hpp"
#include "mesh/io/exodus_io.hpp"
#include "mesh/io/file_numbers.hpp"
#include "mesh/io/kept_deck.hpp"
#include "mesh/io/netcdf/netcdf_dataset.hpp"
#include "mesh/io/region_sets.hpp"

namespace tetsmooth {
namespace {

constexpr long long kLargestId = INT_MAX;
// Exodus's names are 32 characters, unless the file says more (SEACAS reads
// up to 255, as maximum_name_length gives).
constexpr std::size_t kShortestName = 32, kLongestName = 255;
// A classic (64-bit offset) variable holds at most 4 GiB less 4 bytes.
constexpr std::size_t kClassicVariableBytes = 4294967292ULL;

// --- A file read with the mesh ------------------------------------------------

std::string kept_file(const TetMesh& mesh) {
  const FileExtras& e = mesh.extras;
  const std::string* bytes = raw_section(e, "exodus:file");
  const std::string* coordinates = raw_section(e, "exodus:coordinates");
  if (bytes == nullptr || coordinates == nullptr)
    throw OutputError("the mesh is stamped as read from an Exodus file, and carries no file");
  const std::size_t n = mesh.num_nodes();
  if (*coordinates == "coord") {
    std::vector<double> all(3 * n);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < 3; ++c) all[c * n + i] = mesh.xyz[3 * i + c];
    return netcdf::overwrite_reals(*bytes, {{"coord", &all}});
  }
  std::vector<double> x(n), y(n), z(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = mesh.xyz[3 * i];
    y[i] = mesh.xyz[3 * i + 1];
    z[i] = mesh.xyz[3 * i + 2];
  }
  return netcdf::overwrite_reals(*bytes, {{"coordx", &x}, {"coordy", &y}, {"coordz", &z}});
}

// --- A new file ---------------------------------------------------------------

// An element block of the new file: its type, id, name, and its elements
// as 1-based node numbers, with the mesh's element numbers (element_numbers
// order) of each.
struct Block {
  const char* type = nullptr;
  int nodes = 0;
  int id = 0;
  std::string name;
  std::vector<int> connect;
  std::vector<std::size_t> elements;
};

class BlockPlan {
 public:
  explicit BlockPlan(const TetMesh& mesh) : mesh_(mesh) {
    if (const std::string* body = raw_section(mesh.extras, "$PhysicalNames"))
      for (int d = 0; d <= 3; ++d) names_[d] = physical_names_of(*body, d);
    plan_tets();
    plan_others();
    number_blocks();
    name_blocks_apart();
  }
  std::vector<Block>& blocks() { return blocks_; }

 private:
  // The block for (tag, kind), made in the order met.
  Block& block_for(bool tagged, int tag, const exodus::ElementType& type) {
    const auto key = std::make_tuple(std::string(type.kind), tagged, tag);
    const auto [it, added] = index_.try_emplace(key, blocks_.size());
    if (added) {
      Block b;
      b.type = type.name;
      b.nodes = type.nodes;
      b.id = tagged && tag >= 0 ? tag : -1;  // settled by number_blocks
      if (tagged) {
        const auto& names = names_[kind_dimension(type.kind)];
        if (const auto named = names.find(tag); named != names.end()) b.name = named->second;
      }
      blocks_.push_back(std::move(b));
    }
    return blocks_[it->second];
  }

  void plan_tets() {
    const FileExtras& e = mesh_.extras;
    const bool ten = !mesh_.midsides.empty();
    const exodus::ElementType& type = *exodus::element_type_of_kind(ten ? "tetra10" : "tetra", ten ? 10 : 4);
    const bool tagged = e.tet_tags.size() == mesh_.num_tets();
    index_t nodes[10];
    for (std::size_t t = 0; t < mesh_.num_tets(); ++t) {
      Block& b = block_for(tagged, tagged ? e.tet_tags[t] : 0, type);
      if (ten)
        file_tet10(mesh_, t, exodus::kTetra10Midsides, nodes);
      else
        std::copy_n(&mesh_.tets[4 * t], 4, nodes);
      for (int k = 0; k < type.nodes; ++k) b.connect.push_back(nodes[k] + 1);
      b.elements.push_back(element_++);
    }
  }

  void plan_others() {
    for (const PassThroughBlock& pass : mesh_.extras.blocks) {
      const exodus::ElementType* type = exodus::element_type_of_kind(pass.kind, pass.nodes_per_element);
      if (type == nullptr) continue;
      const std::size_t count = elements_in(pass);
      const bool tagged = pass.tags.size() == count;
      for (std::size_t k = 0; k < count; ++k) {
        Block& b = block_for(tagged, tagged ? pass.tags[k] : 0, *type);
        for (std::size_t j = 0; j < static_cast<std::size_t>(type->nodes); ++j)
          b.connect.push_back(pass.connectivity[k * static_cast<std::size_t>(type->nodes) + j] + 1);
        b.elements.push_back(element_++);
      }
    }
  }

  // Each block keeps its tag as its id where that is not negative (MOOSE
  // and meshio number blocks from 0) and not taken by an earlier block; the
  // others take the smallest free positive ids.
  void number_blocks() {
    std::set<int> taken;
    for (Block& b : blocks_)
      if (b.id >= 0 && !taken.insert(b.id).second) b.id = -1;
    int next = 1;
    for (Block& b : blocks_) {
      if (b.id >= 0) continue;
      while (taken.count(next) > 0) ++next;
      b.id = next;
      taken.insert(next);
    }
  }

  // Exodus readers (SEACAS's IOSS) refuse a file whose blocks and sets
  // share a name: a name met again (a volume and a surface of one Gmsh
  // physical name, say) takes its block's type, then its id, then a count.
  void name_blocks_apart() {
    for (Block& b : blocks_)
      if (!b.name.empty()) b.name = unused_name(b.name, {"_" + std::string(b.type), "_" + std::to_string(b.id)});
  }

 public:
  // A name for a set that no block has.
  std::string free_name(const std::string& wanted) { return unused_name(wanted, {}); }

 private:
  // `wanted`, or it with the first `suffixes` then _2, _3, ... after it, the
  // first that no block or set has; cut to kLongestName bytes (at a UTF-8
  // character's start) before its suffixes.
  std::string unused_name(const std::string& wanted, const std::vector<std::string>& suffixes) {
    std::string taken;  // the suffixes tried so far, each after the last
    for (std::size_t k = 0;; ++k) {
      if (k > 0 && k <= suffixes.size()) taken += suffixes[k - 1];
      const std::string suffix = k <= suffixes.size() ? taken : taken + "_" + std::to_string(k - suffixes.size() + 1);
      std::size_t keep = std::min(wanted.size(), kLongestName - std::min(suffix.size(), kLongestName));
      while (keep > 0 && keep < wanted.size() && (static_cast<unsigned char>(wanted[keep]) & 0xC0) == 0x80) --keep;
      std::string name = wanted.substr(0, keep) + suffix;
      if (names_used_.insert(name).second) return name;
    }
  }

  const TetMesh& mesh_;
  std::map<int, std::string> names_[4];
  std::map<std::tuple<std::string, bool, int>, std::size_t> index_;
  std::vector<Block> blocks_;
  std::set<std::string> names_used_;
  std::size_t element_ = 0;
};

// Whether a new file writes a block's elements (every kind the readers give).
bool written(const PassThroughBlock& b) { return exodus::element_type_of_kind(b.kind, b.nodes_per_element) != nullptr; }

std::string new_file(const TetMesh& mesh) {
  BlockPlan plan(mesh);
  std::vector<Block>& blocks = plan.blocks();
  const FileExtras& e = mesh.extras;
  const std::size_t nodes = mesh.num_nodes();
  std::size_t elements = 0, largest = 8 * nodes;
  std::size_t name_length = kShortestName;
  for (const Block& b : blocks) {
    elements += b.elements.size();
    largest = std::max(largest, 4 * b.connect.size());
    name_length = std::max(name_length, b.name.size());
  }
  // Element ids where the file's are usable, in the new file's order.
  std::vector<int> element_map;
  if (const auto [ids, count] = file_element_numbers(mesh, ElementSet{true, written});
      !ids.empty() && usable_numbers(ids, count, kLargestId))
    for (const Block& b : blocks)
      for (std::size_t k : b.elements) element_map.push_back(static_cast<int>(ids[k]));
  std::vector<int> node_map;
  if (!e.node_tags.empty() && usable_numbers(e.node_tags, nodes, kLargestId))
    for (long long id : e.node_tags) node_map.push_back(static_cast<int>(id));
  std::vector<long long> positions(nodes);
  for (std::size_t i = 0; i < nodes; ++i) positions[i] = static_cast<long long>(i) + 1;
  const std::vector<long long> pins = pins_to_list(mesh, positions, written);

  netcdf::NewDataset file(largest > kClassicVariableBytes);
  file.text_attribute(-1, "title", "written by tetsmooth");
  file.float_attribute(-1, "api_version", 8.03f);
  file.float_attribute(-1, "version", 8.03f);
  file.int_attribute(-1, "floating_point_word_size", 8);
  file.int_attribute(-1, "file_size", 1);
  file.int_attribute(-1, "maximum_name_length", static_cast<int>(name_length));
  file.int_attribute(-1, "int64_status", 0);
  const int len_name = file.define_dimension("len_name", name_length + 1);
  file.define_dimension("len_string", 33);
  file.define_dimension("len_line", 81);
  file.define_dimension("four", 4);
  const int time_step = file.define_dimension("time_step", 0);
  const int num_dim = file.define_dimension("num_dim", 3);
  const int num_nodes = file.define_dimension("num_nodes", nodes);
  const int num_elem = file.define_dimension("num_elem", elements);
  const int num_el_blk = file.define_dimension("num_el_blk", blocks.size());
  file.define_variable("time_whole", NC_DOUBLE, {time_step});
  const int eb_status = file.define_variable("eb_status", NC_INT, {num_el_blk});
  const int eb_prop1 = file.define_variable("eb_prop1", NC_INT, {num_el_blk});
  file.text_attribute(eb_prop1, "name", "ID");
  const int eb_names = file.define_variable("eb_names", NC_CHAR, {num_el_blk, len_name});
  const int coord[3] = {file.define_variable("coordx", NC_DOUBLE, {num_nodes}),
                        file.define_variable("coordy", NC_DOUBLE, {num_nodes}),
                        file.define_variable("coordz", NC_DOUBLE, {num_nodes})};
  const int coor_names = file.define_variable("coor_names", NC_CHAR, {num_dim, len_name});
  std::vector<int> connect;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const std::string n = std::to_string(b + 1);
    const int count = file.define_dimension("num_el_in_blk" + n, blocks[b].elements.size());
    const int per = file.define_dimension("num_nod_per_el" + n, static_cast<std::size_t>(blocks[b].nodes));
    connect.push_back(file.define_variable("connect" + n, NC_INT, {count, per}));
    file.text_attribute(connect.back(), "elem_type", blocks[b].type);
  }
  const int node_num_map = node_map.empty() ? -1 : file.define_variable("node_num_map", NC_INT, {num_nodes});
  const int elem_num_map = element_map.empty() ? -1 : file.define_variable("elem_num_map", NC_INT, {num_elem});
  int ns_status = -1, ns_prop1 = -1, ns_names = -1, node_ns1 = -1;
  if (!pins.empty()) {
    const int sets = file.define_dimension("num_node_sets", 1);
    const int members = file.define_dimension("num_nod_ns1", pins.size());
    ns_status = file.define_variable("ns_status", NC_INT, {sets});
    ns_prop1 = file.define_variable("ns_prop1", NC_INT, {sets});
    file.text_attribute(ns_prop1, "name", "ID");
    ns_names = file.define_variable("ns_names", NC_CHAR, {sets, len_name});
    node_ns1 = file.define_variable("node_ns1", NC_INT, {members});
  }
  file.end_definitions();

  std::vector<int> status(blocks.size(), 1), ids;
  std::vector<std::string> names;
  for (const Block& b : blocks) {
    ids.push_back(b.id);
    names.push_back(b.name);
  }
  file.put(eb_status, status);
  file.put(eb_prop1, ids);
  file.put_rows(eb_names, names, name_length + 1);
  for (std::size_t c = 0; c < 3; ++c) {
    std::vector<double> values(nodes);
    for (std::size_t i = 0; i < nodes; ++i) values[i] = mesh.xyz[3 * i + c];
    file.put(coord[c], values);
  }
  file.put_rows(coor_names, {"X", "Y", "Z"}, name_length + 1);
  for (std::size_t b = 0; b < blocks.size(); ++b) file.put(connect[b], blocks[b].connect);
  if (node_num_map >= 0) file.put(node_num_map, node_map);
  if (elem_num_map >= 0) file.put(elem_num_map, element_map);
  if (!pins.empty()) {
    file.put(ns_status, std::vector<int>{1});
    file.put(ns_prop1, std::vector<int>{1});
    file.put_rows(ns_names, {plan.free_name("tetsmooth_pinned")}, name_length + 1);
    file.put(node_ns1, std::vector<int>(pins.begin(), pins.end()));
  }
  return file.bytes();
}

void write_kept_file(const TetMesh& mesh, std::ostream& out) {
  const std::string bytes = kept_file(mesh);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

void write_new_file(const TetMesh& mesh, std::ostream& out) {
  const std::string bytes = new_file(mesh);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

void check_new_file(const TetMesh& mesh) {
  if (mesh.num_tets() == 0) throw OutputError("the mesh has no tetrahedra to write");
  if (mesh.num_nodes() > static_cast<std::size_t>(INT_MAX))
    throw OutputError("a new Exodus file numbers nodes in 32-bit ints, and the mesh has more than 2^31 - 1");
}

constexpr DeckWriter kWriter{"exodus", "Exodus file", check_new_file, write_kept_file, write_new_file};

}  // namespace

// A file written back keeps its own id maps byte for byte, whatever they hold.
std::string exodus_numbers_lost(const TetMesh& mesh) {
  return has_kept_deck(mesh, "exodus") ? "" : numbers_lost(mesh, kLargestId, {ElementSet{true, written}});
}

void check_exodus_writable(const TetMesh& mesh) { kWriter.check(mesh); }

std::string write_exodus(const TetMesh& mesh) {
  std::ostringstream out;
  kWriter.write(mesh, out);
  return out.str();
}

void write_exodus_file(const TetMesh& mesh, const std::string& path) { kWriter.write_file(mesh, path); }

}  // namespace tetsmooth
