#pragma once
// The Abaqus deck reader's state (not a public API: read_abaqus in
// abaqus_io.hpp is). abaqus_reader.cpp takes the deck line by line and keeps
// what it lists by the file's numbers; abaqus_resolve.cpp then turns numbers
// and set names into the mesh, its regions and its pins, once every line is
// read, as Abaqus resolves them.
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

#include "mesh/io/abaqus_deck_lines.hpp"
#include "mesh/io/abaqus_element_types.hpp"
#include "mesh/io/abaqus_placement.hpp"
#include "mesh/io/abaqus_regions.hpp"
#include "mesh/io/abaqus_scopes.hpp"
#include "mesh/io/abaqus_sets.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::abaqus {

class DeckReader {
 public:
  explicit DeckReader(DeckLines& lines) : lines_(lines) {}
  TetMesh read(const std::string& source);

  // Where the data lines of a keyword that loads or constrains nodes name
  // them (see kPinKeywords in abaqus_reader.cpp).
  enum class Names { First, AfterFirst, EveryThird };

 private:
  enum class Block { None, Other, Node, Element, Set, Pins, Instance };
  // Elements of one kind other than tets, in read order.
  struct Others {
    ElementType type;
    std::vector<long long> ids, nodes;  // nodes in PassThroughBlock order, by key
    std::vector<std::uint32_t> elsets;  // see tags_from_element_sets (abaqus_regions.hpp)
  };
  // A node or node set that a load or constraint names, and its line.
  struct PinRef {
    std::string name;
    std::uint32_t mark;
    std::size_t scope;  // the part it was read in (abaqus_scopes.hpp), 0 outside parts
  };
  // A *PART: its name (set_name; as written), its line, and its nodes and
  // elements (read indices: a part's items come in one run).
  struct Part {
    std::string name, written, where;
    std::size_t node_first = 0, node_end = 0, element_first = 0, element_end = 0;
    std::size_t instance = 0;  // its *INSTANCE's index + 1, 0 for none
  };
  struct Instance {
    std::string name, written, where;
    std::size_t part;  // index in parts_
    Placement placement;
  };
  // A node or set that a data line names, as the reader finds it: a node
  // by key (abaqus_scopes.hpp), or a set by name (set_key).
  struct Ref {
    bool is_node;
    long long key;
    std::string set;
  };
  enum class Level { Model, Part, Assembly, Instance };

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
  std::string set_in_data(std::string_view field) const;  // a set that a set's line names, as set_key
  long long number_key(long long number) const;           // an item that a set's line numbers
  void pin_line();
  std::uint32_t elset_index(const std::string* name);
  void note_elset(const std::string& name, const std::string& written);
  std::string element_text() const;

  // abaqus_assembly.cpp: parts, the assembly, instances.
  bool structure_keyword(const Keyword& kw);       // false for keywords of no structure
  void check_mesh_level(const Keyword& kw) const;  // *NODE and *ELEMENT
  void finish_instance();
  void finish_structure();
  void drop_part(std::size_t part);  // a part without an instance leaves the mesh
  bool has_parts() const { return !parts_.empty(); }
  long long key(std::size_t scope, long long number) const;  // fails at the current line if too large
  // A set's key: its name (set_name) within a part, "PART/NAME".
  std::string set_key(std::size_t scope, const std::string& name) const;
  std::string set_written(std::size_t scope, const std::string& written) const;  // "Part.Name"
  Ref reference(std::string_view field, std::size_t scope, const std::string& where) const;
  long long shown(long long key) const { return number_of_key(key, has_parts()); }
  void place_instances();

  // abaqus_resolve.cpp: numbers and names.
  void resolve();
  void resolve_regions(const IdIndex& element_ids, RegionNames& names);
  void resolve_pins(const IdIndex& node_ids, const IdIndex& element_ids);
  std::vector<std::size_t> tets_of(const std::vector<std::size_t>& elements) const;
  void name_regions_by_lists(const std::vector<std::vector<std::size_t>>& tets_of_sets, RegionNames& names) const;
  void keep_deck_notes();

  DeckLines& lines_;
  TetMesh mesh_;
  std::vector<long long> node_keys_;                            // per node (abaqus_scopes.hpp)
  std::vector<std::pair<std::size_t, std::size_t>> node_runs_;  // (raw section, first node) of each run

  Level level_ = Level::Model;
  std::size_t scope_ = 0;      // the part being read (index + 1), 0 outside parts
  std::size_t set_scope_ = 0;  // the part whose numbers a set's lines give
  bool assembly_seen_ = false;
  std::string assembly_where_;
  std::vector<Part> parts_;
  std::vector<Instance> instances_;
  std::vector<std::vector<std::string>> instance_lines_;  // data lines of the current *INSTANCE
  std::uint32_t instance_mark_ = 0;
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
  std::vector<long long> element_keys_;       // per element (abaqus_scopes.hpp)
  std::vector<std::uint32_t> element_marks_;  // per element, its first line
  std::vector<std::int64_t> element_at_;      // per element: tet index, or -1 - its place in others_at_
  std::vector<std::pair<std::size_t, std::size_t>> others_at_;  // (block, element) of each other element
  std::vector<long long> tet_ids_, tet_nodes_;                  // nodes by key
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
