#pragma once
// Medit .mesh (ASCII) reading and writing. The reader validates the mesh and
// throws InputError naming the source and line; the file writer writes
// atomically (mesh/io/atomic_file.hpp) and throws OutputError; it refuses
// second-order tets (Medit's P2 sections are neither read nor written).
#include <iosfwd>
#include <string>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

TetMesh read_medit(std::istream& in, const std::string& source);
TetMesh read_medit_file(const std::string& path);

void write_medit(const TetMesh& mesh, std::ostream& out);
void write_medit_file(const TetMesh& mesh, const std::string& path);

}  // namespace tetsmooth
