#pragma once
// The Abaqus deck reader's state (not a public API: read_abaqus in
// abaqus_io.hpp is). abaqus_reader.cpp takes the deck line by line and keeps
// what it lists by the file's numbers; abaqus_resolve.cpp then turns numbers
// and set names into the mesh, its regions and its pins, once every line is
// read, as Abaqus resolves them.
#include <cstdint>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "mesh/tet_mesh.hpp"
#include "mesh/io/abaqus_deck_lines.hpp"
#include "mesh/io/abaqus_element_types.hpp"
#include "mesh/io/abaqus_regions.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/io/abaqus_sets.hpp"

namespace tetsmooth::abaqus {

class DeckReader {
 public:
  explicit DeckReader(DeckLines& lines) : lines_(lines) {}
  TetMesh read(const std::string& source);

  // Where the data lines of a keyword that loads or constrains nodes name
  // them (see kPinKeywords in abaqus_reader.cpp).
  enum class Names { First, AfterFirst, EveryThird };

 private:
  enum class Block { None, Other, Node, Element, Set, Pins };
  // Elements of one kind other than tets, in read order.
  struct Others {
    ElementType type;
    std::vector<long long> ids, nodes;  // nodes in PassThroughBlock order, by file id
    std::vector<std::uint32_t> elsets;  // see tags_from_element_sets (abaqus_regions.hpp)
  };
  // A node or node set that a load or constraint names, and its line.
  struct PinRef {
    std::string name;
    std::uint32_t mark;
  };

  // abaqus_reader.cpp: the lines.
  void keyword();
  void data();
  void flush_nodes();  // ends a run of node lines in the kept deck
  void append_text(const std::string& line);
  void finish_block();
  void start_element_block(const Keyword& kw);
  void start_set(const Keyword& kw);
  void node_line();
  void element_line();
  void add_element();
  void set_line();
  void pin_line();
  std::uint32_t elset_index(const std::string* name);
  void note_elset(const std::string& name, const std::string& written);
  std::string element_text() const;

  // abaqus_resolve.cpp: numbers and names.
  void resolve();
  void resolve_regions(const IdIndex& element_ids, RegionNames& names);
  void resolve_pins(const IdIndex& node_ids, const IdIndex& element_ids);
  std::vector<std::size_t> tets_of(const std::vector<std::size_t>& elements) const;
  void name_regions_by_lists(const std::vector<std::vector<std::size_t>>& tets_of_sets, RegionNames& names) const;
  void keep_deck_notes();

  DeckLines& lines_;
  TetMesh mesh_;
  DeckSets sets_;
  Block block_ = Block::None;
  Names pin_names_ = Names::First;

  std::string text_;          // the deck since the last run of node lines
  std::size_t node_run_ = 0;  // node lines since the last text
  std::string node_set_;      // NSET= of the current *NODE
  std::size_t block_first_ = 0;
  std::vector<std::uint32_t> node_marks_;  // per node, its line (DeckLines::mark)

  ElementType type_;
  std::string type_name_;
  std::uint32_t elset_ = 0;
  std::string elset_name_;
  std::vector<long long> pending_;  // an element's id and nodes so far
  std::uint32_t pending_mark_ = 0;

  std::vector<long long> element_ids_;        // every element, in read order
  std::vector<std::uint32_t> element_marks_;  // per element, its first line
  std::vector<std::int64_t> element_at_;      // per element: tet index, or -1 - its place in others_at_
  std::vector<std::pair<std::size_t, std::size_t>> others_at_;  // (block, element) of each other element
  std::vector<long long> tet_ids_, tet_nodes_;
  int tet_nodes_each_ = 0;
  std::vector<std::uint32_t> tet_elsets_;
  std::vector<Others> others_;
  // ELSET= names of *ELEMENT lines (set_name; as written), and their
  // indices + 1.
  std::vector<std::string> elset_names_, elset_written_;
  std::unordered_map<std::string, std::uint32_t> elset_numbers_;
  // Every element set, in the order defined (set_name; as first written).
  std::vector<std::string> elset_order_, elset_order_written_;
  std::unordered_set<std::string> elsets_met_;

  SetPart part_;
  std::string set_name_;
  bool set_of_nodes_ = false, generate_ = false, lists_elsets_ = false;

  struct Section {
    std::string elset, where, written;  // its ELSET= (set_name), its line, the name as written
  };
  std::vector<Section> sections_;
  std::vector<PinRef> pin_refs_;
  std::vector<std::string> other_keywords_;  // as written, each once
};

}  // namespace tetsmooth::abaqus
