#pragma once
// Gmsh MSH reading (2.2 and 4.1, ASCII or binary, detected from $MeshFormat)
// and writing (4.1 ASCII, 4.1 binary, 2.2 ASCII). Readers validate the mesh
// and throw InputError naming the source and line or byte offset; file
// writers write atomically (mesh/io/atomic_file.hpp) and throw OutputError.
#include <iosfwd>
#include <string>

#include "mesh/io/mesh_io.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

enum class MshFlavour { V41Ascii, V41Binary, V22Ascii };

// Detects the version and binary/ASCII encoding from $MeshFormat.
TetMesh read_gmsh(std::istream& in, const std::string& source);
TetMesh read_gmsh_file(const std::string& path);

// Fields go out as $NodeData/$ElementData, whose tags are 32-bit ints: node
// fields are left out where a kept node tag exceeds gmsh::kLargestIntTag
// (MSH 4.1 only; MSH 2.2 numbers such nodes 1, 2, ...). Negative region tags
// become new positive physical tags (gmsh::negative_tag_renumbering).
void write_gmsh(const TetMesh& mesh, std::ostream& out, MshFlavour flavour, const MeshFields& fields);
void write_gmsh_file(const TetMesh& mesh, const std::string& path, MshFlavour flavour,
                     const MeshFields& fields);

}  // namespace tetsmooth
