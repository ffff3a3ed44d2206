#include "mesh/io/field_check.hpp"

#include <stdexcept>
#include <string>

namespace tetsmooth {

void check_field_sizes(const TetMesh& mesh, const MeshFields& fields) {
  const auto check = [](const auto& list, std::size_t expected, const char* per) {
    for (const auto& [name, values] : list)
      if (values.size() != expected)
        throw std::invalid_argument("field '" + name + "' has " + std::to_string(values.size()) + " values, expected " +
                                    std::to_string(expected) + " (one per " + per + ")");
  };
  check(fields.node_scalars, mesh.num_nodes(), "node");
  check(fields.tet_scalars, mesh.num_tets(), "tet");
}

}  // namespace tetsmooth
