#pragma once
// The Nastran deck reader's state (not a public API: read_nastran in
// nastran_io.hpp is). nastran_reader.cpp takes the deck entry by entry and
// keeps what it lists by the file's ids; nastran_resolve.cpp then turns ids
// into the mesh, its regions and its pins once every entry is read, since
// an entry may name a grid point defined after it.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "mesh/tet_mesh.hpp"
#include "mesh/io/id_index.hpp"
#include "mesh/io/nastran_cards.hpp"
#include "mesh/io/nastran_entry_types.hpp"

namespace tetsmooth::nastran {

class DeckReader {
 public:
  DeckReader(BulkCards& cards, std::string source) : cards_(cards), source_(std::move(source)) {}
  TetMesh read();

 private:
  // Elements of one shape other than tets, in read order.
  struct Others {
    std::string kind;
    int nodes = 0;
    bool tagged = false;  // the type has a PID
    std::vector<long long> ids, grids;
    std::vector<int> pids;
    std::vector<std::uint32_t> marks;  // each element's line
  };
  // Grid points that a load, a constraint or an element names (a single id
  // is the range (id, id)), and the entry's name and line.
  struct PinRef {
    long long first, last;
    const char* entry;
    std::uint32_t mark;
  };
  // What a GRID leaves blank that GRDSET gives.
  enum GridBits : std::uint8_t { kPsGiven = 1, kPsBlank = 2, kCpBlank = 4 };

  // nastran_reader.cpp: the entries.
  void keep(const std::string& text, bool grid);
  void entry(const Card& card);
  void grid(const Card& card);
  void tet(const Card& card);
  void element(const EntryType& type, const Card& card);
  void pins(const EntryType& type, const Card& card);
  void orientation_pin(const EntryType& type, const Card& card);
  void pinned_comment(const std::string& line);
  void keep_notes();

  // nastran_resolve.cpp: ids and pins.
  void resolve();
  void resolve_pins(const IdIndex& nodes);
  index_t node_of(long long id, const IdIndex& nodes, std::uint32_t mark, long long element) const;
  bool scalar_point(long long id) const;

  BulkCards& cards_;
  std::string source_;
  TetMesh mesh_;
  std::string kept_;         // the deck's text since the last change between GRID runs and the rest
  bool kept_grids_ = false;  // whether kept_ is a run of GRID entries
  // Marks of the lines that define each node and element (BulkCards::where).
  std::vector<std::uint32_t> node_marks_;
  std::vector<std::uint8_t> grid_bits_;  // GridBits per node
  std::vector<long long> element_ids_;   // every element, for repeats
  std::vector<std::uint32_t> element_marks_;
  std::vector<long long> tet_grids_;
  std::vector<std::uint32_t> tet_marks_;
  int tet_nodes_each_ = 0;
  bool meshio_tets_ = false;  // CTETRA_ read (meshio's name for 10-node tets)
  std::vector<Others> others_;
  std::vector<PinRef> pin_refs_;
  std::vector<std::pair<long long, long long>> scalar_points_;  // SPOINT, EPOINT
  // GRDSET's defaults for blank GRID fields: its CP and PS, and its line.
  std::string grdset_cp_, grdset_ps_;
  std::uint32_t grdset_mark_ = 0;
  // Entry types: those not read (for other formats' notes), elements that
  // only pin, types known to name grid points in layouts not read, and
  // types not known at all.
  std::vector<std::string> types_, uncarried_, unread_, unknown_;
};

}  // namespace tetsmooth::nastran
