#include "mesh/io/gmsh_write_plan.hpp"

#include <algorithm>
#include <climits>
#include <cstddef>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

#include "mesh/errors.hpp"

namespace tetsmooth::gmsh {
namespace {

// The file's own tags when they can be written back: one per item,
// positive, distinct and at most `largest`; otherwise 1..count.
std::vector<long long> output_tags(std::vector<long long> given, std::size_t count, long long largest) {
  if (given.size() == count && !unusable_tag(given, largest)) return given;
  std::vector<long long> fresh(count);
  std::iota(fresh.begin(), fresh.end(), 1LL);
  return fresh;
}

// Groups with the entity and physical tags the mesh gives (negative ones
// renumbered, see negative_tag_renumbering), or empty arrays where it gives
// none.
std::vector<ElementGroup> given_groups(const TetMesh& mesh) {
  const FileExtras& extras = mesh.extras;
  const std::map<int, int> renumbered = negative_tag_renumbering(extras);
  const auto physical_of = [&](const std::vector<int>& tags) {
    std::vector<int> physical = tags;
    for (int& tag : physical)
      if (tag < 0) tag = renumbered.at(tag);
    return physical;
  };
  std::vector<ElementGroup> groups;
  ElementGroup& tets = groups.emplace_back();
  tets.count = mesh.num_tets();
  if (mesh.midsides.empty()) {
    tets.type = element_type(kTetType);
    tets.connectivity = mesh.tets.data();
  } else {
    tets.type = element_type(kTet10Type);
    tets.owned.resize(10 * tets.count);
    for (std::size_t t = 0; t < tets.count; ++t) file_tet10(mesh, t, kGmshMidsidePlaces, &tets.owned[10 * t]);
  }
  if (extras.tet_entity_tags.size() == tets.count) tets.entity = extras.tet_entity_tags;
  if (extras.tet_tags.size() == tets.count) tets.physical = physical_of(extras.tet_tags);
  for (const PassThroughBlock& block : extras.blocks) {
    const ElementType* type = element_type_of_kind(block.kind);
    if (type == nullptr || is_tet_type(type->id) || type->nodes != block.nodes_per_element)
      throw OutputError("MSH output cannot hold the pass-through '" + block.kind + "' block (" +
                        std::to_string(block.nodes_per_element) + " nodes per element)");
    ElementGroup& g = groups.emplace_back();
    g.type = type;
    g.connectivity = block.connectivity.data();
    g.count = block.connectivity.size() / static_cast<std::size_t>(type->nodes);
    if (block.entity_tags.size() == g.count) g.entity = block.entity_tags;
    if (block.tags.size() == g.count) g.physical = physical_of(block.tags);
  }
  return groups;
}

// Keeps the file's $Entities if every element still refers to one of them.
bool adopt_file_entities(const FileExtras& extras, std::vector<ElementGroup>& groups, WritePlan& plan) {
  const std::string* raw = raw_section(extras, "$Entities");
  if (raw == nullptr) return false;
  Entities entities;
  try {
    entities = parse_entities_text(*raw, "$Entities");
  } catch (const InputError&) {
    return false;  // not what the reader stored: make entities up instead
  }
  for (const ElementGroup& g : groups) {
    if (g.entity.size() != g.count) return false;
    for (int tag : g.entity)
      if (entities.find(g.type->dim, tag) == nullptr) return false;
  }
  // The physical tags follow from the entities, so that MSH 2.2 output
  // agrees with MSH 4.1 output.
  for (ElementGroup& g : groups) {
    g.physical.resize(g.count);
    for (std::size_t e = 0; e < g.count; ++e) g.physical[e] = first_physical(entities, g.type->dim, g.entity[e]);
  }
  plan.entities = std::move(entities);
  plan.entities_text = *raw;
  plan.groups_of_entities = true;
  return true;
}

// Entities made up for elements without a file's $Entities: one for each
// (given entity tag, physical tag) of a dimension, as an MSH 4.1 entity puts
// all of its elements in the same physical groups. A given entity keeps its
// tag for the first physical tag met on it; its elements under another one
// (entity tags from another program, which need not nest in the physical
// groups) go on an entity of a new tag, and so do elements without an
// entity tag, which take their physical tag (or 1) where no other entity
// has it.
class EntityTags {
 public:
  explicit EntityTags(const std::vector<ElementGroup>& groups) {
    for (const ElementGroup& g : groups)
      for (int tag : g.entity)
        if (tag > 0) taken_[g.type->dim].insert(tag);
  }
  int operator()(int dim, int given, int physical) {
    const auto [it, fresh] = made_.try_emplace(std::make_tuple(dim, std::max(given, 0), physical), 0);
    if (!fresh) return it->second;
    std::set<int>& taken = taken_[dim];
    int tag = given > 0 ? given : (physical > 0 ? physical : 1);
    if (given > 0 ? !owned_[dim].insert(given).second : taken.count(tag) > 0) tag = unused(taken);
    taken.insert(tag);
    return it->second = tag;
  }

 private:
  std::map<int, std::set<int>> taken_;  // by dimension: given tags, and those made
  std::map<int, std::set<int>> owned_;  // given tags already on an entity
  std::map<std::tuple<int, int, int>, int> made_;

  // A positive tag not in `taken`: past the largest, or the first gap where
  // the largest is INT_MAX.
  static int unused(const std::set<int>& taken) {
    if (taken.empty()) return 1;
    if (*taken.rbegin() < INT_MAX) return std::max(*taken.rbegin() + 1, 1);
    int tag = 1;
    for (auto it = taken.lower_bound(1); it != taken.end() && *it == tag; ++it) ++tag;
    return tag;
  }
};

// The points, curves and surfaces that the nodes' classification names
// (meshio's gmsh:dim_tags in VTU and VTK) and no element is on: Gmsh writes
// those too where only the volumes are in a physical group (an embedded
// fault surface whose triangles are not saved), with the nodes classified
// on them, and that is what pins the nodes in a later run. Each is declared
// without physical groups and, as the mesh does not tell them, without
// bounding entities (a discrete entity to Gmsh), its box that of its nodes.
// Left undeclared, so that their nodes go where classify_nodes puts nodes
// without a classification: a volume no tet is on (Gmsh's volume holds the nodes inside
// its tets, and a volume of stray nodes beside the tets' own is no model a
// Gmsh user has; nothing pins a volume's nodes, so nothing is lost), and an
// entity of a tag below 1 (Gmsh's model entities have positive tags).
void add_classification_entities(const TetMesh& mesh, Entities& entities) {
  const FileExtras& extras = mesh.extras;
  const std::size_t n = mesh.num_nodes();
  if (extras.node_entity_dims.size() != n || extras.node_entity_tags.size() != n) return;
  EntityBuilder builder;
  for (std::size_t i = 0; i < n; ++i) {
    const int dim = extras.node_entity_dims[i], tag = extras.node_entity_tags[i];
    if (dim >= 3 || tag < 1 || entities.find(dim, tag) != nullptr) continue;
    const auto node = static_cast<std::int32_t>(i);
    builder.add(dim, tag, mesh.xyz.data(), &node, 1);
  }
  const Entities made = builder.take();
  for (const Entity& x : made.list()) entities.add(x);
}

void make_entities(const TetMesh& mesh, std::vector<ElementGroup>& groups, WritePlan& plan) {
  EntityBuilder builder;
  EntityTags entity_tag(groups);
  for (ElementGroup& g : groups) {
    const int dim = g.type->dim;
    const int nodes = g.type->nodes;
    std::vector<int> entity(g.count), physical(g.count);
    for (std::size_t e = 0; e < g.count; ++e) {
      const int p = g.physical.empty() ? 0 : std::max(g.physical[e], 0);
      const int given = g.entity.empty() ? 0 : g.entity[e];
      const int tag = entity_tag(dim, given, p);
      entity[e] = tag;
      physical[e] = p;
      Entity& x = builder.add(dim, tag, mesh.xyz.data(), &g.nodes()[e * static_cast<std::size_t>(nodes)], nodes);
      if (p > 0 && std::find(x.physicals.begin(), x.physicals.end(), p) == x.physicals.end()) x.physicals.push_back(p);
    }
    g.entity = std::move(entity);
    g.physical = std::move(physical);
  }
  plan.entities = builder.take();
  add_classification_entities(mesh, plan.entities);
  plan.entities_text = format_entities_text(plan.entities);
}

// The nodes' own classification where the entity it names is declared,
// else (and for a mesh without one) the lowest-dimensional entity of an
// element that uses the node, as Gmsh classifies them.
void classify_nodes(const TetMesh& mesh, const std::vector<ElementGroup>& groups, WritePlan& plan) {
  const FileExtras& extras = mesh.extras;
  const std::size_t n = mesh.num_nodes();
  // Nodes in no element go with the first tet's volume.
  plan.node_dims.assign(n, 3);
  plan.node_entities.assign(n, groups.front().entity.front());
  std::vector<int> best(n, 4);
  for (const ElementGroup& g : groups) {
    const std::size_t entries = g.count * static_cast<std::size_t>(g.type->nodes);
    for (std::size_t k = 0; k < entries; ++k) {
      const auto node = static_cast<std::size_t>(g.nodes()[k]);
      if (g.type->dim < best[node]) {
        best[node] = g.type->dim;
        plan.node_dims[node] = g.type->dim;
        plan.node_entities[node] = g.entity[k / static_cast<std::size_t>(g.type->nodes)];
      }
    }
  }
  if (extras.node_entity_dims.size() != n || extras.node_entity_tags.size() != n) return;
  for (std::size_t i = 0; i < n; ++i)
    if (plan.entities.find(extras.node_entity_dims[i], extras.node_entity_tags[i]) != nullptr) {
      plan.node_dims[i] = extras.node_entity_dims[i];
      plan.node_entities[i] = extras.node_entity_tags[i];
    }
}

void check_indices(const TetMesh& mesh, const std::vector<ElementGroup>& groups) {
  for (const ElementGroup& g : groups) {
    const std::size_t entries = g.count * static_cast<std::size_t>(g.type->nodes);
    for (std::size_t k = 0; k < entries; ++k)
      if (g.nodes()[k] < 0 || static_cast<std::size_t>(g.nodes()[k]) >= mesh.num_nodes())
        throw OutputError(std::string("a ") + g.type->kind + " element refers to node " +
                          std::to_string(g.nodes()[k]) + ", outside the " + std::to_string(mesh.num_nodes()) +
                          " nodes");
  }
}

// Kept tags go out in the file's order of types: Gmsh numbers points, lines
// and triangles before the tets, and readers such as meshio expect field
// data in ascending element order. Groups are put in the order of their
// first tags (stable, so 1..N leaves the tets first), with `tags` permuted
// to match.
void order_groups_by_tag(std::vector<ElementGroup>& groups, std::vector<long long>& tags) {
  std::vector<std::size_t> start(groups.size() + 1, 0);
  for (std::size_t g = 0; g < groups.size(); ++g) start[g + 1] = start[g] + groups[g].count;
  std::vector<std::size_t> order(groups.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  const auto first = [&](std::size_t g) { return groups[g].count == 0 ? LLONG_MAX : tags[start[g]]; };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return first(a) < first(b); });
  std::vector<ElementGroup> sorted_groups;
  std::vector<long long> sorted_tags;
  sorted_tags.reserve(tags.size());
  for (std::size_t g : order) {
    sorted_tags.insert(sorted_tags.end(), tags.begin() + static_cast<std::ptrdiff_t>(start[g]),
                       tags.begin() + static_cast<std::ptrdiff_t>(start[g + 1]));
    sorted_groups.push_back(std::move(groups[g]));
  }
  groups = std::move(sorted_groups);
  tags = std::move(sorted_tags);
}

}  // namespace

WritePlan plan_gmsh_output(const TetMesh& mesh, MshFlavour flavour) {
  if (mesh.num_tets() == 0) throw OutputError("the mesh has no tetrahedra to write");
  WritePlan plan;
  std::vector<ElementGroup> groups = given_groups(mesh);
  check_indices(mesh, groups);
  if (!adopt_file_entities(mesh.extras, groups, plan)) make_entities(mesh, groups, plan);
  classify_nodes(mesh, groups, plan);
  plan.node_tags = output_tags(mesh.extras.node_tags, mesh.num_nodes(),
                               flavour == MshFlavour::V22Ascii ? kLargestIntTag : INT64_MAX);
  if (const std::string* names = raw_section(mesh.extras, "$PhysicalNames")) plan.physical_names = *names;
  for (const ElementGroup& g : groups) plan.element_count += g.count;
  plan.element_tags = output_tags(file_element_tags(mesh.extras, mesh.num_tets()), plan.element_count,
                                  kLargestIntTag);
  order_groups_by_tag(groups, plan.element_tags);
  plan.groups = std::move(groups);
  return plan;
}

std::vector<std::uint8_t> msh41_feature_nodes(const TetMesh& mesh) {
  const FileExtras& extras = mesh.extras;
  if (extras.node_entity_dims.size() != mesh.num_nodes() || extras.node_entity_tags.size() != mesh.num_nodes())
    return {};
  try {
    const WritePlan plan = plan_gmsh_output(mesh, MshFlavour::V41Ascii);
    std::vector<std::uint8_t> features(mesh.num_nodes());
    for (std::size_t i = 0; i < features.size(); ++i) features[i] = plan.node_dims[i] < 3;
    return features;
  } catch (const OutputError&) {
    return {};  // nothing is written at all
  }
}

std::pair<const int*, std::size_t> v22_physicals(const WritePlan& plan, const ElementGroup& g, std::size_t e) {
  if (plan.groups_of_entities)
    if (const Entity* x = plan.entities.find(g.type->dim, g.entity[e]); x != nullptr && x->physicals.size() > 1)
      return {x->physicals.data(), x->physicals.size()};
  return {&g.physical[e], 1};
}

std::size_t v22_lines(const WritePlan& plan) {
  std::size_t lines = 0;
  for (const ElementGroup& g : plan.groups)
    for (std::size_t e = 0; e < g.count; ++e) lines += v22_physicals(plan, g, e).second;
  return lines;
}

}  // namespace tetsmooth::gmsh
