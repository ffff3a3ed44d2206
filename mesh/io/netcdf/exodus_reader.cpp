// Exodus II reading (exodus_io.hpp), through netCDF.
#include <algorithm>
#include <climits>
#include <fstream>
#include <map>
#include <optional>
#include <utility>

#include "mesh/errors.hpp"
#include "mesh/io/exodus_element_types.hpp"
#include "mesh/io/exodus_io.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/kept_deck.hpp"
#include "mesh/io/netcdf/netcdf_dataset.hpp"
#include "mesh/io/number_text.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/second_order.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {
namespace {

// Where each block's elements begin in the file's element numbering (which
// runs through the blocks in order), and their tets', for side sets.
struct BlockRange {
  std::size_t first_element = 0, elements = 0;
  long long first_tet = -1;  // -1: not a tet block
};

class ExodusReader {
 public:
  ExodusReader(std::string bytes, const std::string& source) : bytes_(std::move(bytes)) {
    file_.emplace(bytes_, source);
  }

  TetMesh read() {
    read_coordinates();
    read_blocks();
    read_node_ids();
    read_node_sets();
    read_side_sets();
    finish();
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(file_->source(), what); }

  std::size_t dimension(const std::string& name) const { return file_->dimension(name).value_or(0); }

  // Refuses a variable whose dimensions are not those the data model gives
  // it: the same number of values in another shape (a transposed coord or
  // connect) would be read as another mesh.
  void require_dimensions(const std::string& variable, const std::vector<std::string>& expected) const {
    const std::vector<std::string> dims = file_->dimension_names(variable);
    if (dims != expected)
      fail("variable '" + variable + "' has the dimensions (" + joined(dims) + "), where Exodus gives it (" +
           joined(expected) + ")");
  }

  // The numbers N, in order, of the items of a list (blocks, node sets,
  // side sets) that have a dimension or variable `prefix`N among `names`,
  // up to the list's length: the others are empty. Going by what the file
  // has, not by the length it declares, keeps a file of a few bytes that
  // declares 10^8 blocks from costing 10^8 lookups.
  std::vector<std::size_t> items(const std::vector<std::string>& names, const std::string& prefix,
                                 const std::string& length) const {
    const std::size_t declared = dimension(length);
    std::vector<std::size_t> numbers;
    for (const std::string& name : names) {
      if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
          name.find_first_not_of("0123456789", prefix.size()) != std::string::npos || name[prefix.size()] == '0' ||
          name.size() - prefix.size() > 18)
        continue;
      const std::size_t n = std::stoull(name.substr(prefix.size()));
      if (n <= declared) numbers.push_back(n);
    }
    std::sort(numbers.begin(), numbers.end());
    return numbers;
  }

  // A 1-based node number from `variable` (its `entry`-th value) as a
  // 0-based index.
  index_t node_index(long long n, const std::string& variable, std::size_t entry) const {
    if (n < 1 || static_cast<unsigned long long>(n) > mesh_.num_nodes())
      fail("entry " + std::to_string(entry + 1) + " of " + variable + " names node " + std::to_string(n) +
           ", outside 1.." + std::to_string(mesh_.num_nodes()));
    return static_cast<index_t>(n - 1);
  }

  // The coordinates' variable, which must hold reals, all of one size:
  // they are written back as such.
  void require_reals(const std::string& variable) {
    const int bytes = file_->real_bytes(variable);
    if (bytes == 0) fail("variable '" + variable + "' holds no real numbers, where Exodus has the coordinates");
    if (real_bytes_ != 0 && bytes != real_bytes_) fail("coordx and " + variable + " hold reals of different sizes");
    real_bytes_ = bytes;
  }

  void read_coordinates() {
    const auto dims = file_->dimension("num_dim");
    if (!dims) fail("no num_dim dimension: not an Exodus II file");
    if (*dims != 3)
      fail("a " + std::to_string(*dims) + "-D mesh (num_dim " + std::to_string(*dims) + "): tetsmooth reads 3-D tets");
    const std::size_t nodes = dimension("num_nodes");
    if (nodes == 0) fail("no nodes (num_nodes)");
    if (nodes > static_cast<std::size_t>(INT_MAX)) fail("more than 2^31 - 1 nodes");
    if (file_->has_variable("coordx")) {
      coordinates_ = "coordx coordy coordz";
      const char* names[3] = {"coordx", "coordy", "coordz"};
      for (std::size_t c = 0; c < 3; ++c) {
        if (!file_->has_variable(names[c])) fail("coordx without " + std::string(names[c]));
        require_dimensions(names[c], {"num_nodes"});
        require_reals(names[c]);
        const std::vector<double> values = file_->reals(names[c]);
        mesh_.xyz.resize(3 * nodes);
        for (std::size_t i = 0; i < nodes; ++i) mesh_.xyz[3 * i + c] = values[i];
      }
    } else if (file_->has_variable("coord")) {
      coordinates_ = "coord";
      require_dimensions("coord", {"num_dim", "num_nodes"});
      require_reals("coord");
      const std::vector<double> values = file_->reals("coord");
      mesh_.xyz.resize(3 * nodes);
      for (std::size_t i = 0; i < nodes; ++i)
        for (std::size_t c = 0; c < 3; ++c) mesh_.xyz[3 * i + c] = values[c * nodes + i];
    } else {
      fail("no coordinates (coordx, coordy, coordz or coord)");
    }
    pinned_.assign(nodes, 0);
  }

  // Region tags of the blocks numbered `blocks` (1-based): their ids, or
  // 1, 2, ... in block order where an id does not fit an int or two blocks
  // share one (with a note), so that the blocks stay apart.
  std::vector<int> block_tags(const std::vector<std::size_t>& blocks) {
    if (!file_->has_variable("eb_prop1"))
      return std::vector<int>(blocks.begin(), blocks.end());  // numbered as the file numbers them
    require_dimensions("eb_prop1", {"num_el_blk"});
    const std::vector<long long> ids = file_->integers("eb_prop1");
    const bool fit = std::all_of(ids.begin(), ids.end(), [](long long id) { return id >= INT_MIN && id <= INT_MAX; });
    std::map<long long, std::size_t> first_with;
    std::string repeated;
    for (std::size_t b = 0; b < ids.size() && repeated.empty(); ++b)
      if (const auto [it, added] = first_with.try_emplace(ids[b], b); !added)
        repeated = "id " + std::to_string(ids[b]) + " is that of blocks " + std::to_string(it->second + 1) + " and " +
                   std::to_string(b + 1);
    if (!fit || !repeated.empty())
      mesh_.extras.read_notes.push_back(
          std::string(!fit ? "block ids past 32-bit ints" : "block ids that repeat (" + repeated + ")") +
          ": the blocks are read as region tags 1, 2, ... in block order, so that they stay apart");
    std::vector<int> tags;
    for (std::size_t b : blocks)
      tags.push_back(fit && repeated.empty() ? static_cast<int>(ids[b - 1]) : static_cast<int>(b));
    return tags;
  }

  void read_blocks() {
    const std::vector<std::size_t> blocks = items(file_->all_dimension_names(), "num_el_in_blk", "num_el_blk");
    const std::size_t elements = dimension("num_elem");
    const std::vector<int> tags = block_tags(blocks);
    std::vector<std::string> names;
    if (file_->has_variable("eb_names")) names = file_->rows_of_text("eb_names");
    std::vector<long long> element_ids;
    if (file_->has_variable("elem_num_map")) {
      require_dimensions("elem_num_map", {"num_elem"});
      element_ids = file_->integers("elem_num_map");
    }
    std::map<std::string, std::size_t> uncarried;  // "HEX20 (20 nodes)" -> elements
    FileExtras& e = mesh_.extras;
    std::size_t next_element = 0;
    for (std::size_t listed = 0; listed < blocks.size(); ++listed) {
      const std::size_t b = blocks[listed] - 1;
      const std::string n = std::to_string(blocks[listed]);
      const std::size_t count = dimension("num_el_in_blk" + n);
      const std::string variable = "connect" + n;
      if (count == 0) continue;  // a null block
      if (!file_->has_variable(variable)) {
        if (file_->has_variable("facconn" + n))
          fail("block " + n + " holds polyhedra (NFACED), which tetsmooth does not read");
        fail("block " + n + " has " + count_of(count, "element") + " and no " + variable);
      }
      const std::optional<std::string> type_name = file_->text_attribute(variable, "elem_type");
      if (!type_name) fail(variable + " has no elem_type attribute");
      if (next_element + count > elements)
        fail("the blocks hold more elements than num_elem (" + std::to_string(elements) + ")");
      const std::size_t per = dimension("num_nod_per_el" + n);
      const exodus::ElementType* type = exodus::element_type(*type_name, static_cast<int>(per));
      // Polygons (NSIDED) list all their nodes in one row.
      const bool one_row = type == nullptr && file_->dimension_names(variable).size() == 1;
      if (!one_row) require_dimensions(variable, {"num_el_in_blk" + n, "num_nod_per_el" + n});
      std::vector<int> nodes = file_->ints(variable);
      for (std::size_t k = 0; k < nodes.size(); ++k) nodes[k] = node_index(nodes[k], variable, k);
      const int tag = tags[listed];
      const std::string name = b < names.size() ? names[b] : "";
      const auto id_of = [&](std::size_t k) { return element_ids.empty() ? 0 : element_ids[next_element + k]; };
      BlockRange& range = ranges_.emplace_back(BlockRange{next_element, count, -1});
      if (type == nullptr) {
        for (int node : nodes) pinned_[static_cast<std::size_t>(node)] = 1;
        uncarried[*type_name + " (" + std::to_string(per) + " nodes)"] += count;
      } else if (std::string(type->kind) == "tetra" || std::string(type->kind) == "tetra10") {
        const bool ten = type->nodes == 10;
        if (mesh_.num_tets() > 0 && ten != !mesh_.midsides.empty())
          fail(variable + ": " + mixed_tet_kinds(type->nodes));
        range.first_tet = static_cast<long long>(mesh_.num_tets());
        for (std::size_t k = 0; k < count; ++k) {
          append_file_tet(mesh_, &nodes[k * per], ten, exodus::kTetra10Midsides);
          e.tet_tags.push_back(tag);
          if (!element_ids.empty()) e.tet_element_tags.push_back(id_of(k));
        }
        if (!name.empty()) names_.add(3, tag, name);
      } else {
        PassThroughBlock& block = e.blocks.emplace_back();
        block.kind = type->kind;
        block.nodes_per_element = type->nodes;
        block.connectivity.assign(nodes.begin(), nodes.end());
        block.tags.assign(count, tag);
        for (std::size_t k = 0; k < count && !element_ids.empty(); ++k) block.element_tags.push_back(id_of(k));
        for (int node : nodes) pinned_[static_cast<std::size_t>(node)] = 1;
        if (!name.empty()) names_.add(kind_dimension(block.kind), tag, name);
      }
      next_element += count;
    }
    std::vector<std::string> types;
    for (const auto& [type, count] : uncarried) types.push_back(std::to_string(count) + " " + type);
    uncarried_ = joined(types);
    if (mesh_.num_tets() == 0)
      fail("no blocks of 4- or 10-node tets (TETRA, TET4, TETRA10, ...)" +
           (uncarried_.empty() ? std::string()
                               : ", only blocks of types tetsmooth does not read as such (" + uncarried_ + ")") +
           ": tetsmooth smooths tets");
    if (!uncarried_.empty())
      e.read_notes.push_back("elements of types tetsmooth does not carry (" + uncarried_ +
                             ") pin their nodes, and only Exodus output keeps them");
  }

  // The file's ids of the nodes, 1, 2, ... without a map: the kept file is
  // written back only for the mesh with those (kept_deck.hpp).
  void read_node_ids() {
    std::vector<long long>& ids = mesh_.extras.node_tags;
    if (file_->has_variable("node_num_map")) {
      require_dimensions("node_num_map", {"num_nodes"});
      ids = file_->integers("node_num_map");
    } else {
      for (std::size_t i = 0; i < mesh_.num_nodes(); ++i) ids.push_back(static_cast<long long>(i) + 1);
    }
  }

  void read_node_sets() {
    node_sets_ = dimension("num_node_sets");
    for (std::size_t s : items(file_->variable_names(), "node_ns", "num_node_sets")) {
      const std::string n = std::to_string(s);
      const std::string variable = "node_ns" + n;
      require_dimensions(variable, {"num_nod_ns" + n});
      const std::vector<int> members = file_->ints(variable);
      for (std::size_t k = 0; k < members.size(); ++k)
        pinned_[static_cast<std::size_t>(node_index(members[k], variable, k))] = 1;
    }
  }

  void read_side_sets() {
    side_sets_ = dimension("num_side_sets");
    for (std::size_t s : items(file_->variable_names(), "elem_ss", "num_side_sets")) {
      const std::string n = std::to_string(s);
      if (!file_->has_variable("side_ss" + n)) fail("elem_ss" + n + " without side_ss" + n);
      require_dimensions("elem_ss" + n, {"num_side_ss" + n});
      require_dimensions("side_ss" + n, {"num_side_ss" + n});
      const std::vector<long long> elements = file_->integers("elem_ss" + n);
      const std::vector<long long> sides = file_->integers("side_ss" + n);
      const std::size_t total = ranges_.empty() ? 0 : ranges_.back().first_element + ranges_.back().elements;
      for (std::size_t k = 0; k < elements.size(); ++k) {
        const long long element = elements[k];
        if (element < 1 || static_cast<unsigned long long>(element) > total)
          fail("entry " + std::to_string(k + 1) + " of elem_ss" + n + " names element " + std::to_string(element) +
               ", outside 1.." + std::to_string(total));
        const auto index = static_cast<std::size_t>(element - 1);
        const BlockRange& range =
            *std::prev(std::upper_bound(ranges_.begin(), ranges_.end(), index,
                                        [](std::size_t i, const BlockRange& r) { return i < r.first_element; }));
        if (range.first_tet < 0) continue;  // its nodes are pinned already
        const int* corners = exodus::tet_side_corners(sides[k] >= 1 && sides[k] <= 4 ? static_cast<int>(sides[k]) : 0);
        if (corners == nullptr)
          fail("entry " + std::to_string(k + 1) + " of side_ss" + n + " names side " + std::to_string(sides[k]) +
               " of a tet, which has sides 1..4");
        const std::size_t t = static_cast<std::size_t>(range.first_tet) + (index - range.first_element);
        for (int c = 0; c < 3; ++c)
          pinned_[static_cast<std::size_t>(mesh_.tets[4 * t + static_cast<std::size_t>(corners[c])])] = 1;
      }
    }
  }

  void finish() {
    FileExtras& e = mesh_.extras;
    // The midside nodes between pinned corners (on a pinned side, say) stay
    // with them.
    mark_midsides_of_marked_edges(mesh_, pinned_);
    if (std::find(pinned_.begin(), pinned_.end(), 1) != pinned_.end()) mesh_.fixed = std::move(pinned_);
    if (!names_.empty()) e.raw_sections.emplace_back("$PhysicalNames", names_.msh_body());
    // What other formats drop, for their note.
    std::vector<std::string> rest;
    if (node_sets_ > 0) rest.push_back(count_of(node_sets_, "node set"));
    if (side_sets_ > 0) rest.push_back(count_of(side_sets_, "side set"));
    const std::vector<std::string> variables = file_->variable_names();
    const auto any_named = [&](const char* prefix) {
      return std::any_of(variables.begin(), variables.end(),
                         [&](const std::string& v) { return v.rfind(prefix, 0) == 0; });
    };
    // Results are the values of variables over the time steps (meshio
    // writes a time step with none, and a file may define results before
    // any step).
    const std::size_t steps = dimension("time_step");
    const bool results = steps > 0 && any_named("vals_");
    if (results) rest.push_back("results over " + count_of(steps, "time step"));
    if (any_named("attrib")) rest.push_back("element attributes");
    if (any_named("qa_records") || any_named("info_records")) rest.push_back("QA and info records");
    if (!rest.empty()) e.raw_sections.emplace_back("exodus:rest", joined(rest));
    if (!uncarried_.empty()) e.raw_sections.emplace_back("exodus:uncarried", uncarried_);
    if (results)
      e.read_notes.push_back("the file holds results over " + count_of(steps, "time step") +
                             ", computed on the mesh as it was: Exodus output keeps them unchanged");
    if (real_bytes_ == 4)
      e.read_notes.push_back(
          "the file keeps its coordinates as 4-byte floats: in Exodus output, moved nodes are "
          "rounded to float");
    validate_mesh(mesh_, file_->source());
    file_.reset();  // netCDF is done with the bytes
    e.raw_sections.emplace_back("exodus:file", std::move(bytes_));
    e.raw_sections.emplace_back("exodus:coordinates", coordinates_);
    stamp_kept_deck(mesh_, "exodus");
  }

  std::string bytes_;
  std::optional<netcdf::Dataset> file_;  // reads from bytes_
  TetMesh mesh_;
  std::size_t node_sets_ = 0, side_sets_ = 0;
  std::vector<BlockRange> ranges_;  // the blocks with elements, in order
  std::vector<std::uint8_t> pinned_;
  RegionNames names_;
  std::string coordinates_, uncarried_;
  int real_bytes_ = 0;  // of the coordinates: 4 (float) or 8
};

}  // namespace

bool exodus_available() { return true; }

TetMesh read_exodus(std::string bytes, const std::string& source) {
  if (netcdf::format_of(bytes).empty())
    throw InputError(source,
                     "not an Exodus II file: Exodus files are netCDF, which begin with \"CDF\" or "
                     "HDF5's signature");
  return ExodusReader(std::move(bytes), source).read();
}

TetMesh read_exodus_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return read_exodus(read_all(in, path), path);
}

}  // namespace tetsmooth
