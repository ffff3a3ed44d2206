// MSH 4.1 $Nodes and $Elements, ASCII or binary, and the pieces the MSH 2
// parsers share with them.
#include <algorithm>
#include <limits>

#include "mesh/io/gmsh_source.hpp"

namespace tetsmooth::gmsh {

long long NodeLookup::build(const std::vector<long long>& tags) {
  dense_.clear();
  sparse_.clear();
  const long long max_tag = tags.empty() ? 0 : *std::max_element(tags.begin(), tags.end());
  // A table indexed by tag costs 4 bytes per possible tag; worth it while
  // the tags are mostly used, as they are in files Gmsh writes.
  if (static_cast<unsigned long long>(max_tag) <= 4 * tags.size() + 1024) {
    dense_.assign(static_cast<std::size_t>(max_tag) + 1, -1);
    for (std::size_t i = 0; i < tags.size(); ++i) {
      index_t& slot = dense_[static_cast<std::size_t>(tags[i])];
      if (slot >= 0) return tags[i];
      slot = static_cast<index_t>(i);
    }
    return -1;
  }
  sparse_.reserve(tags.size());
  for (std::size_t i = 0; i < tags.size(); ++i) sparse_.emplace_back(tags[i], static_cast<index_t>(i));
  std::sort(sparse_.begin(), sparse_.end());
  for (std::size_t i = 1; i < sparse_.size(); ++i)
    if (sparse_[i].first == sparse_[i - 1].first) return sparse_[i].first;
  return -1;
}

index_t NodeLookup::find(long long tag) const {
  if (tag < 0) return -1;
  if (!sparse_.empty()) {
    const auto it = std::lower_bound(sparse_.begin(), sparse_.end(), std::make_pair(tag, index_t{-1}));
    return it != sparse_.end() && it->first == tag ? it->second : -1;
  }
  return static_cast<unsigned long long>(tag) < dense_.size() ? dense_[static_cast<std::size_t>(tag)] : -1;
}

PassThroughBlock& ReadState::block_for(const ElementType& type) {
  for (const auto& [id, index] : block_of_type)
    if (id == type.id) return mesh.extras.blocks[index];
  block_of_type.emplace_back(type.id, mesh.extras.blocks.size());
  PassThroughBlock& block = mesh.extras.blocks.emplace_back();
  block.kind = type.kind;
  block.nodes_per_element = type.nodes;
  return block;
}

template <class Source>
void read_nodes_v41(Source& src, ReadState& state) {
  const std::uint64_t blocks = src.size_value("number of node blocks");
  const std::uint64_t total = src.size_value("number of nodes");
  src.size_value("smallest node tag");
  src.size_value("largest node tag");
  // A block header is 20 bytes, a node 32 (tag and three coordinates).
  src.reservable(blocks, 20);
  if (total > static_cast<std::uint64_t>(std::numeric_limits<index_t>::max()))
    src.fail(std::to_string(total) + " nodes exceed the 32-bit index range");
  const std::size_t expected = src.reservable(total, 32);

  TetMesh& mesh = state.mesh;
  FileExtras& extras = mesh.extras;
  mesh.xyz.reserve(3 * expected);
  extras.node_tags.reserve(expected);
  extras.node_entity_dims.reserve(expected);
  extras.node_entity_tags.reserve(expected);

  std::uint64_t parametric_nodes = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const int dim = src.int_value("entity dimension");
    const int entity = src.int_value("entity tag");
    const int parametric = src.int_value("parametric flag");
    const std::uint64_t count = src.size_value("number of nodes in the block");
    if (dim < 0 || dim > 3) src.fail("entity dimension " + std::to_string(dim) + " is not 0, 1, 2 or 3");
    if (parametric != 0 && parametric != 1)
      src.fail("parametric flag " + std::to_string(parametric) + " is not 0 or 1");
    if (count > total - extras.node_tags.size())
      src.fail("the node blocks hold more nodes than the " + std::to_string(total) + " announced");
    // Parametric coordinates (u, v, w up to the entity dimension) follow the
    // coordinates; they are dropped, and the writers write plain nodes
    // (nodes on curves and surfaces stay in place, but a volume's nodes,
    // which Gmsh writes without parameters, would leave any stale).
    const int extra_values = parametric != 0 ? dim : 0;
    if (extra_values > 0) parametric_nodes += count;
    src.reservable(count, 8 + 24 + 8 * static_cast<std::size_t>(extra_values));
    for (std::uint64_t i = 0; i < count; ++i) extras.node_tags.push_back(tag_value(src, "node tag"));
    for (std::uint64_t i = 0; i < count; ++i) {
      for (int k = 0; k < 3; ++k) mesh.xyz.push_back(src.real_value("node coordinate"));
      for (int k = 0; k < extra_values; ++k) src.real_value("parametric coordinate");
    }
    extras.node_entity_dims.insert(extras.node_entity_dims.end(), static_cast<std::size_t>(count), dim);
    extras.node_entity_tags.insert(extras.node_entity_tags.end(), static_cast<std::size_t>(count), entity);
  }
  if (extras.node_tags.size() != total)
    src.fail("the node blocks hold " + std::to_string(extras.node_tags.size()) + " nodes, not the " +
             std::to_string(total) + " announced");
  const long long repeated = state.lookup.build(extras.node_tags);
  if (repeated >= 0) src.fail("node tag " + std::to_string(repeated) + " occurs twice in $Nodes");
  if (parametric_nodes > 0) extras.read_notes.push_back(parametric_note(parametric_nodes));
}

std::string parametric_note(std::uint64_t nodes) {
  return "the parametric coordinates of " + std::to_string(nodes) +
         " nodes on curves and surfaces are not kept: tetsmooth writes plain node coordinates";
}

template <class Source>
void read_elements_v41(Source& src, ReadState& state) {
  const std::uint64_t blocks = src.size_value("number of element blocks");
  const std::uint64_t total = src.size_value("number of elements");
  src.size_value("smallest element tag");
  src.size_value("largest element tag");
  src.reservable(blocks, 20);
  src.reservable(total, 16);  // an element is at least its tag and one node tag

  TetMesh& mesh = state.mesh;
  std::uint64_t seen = 0;
  std::vector<index_t> nodes;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    const int dim = src.int_value("entity dimension");
    const int entity = src.int_value("entity tag");
    const int type_id = src.int_value("element type");
    const std::uint64_t count = src.size_value("number of elements in the block");
    const ElementType* type = element_type(type_id);
    if (type == nullptr) src.fail(unsupported_element_type(type_id));
    if (count > 0) check_tet_kind(src, state, *type);
    if (type->dim != dim)
      src.fail("element type " + std::to_string(type_id) + " (" + type->kind + ") in a block of dimension " +
               std::to_string(dim));
    if (count > total - seen)
      src.fail("the element blocks hold more elements than the " + std::to_string(total) + " announced");
    seen += count;
    const std::size_t reserve = src.reservable(count, 8 * (1 + static_cast<std::size_t>(type->nodes)));

    nodes.resize(static_cast<std::size_t>(type->nodes));
    const bool tet = is_tet_type(type->id);
    // An empty block makes no PassThroughBlock (see MeditReader::elements).
    PassThroughBlock* block = tet || count == 0 ? nullptr : &state.block_for(*type);
    if (tet) {
      mesh.tets.reserve(mesh.tets.size() + 4 * reserve);
      mesh.extras.tet_entity_tags.reserve(mesh.extras.tet_entity_tags.size() + reserve);
      mesh.extras.tet_element_tags.reserve(mesh.extras.tet_element_tags.size() + reserve);
    }
    for (std::uint64_t e = 0; e < count; ++e) {
      const long long id = tag_value(src, "element tag");
      for (index_t& n : nodes) n = node_index(src, state, src.size_value("node tag"));
      if (tet) {
        append_file_tet(mesh, nodes.data(), type->id == kTet10Type, kGmshMidsidePlaces);
        mesh.extras.tet_entity_tags.push_back(entity);
        mesh.extras.tet_element_tags.push_back(id);
      } else {
        block->connectivity.insert(block->connectivity.end(), nodes.begin(), nodes.end());
        block->entity_tags.push_back(entity);
        block->element_tags.push_back(id);
      }
    }
  }
  if (seen != total)
    src.fail("the element blocks hold " + std::to_string(seen) + " elements, not the " + std::to_string(total) +
             " announced");
}

template void read_nodes_v41<AsciiSource>(AsciiSource&, ReadState&);
template void read_nodes_v41<BinarySource>(BinarySource&, ReadState&);
template void read_elements_v41<AsciiSource>(AsciiSource&, ReadState&);
template void read_elements_v41<BinarySource>(BinarySource&, ReadState&);

}  // namespace tetsmooth::gmsh
