#include "mesh/region_interfaces.hpp"

#include <algorithm>
#include <unordered_map>
#include <utility>

#include "mesh/topology.hpp"

namespace tetsmooth {

bool tet_entities_split_regions(const TetMesh& mesh) {
  const FileExtras& e = mesh.extras;
  const std::size_t tets = mesh.num_tets();
  if (e.tet_entity_tags.size() != tets) return false;
  const bool tagged = e.tet_tags.size() == tets;
  std::unordered_map<int, int> entity_of_region;
  for (std::size_t t = 0; t < tets; ++t)
    if (entity_of_region.try_emplace(tagged ? e.tet_tags[t] : 0, e.tet_entity_tags[t]).first->second !=
        e.tet_entity_tags[t])
      return true;
  return false;
}

std::vector<std::uint8_t> region_interface_nodes(const TetMesh& mesh, InterfaceSources sources, int threads) {
  const std::size_t nodes = mesh.num_nodes(), tets = mesh.num_tets();
  std::vector<std::uint8_t> pinned(nodes, kNotPinned);
  const FileExtras& extras = mesh.extras;
  const std::vector<int>& tags = extras.tet_tags;
  const std::vector<int>& entities = extras.tet_entity_tags;
  const std::vector<int>& dims = extras.node_entity_dims;
  const bool by_region = tags.size() == tets;
  // What adds nothing is left out, which spares the topology below where
  // nothing is left (a Gmsh file of one volume whose points, curves and
  // surfaces all carry elements, say).
  const bool by_entity = sources.entity_tags && tet_entities_split_regions(mesh);
  const auto file_pins = [&](std::size_t i) { return !mesh.fixed.empty() && mesh.fixed[i]; };
  bool by_node = false;
  if (sources.node_entities && dims.size() == nodes)
    for (std::size_t i = 0; i < nodes && !by_node; ++i) by_node = dims[i] < 3 && !file_pins(i);
  if (!by_region && !by_entity && !by_node) return pinned;
  const RowItems<FaceUse> uses = sorted_face_uses(mesh.tets, threads);
  // A tet's side of an interface: its region tag and its entity tag, 0 for
  // either that is not looked at.
  using Side = std::pair<int, int>;
  const auto side_of = [&](index_t tet) {
    const auto t = static_cast<std::size_t>(tet);
    return Side{by_region ? tags[t] : 0, by_entity ? entities[t] : 0};
  };
  // The sides of the listings [b, e) of one tet, sorted, without repeats,
  // into `set` (two buffers reused across faces: a mesh has millions).
  const auto side_set = [&](std::size_t b, std::size_t e, std::vector<Side>& set) {
    set.clear();
    for (std::size_t k = b; k < e; ++k) set.push_back(side_of(uses[k].tet));
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
  };
  std::vector<std::uint8_t> boundary(nodes, 0);
  std::vector<Side> seen, set;
  for (std::size_t first = 0, last; first < uses.size(); first = last) {
    for (last = first + 1; last < uses.size() && uses[last].face == uses[first].face; ++last) {
    }
    // The run holds the face's tets one after another (by fourth node); the
    // face is an interface when two of them differ in sides, and on the
    // boundary when it has one tet.
    bool differs = false;
    std::size_t tets_on_face = 0;
    for (std::size_t b = first, e; b < last; b = e) {
      for (e = b + 1; e < last && uses[e].opposite == uses[b].opposite; ++e) {
      }
      ++tets_on_face;
      if (differs) continue;
      side_set(b, e, set);
      differs = b != first && set != seen;
      std::swap(seen, set);
    }
    if (differs)
      for (index_t n : uses[first].face) pinned[static_cast<std::size_t>(n)] = kOnInterface;
    if (tets_on_face == 1)
      for (index_t n : uses[first].face) boundary[static_cast<std::size_t>(n)] = 1;
  }
  // The boundary stays in place anyway; its nodes at the rim of an
  // interface are not counted as pinned by it.
  for (std::size_t i = 0; i < nodes; ++i)
    if (boundary[i]) pinned[i] = kNotPinned;
  if (by_node) {
    // Nodes in no tet never move; they are no feature of the mesh.
    std::vector<std::uint8_t> used(nodes, 0);
    for (index_t n : mesh.tets) used[static_cast<std::size_t>(n)] = 1;
    for (std::size_t i = 0; i < nodes; ++i)
      if (dims[i] < 3 && used[i] && !boundary[i] && !file_pins(i) && pinned[i] == kNotPinned)
        pinned[i] = kOnGmshFeature;
  }
  return pinned;
}

}  // namespace tetsmooth
