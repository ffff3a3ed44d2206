#pragma once
// A solver's input deck or grid kept whole with the mesh read from it
// (Abaqus, Nastran, FLAC3D), so that the writer writes it back with new
// coordinates:
// the raw section "<format>:deck" records the nodes and tets it describes
// (not a public API).
#include <ostream>
#include <string>

#include "mesh/tet_mesh.hpp"

namespace tetsmooth {

// Records in mesh.extras that the deck read describes the mesh as it is.
void stamp_kept_deck(TetMesh& mesh, const std::string& format_key);

// Whether the mesh carries a deck stamped for `format_key` ("abaqus",
// "nastran", "flac3d").
bool has_kept_deck(const TetMesh& mesh, const std::string& format_key);

// Throws OutputError unless the deck still describes the mesh, with its
// node numbers: only coordinates change on the way through tetsmooth, and
// the deck's other lines are written as read. `file` names the deck in
// the message ("Abaqus deck").
void check_kept_deck(const TetMesh& mesh, const std::string& format_key, const char* file);

// A deck format's writer: the deck read with the mesh where it has one
// (write_kept), else a new deck (check_new, then write_new).
struct DeckWriter {
  const char* format_key;  // "abaqus"
  const char* file;        // "Abaqus deck", for messages
  void (*check_new)(const TetMesh& mesh);
  void (*write_kept)(const TetMesh& mesh, std::ostream& out);
  void (*write_new)(const TetMesh& mesh, std::ostream& out);

  // Throws OutputError when the mesh cannot be written (check_kept_deck, or
  // check_new).
  void check(const TetMesh& mesh) const;
  void write(const TetMesh& mesh, std::ostream& out) const;
  // Checked before the file is opened, written atomically (atomic_file.hpp).
  void write_file(const TetMesh& mesh, const std::string& path) const;

 private:
  void write_body(const TetMesh& mesh, std::ostream& out) const;
};

}  // namespace tetsmooth
