// MSH 2.2 $Nodes (or $ParametricNodes) and $Elements. The binary encoding is
// not the ASCII one written in bytes: counts stay text and elements come in
// typed runs.
#include <algorithm>
#include <limits>

#include "mesh/io/gmsh_source.hpp"

namespace tetsmooth::gmsh {
namespace {

// MSH 2 gives each element its number (`id`, the element tag of MSH 4) and
// its tags: the first is the physical group, the second the elementary
// (entity) tag; partition tags follow.
void add_element(ReadState& state, const ElementType& type, const std::vector<index_t>& nodes, long long id,
                 int physical, int elementary) {
  FileExtras& extras = state.mesh.extras;
  if (is_tet_type(type.id)) {
    append_file_tet(state.mesh, nodes.data(), type.id == kTet10Type, kGmshMidsidePlaces);
    extras.tet_tags.push_back(physical);
    extras.tet_entity_tags.push_back(elementary);
    extras.tet_element_tags.push_back(id);
    return;
  }
  PassThroughBlock& block = state.block_for(type);
  block.connectivity.insert(block.connectivity.end(), nodes.begin(), nodes.end());
  block.tags.push_back(physical);
  block.entity_tags.push_back(elementary);
  block.element_tags.push_back(id);
}

// One element line: a new element, or a further physical group of the
// element on the line before (V22Lines). `tags` is the line's number of
// tags: past the elementary tag come the partitions, first their count.
void take_line(ReadState& state, const ElementType& type, const std::vector<index_t>& nodes, long long id,
               int physical, int elementary, std::uint64_t tags, int partitions) {
  V22Lines& lines = state.v22;
  const bool again = lines.any && id == lines.id && type.id == lines.type && elementary == lines.elementary &&
                     nodes == lines.nodes;
  V22Lines::Groups& groups = lines.entities[{type.dim, elementary}];
  if (physical != 0 && std::find(groups.physicals.begin(), groups.physicals.end(), physical) == groups.physicals.end())
    groups.physicals.push_back(physical);
  ++groups.lines;
  if (again) {
    lines.repeated += !lines.repeats;  // an element counts once, at its second line
    lines.repeats = true;
    return;
  }
  add_element(state, type, nodes, id, physical, elementary);
  ++groups.elements;
  if (physical == 0)
    groups.ungrouped = true;
  else
    groups.first_agrees = groups.first_agrees && physical == groups.physicals.front();
  lines.partitioned += tags > 2 && partitions > 0;
  lines.any = true;
  lines.repeats = false;
  lines.id = id;
  lines.type = type.id;
  lines.elementary = elementary;
  lines.nodes = nodes;
}

template <class Source>
const ElementType& checked_type(Source& src, ReadState& state, int type_id) {
  const ElementType* type = element_type(type_id);
  if (type == nullptr) src.fail(unsupported_element_type(type_id));
  check_tet_kind(src, state, *type);
  return *type;
}

}  // namespace

template <class Source>
void read_nodes_v22(Source& src, ReadState& state, bool parametric) {
  const std::uint64_t total = src.text_count("number of nodes");
  if (total > static_cast<std::uint64_t>(std::numeric_limits<index_t>::max()))
    src.fail(std::to_string(total) + " nodes exceed the 32-bit index range");
  // A node is at least its tag and three coordinates, and in
  // $ParametricNodes its entity's dimension and tag.
  const std::size_t expected = src.reservable(total, 4 + 24 + (parametric ? 8 : 0));
  TetMesh& mesh = state.mesh;
  FileExtras& extras = mesh.extras;
  mesh.xyz.reserve(3 * expected);
  extras.node_tags.reserve(expected);
  std::uint64_t parametric_nodes = 0;
  for (std::uint64_t i = 0; i < total; ++i) {
    long long tag = 0;
    if constexpr (Source::kBinary) {
      tag = src.int_value("node tag");
      if (tag < 0) src.fail("negative node tag " + std::to_string(tag));
    } else {
      tag = tag_value(src, "node tag");
    }
    extras.node_tags.push_back(tag);
    for (int k = 0; k < 3; ++k) mesh.xyz.push_back(src.real_value("node coordinate"));
    if (!parametric) continue;
    // As Gmsh writes them (MVertex::writeMSH2): the dimension and tag of
    // the entity the node is classified on, then u on a curve, u v on a
    // surface, nothing on a point or in a volume. MSH 2.2 output has no
    // place for the classification, and MSH 4.1 output could not always
    // declare the entities it names, so it is read past too.
    const int dim = src.int_value("entity dimension");
    if (dim < 0 || dim > 3) src.fail("entity dimension " + std::to_string(dim) + " is not 0, 1, 2 or 3");
    src.int_value("entity tag");
    const int values = dim == 1 || dim == 2 ? dim : 0;
    for (int k = 0; k < values; ++k) src.real_value("parametric coordinate");
    parametric_nodes += values > 0;
  }
  const long long repeated = state.lookup.build(extras.node_tags);
  if (repeated >= 0)
    src.fail("node tag " + std::to_string(repeated) + " occurs twice in " +
             (parametric ? "$ParametricNodes" : "$Nodes"));
  if (parametric_nodes > 0) extras.read_notes.push_back(parametric_note(parametric_nodes));
}

template void read_nodes_v22<AsciiSource>(AsciiSource&, ReadState&, bool);
template void read_nodes_v22<BinarySource>(BinarySource&, ReadState&, bool);

void read_elements_v22(AsciiSource& src, ReadState& state) {
  const std::uint64_t total = src.size_value("number of elements");
  std::vector<index_t> nodes;
  for (std::uint64_t e = 0; e < total; ++e) {
    const long long id = tag_value(src, "element tag");
    const ElementType& type = checked_type(src, state, src.int_value("element type"));
    const std::uint64_t tags = src.size_value("number of element tags");
    int physical = 0, elementary = 0, partitions = 0;
    for (std::uint64_t k = 0; k < tags; ++k) {
      const int value = src.int_value("element tag value");
      if (k == 0) physical = value;
      if (k == 1) elementary = value;
      if (k == 2) partitions = value;
    }
    nodes.resize(static_cast<std::size_t>(type.nodes));
    for (index_t& n : nodes) n = node_index(src, state, src.size_value("node tag"));
    take_line(state, type, nodes, id, physical, elementary, tags, partitions);
  }
}

void read_elements_v22(BinarySource& src, ReadState& state) {
  const std::uint64_t total = src.text_count("number of elements");
  src.reservable(total, 8);  // at least an element number and one node
  std::vector<index_t> nodes;
  for (std::uint64_t seen = 0; seen < total;) {
    const ElementType& type = checked_type(src, state, src.int_value("element type"));
    const int count = src.int_value("number of elements following");
    const int tags = src.int_value("number of element tags");
    if (count <= 0 || static_cast<std::uint64_t>(count) > total - seen)
      src.fail("a run of " + std::to_string(count) + " elements does not fit the " + std::to_string(total - seen) +
               " still to come");
    if (tags < 0) src.fail("negative number of element tags " + std::to_string(tags));
    src.reservable(static_cast<std::uint64_t>(count), 4 * (1 + static_cast<std::size_t>(tags) + type.nodes));
    nodes.resize(static_cast<std::size_t>(type.nodes));
    for (int e = 0; e < count; ++e) {
      const int id = src.int_value("element number");  // one not positive is noted after reading
      int physical = 0, elementary = 0, partitions = 0;
      for (int k = 0; k < tags; ++k) {
        const int value = src.int_value("element tag value");
        if (k == 0) physical = value;
        if (k == 1) elementary = value;
        if (k == 2) partitions = value;
      }
      for (index_t& n : nodes) {
        const int tag = src.int_value("node tag");
        if (tag < 0) src.fail("negative node tag " + std::to_string(tag));
        n = node_index(src, state, static_cast<std::uint64_t>(tag));
      }
      take_line(state, type, nodes, id, physical, elementary, static_cast<std::uint64_t>(tags), partitions);
    }
    seen += static_cast<std::uint64_t>(count);
  }
}

void finish_elements_v22(ReadState& state) {
  V22Lines& lines = state.v22;
  FileExtras& extras = state.mesh.extras;
  if (lines.partitioned > 0)
    extras.read_notes.push_back("the partition tags of " + std::to_string(lines.partitioned) +
                                " elements are dropped: the partitions are merged; the written file is not "
                                "partitioned");
  if (lines.repeated == 0) return;
  const bool every_group = std::all_of(lines.entities.begin(), lines.entities.end(), [](const auto& entry) {
    const auto& [key, groups] = entry;
    if (groups.physicals.empty()) return groups.lines == groups.elements;
    return key.second > 0 && !groups.ungrouped && groups.first_agrees &&
           groups.lines == groups.elements * groups.physicals.size();
  });
  if (!every_group) {
    const bool one = lines.repeated == 1;
    extras.read_notes.push_back(std::to_string(lines.repeated) + (one ? " element is" : " elements are") +
                                " listed once per physical group, but not every element of " +
                                (one ? "its" : "their") + " elementary entity is in the same groups: " +
                                (one ? "it keeps only its" : "they keep only their") + " first group");
    return;
  }
  EntityBuilder builder;
  const auto add = [&](int dim, const std::vector<int>& entities, const std::vector<index_t>& connectivity,
                       int nodes) {
    for (std::size_t e = 0; e < entities.size(); ++e)
      builder.add(dim, entities[e], state.mesh.xyz.data(), &connectivity[e * static_cast<std::size_t>(nodes)], nodes)
          .physicals = lines.entities.at({dim, entities[e]}).physicals;
  };
  // A volume's box takes in its midside nodes, which a curved boundary
  // puts outside its corners'.
  const TetMesh& mesh = state.mesh;
  if (mesh.midsides.empty()) {
    add(3, extras.tet_entity_tags, mesh.tets, 4);
  } else {
    std::vector<index_t> tet10(10 * mesh.num_tets());
    for (std::size_t t = 0; t < mesh.num_tets(); ++t) file_tet10(mesh, t, kGmshMidsidePlaces, &tet10[10 * t]);
    add(3, extras.tet_entity_tags, tet10, 10);
  }
  for (const PassThroughBlock& block : extras.blocks) {
    const ElementType* type = element_type_of_kind(block.kind);
    add(type->dim, block.entity_tags, block.connectivity, type->nodes);
  }
  extras.raw_sections.emplace_back("$Entities", format_entities_text(builder.take()));
}

}  // namespace tetsmooth::gmsh
