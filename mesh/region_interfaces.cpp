#include "mesh/region_interfaces.hpp"

#include <algorithm>

#include "mesh/topology.hpp"

namespace tetsmooth {

std::vector<std::uint8_t> region_interface_nodes(const TetMesh& mesh) {
  std::vector<std::uint8_t> interface(mesh.num_nodes(), 0);
  const std::vector<int>& tags = mesh.extras.tet_tags;
  if (tags.size() != mesh.num_tets()) return interface;
  const RowItems<FaceUse> uses = sorted_face_uses(mesh.tets);
  // The tags of the listings [b, e) of one tet, sorted, without repeats,
  // into `set` (two buffers reused across faces: a mesh has millions).
  const auto tag_set = [&](std::size_t b, std::size_t e, std::vector<int>& set) {
    set.clear();
    for (std::size_t k = b; k < e; ++k) set.push_back(tags[static_cast<std::size_t>(uses[k].tet)]);
    std::sort(set.begin(), set.end());
    set.erase(std::unique(set.begin(), set.end()), set.end());
  };
  std::vector<int> seen, set;
  for (std::size_t first = 0, last; first < uses.size(); first = last) {
    for (last = first + 1; last < uses.size() && uses[last].face == uses[first].face; ++last) {
    }
    // The run holds the face's tets one after another (by fourth node); the
    // face is an interface when two of them differ in tags.
    bool differs = false;
    for (std::size_t b = first, e; b < last && !differs; b = e) {
      for (e = b + 1; e < last && uses[e].opposite == uses[b].opposite; ++e) {
      }
      tag_set(b, e, set);
      differs = b != first && set != seen;
      std::swap(seen, set);
    }
    if (differs)
      for (index_t n : uses[first].face) interface[static_cast<std::size_t>(n)] = 1;
  }
  return interface;
}

}  // namespace tetsmooth
