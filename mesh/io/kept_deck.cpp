#include "mesh/io/kept_deck.hpp"

#include "mesh/errors.hpp"
#include "mesh/io/atomic_file.hpp"

namespace tetsmooth {
namespace {

std::string counts(const TetMesh& mesh) {
  return std::to_string(mesh.num_nodes()) + " " + std::to_string(mesh.num_tets());
}

}  // namespace

void stamp_kept_deck(TetMesh& mesh, const std::string& format_key) {
  mesh.extras.raw_sections.emplace_back(format_key + ":deck", counts(mesh));
}

bool has_kept_deck(const TetMesh& mesh, const std::string& format_key) {
  return raw_section(mesh.extras, format_key + ":deck") != nullptr;
}

void check_kept_deck(const TetMesh& mesh, const std::string& format_key, const char* file) {
  const std::string expected = counts(mesh);
  const std::string& stamp = *raw_section(mesh.extras, format_key + ":deck");
  const bool numbered = mesh.extras.node_tags.size() == mesh.num_nodes();
  if (stamp != expected || !numbered)
    throw OutputError(std::string("the ") + file + " read with this mesh lists (nodes, tets) " + stamp +
                      ", and the mesh has " + expected + (numbered ? "" : " without their numbers") +
                      ": it is written back only for the mesh it was read with");
}

void DeckWriter::check(const TetMesh& mesh) const {
  if (has_kept_deck(mesh, format_key))
    check_kept_deck(mesh, format_key, file);
  else
    check_new(mesh);
}

void DeckWriter::write_body(const TetMesh& mesh, std::ostream& out) const {
  if (has_kept_deck(mesh, format_key))
    write_kept(mesh, out);
  else
    write_new(mesh, out);
}

void DeckWriter::write(const TetMesh& mesh, std::ostream& out) const {
  check(mesh);
  write_body(mesh, out);
  if (!out) throw OutputError(std::string("the ") + file + " output stream failed");
}

void DeckWriter::write_file(const TetMesh& mesh, const std::string& path) const {
  checked_for(path, [&] { check(mesh); });
  write_atomically(path, [&](std::ostream& out) { write_body(mesh, out); });
}

}  // namespace tetsmooth
