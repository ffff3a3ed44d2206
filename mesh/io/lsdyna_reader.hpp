#pragma once
// The LS-DYNA deck reader's state (not a public API: read_lsdyna in
// lsdyna_io.hpp is). lsdyna_reader.cpp takes the deck line by line and
// keeps what its keywords list by the deck's ids; lsdyna_resolve.cpp then
// turns ids into the mesh, its regions and its pins, since a set or a load
// may name a node defined after it.
#include <cstdint>
#include <istream>
#include <string>
#include <utility>
#include <vector>

#include "mesh/io/id_index.hpp"
#include "mesh/io/included_lines.hpp"
#include "mesh/io/lsdyna_cards.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::lsdyna {

class DeckReader {
 public:
  DeckReader(std::istream& in, const std::string& source) : lines_(in, source), source_(source) {}
  TetMesh read();

 private:
  // What the data cards under the current keyword are.
  enum class Section {
    Other,       // kept, not read
    Node,        // *NODE
    Solid,       // *ELEMENT_SOLID
    Shell,       // *ELEMENT_SHELL
    Beam,        // *ELEMENT_BEAM
    PinOnly,     // *ELEMENT_TSHELL, _DISCRETE, _MASS: node_fields_ name the nodes
    Part,        // *PART
    NodeSet,     // *SET_NODE, *SET_NODE_LIST
    NodeRanges,  // *SET_NODE_LIST_GENERATE
    Segments,    // *SET_SEGMENT
    NodeFields,  // loads and constraints: node_fields_ name the nodes
    Include,     // *INCLUDE: file names
    Ended,       // after *END
  };
  // Elements of one shape other than tets, in read order.
  struct Others {
    std::string kind;
    int nodes = 0;
    std::vector<long long> ids, nodes_of;
    std::vector<int> pids;
    std::vector<std::uint32_t> marks;
  };
  // Nodes that a set, a load or an element names (a single id is the range
  // (id, id)), and the keyword and line.
  struct PinRef {
    long long first, last;
    std::string keyword;
    std::uint32_t mark;
  };

  // lsdyna_reader.cpp: lines and keywords.
  // Keeps a line in the raw section of its kind (node data of the current
  // layout, or the rest); flush_kept closes the section.
  void keep(const std::string& line, bool node_data);
  void flush_kept();
  void keyword(const std::string& line);
  // A keyword line as the one output deck, which writes included files
  // inline, must read it.
  std::string written_inline(const std::string& line) const;
  void data(const std::string& line);
  void node(const std::string& line);
  void solid(const Card& card);
  void solid_nodes(const long long* n, int count);
  void shell(const Card& card);
  void beam(const Card& card);
  void part(const std::string& line);
  void node_list(const Card& card, bool ranges);
  void include(const std::string& line);
  long long id_field(std::string_view field, const char* what, bool zero_allowed = false) const;
  int pid_field(std::string_view field) const;
  void pin_fields(const Card& card, const std::vector<int>& fields);
  void other_element(const std::string& kind, int nodes, long long id, int pid, const long long* n);
  void keep_notes();
  [[noreturn]] void fail(const std::string& what) const;

  // lsdyna_resolve.cpp: ids into the mesh.
  void resolve();
  void resolve_pins(const IdIndex& nodes);
  index_t node_of(long long id, const IdIndex& nodes, std::uint32_t mark, const std::string& item) const;
  std::size_t orient_tets();

  IncludedLines lines_;
  std::string source_;
  TetMesh mesh_;
  std::string kept_;         // the deck's text since the last change between node data and the rest
  bool kept_nodes_ = false;  // whether kept_ is node data
  Layout node_layout_ = Layout::Standard, kept_layout_ = Layout::Standard;

  // The current keyword.
  Section section_ = Section::Other;
  std::string keyword_;           // its name, for messages and pins
  Layout layout_ = Layout::Standard;
  Layout deck_layout_ = Layout::Standard;     // the current file's: *KEYWORD's, or its *INCLUDE's
  Layout include_layout_ = Layout::Standard;  // the current *INCLUDE's, for the files it names
  struct OuterLayouts {
    Layout deck, include;
  };
  std::vector<OuterLayouts> outer_layouts_;  // those of the files that include the current one
  bool inline_comments_ = false;             // an included file's *KEYWORD section
  bool deck_keyword_ = false, deck_end_ = false;  // the deck's own *KEYWORD and *END, not an included file's
  int cards_each_ = 1;            // cards an element takes (options add some)
  int card_ = 0;                  // cards of the current element (or part) read so far
  bool title_pending_ = false;    // a _TITLE keyword's title card comes next
  bool head_pending_ = false;     // a set's first card (its id) comes next
  bool parts_all_ = true;         // a plain *PART: every card pair is a part
  std::vector<int> node_fields_;  // NodeFields, PinOnly: fields that name nodes
  std::string include_name_;       // a file name continued on the next card (" +")

  // What the deck lists.
  std::vector<std::uint32_t> node_marks_;
  std::vector<std::uint8_t> constrained_;  // per node: TC or RC not 0
  std::vector<long long> solid_ids_;       // every solid, for repeats
  std::vector<std::uint32_t> solid_marks_;
  long long pending_id_ = 0;  // the current solid's EID and PID
  bool two_card_ = false;     // its nodes on its second card
  int pending_pid_ = 0;
  std::vector<long long> tet_nodes_;
  std::vector<std::uint32_t> tet_marks_;
  int tet_nodes_each_ = 0;
  std::vector<Others> others_;
  std::vector<PinRef> pin_refs_;
  int part_pid_card_ = 0;  // *PART: 0 before the heading, 1 before the PID card
  std::string part_heading_;
  std::vector<std::pair<int, std::string>> part_names_;
  // Keywords kept and not read, elements that only pin, keywords that name
  // nodes which are not pinned.
  std::vector<std::string> keywords_, uncarried_, unread_;
};

}  // namespace tetsmooth::lsdyna
