#pragma once
// The ANSYS file reader's state (not a public API: read_ansys in
// ansys_io.hpp is). ansys_reader.cpp walks the file's lines, its commands
// and blocks, keeping what they list by the file's numbers;
// ansys_resolve.cpp then turns numbers into the mesh, its regions and its
// pins, since a component or a load may name items before or after the
// block that defines them.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "mesh/io/ansys_fields.hpp"
#include "mesh/io/id_index.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::ansys {

// The most nodes an element record may list (ANSYS's have 20 at most).
constexpr std::size_t kMostNodes = 200;

class FileReader {
 public:
  FileReader(std::string text, std::string source) : text_(std::move(text)), source_(std::move(source)) {}
  TetMesh read();

 private:
  // An element as its EBLOCK record lists it.
  struct Element {
    long long number = 0, type = 0;
    int mat = 0;
    bool solid = true;                 // from an EBLOCK with SOLID (else its nodes only pin)
    std::size_t first = 0, count = 0;  // its nodes in element_nodes_
    std::size_t line = 0;
  };
  // A CMBLOCK: its items as ranges of numbers (first, last).
  struct Component {
    std::string name;
    bool nodes = true;  // NODE, else ELEM
    std::vector<std::pair<long long, long long>> ranges;
    std::size_t line = 0;
  };
  struct ElementType {
    int number = -1;   // the ANSYS type (187), or -1
    std::string name;  // as ET gave it
    std::size_t line = 0;
  };

  // ansys_reader.cpp: lines, commands and blocks.
  bool next_line();
  // Keeps the current line in the raw section of its kind: the file's
  // text, or NBLOCK records; flush_kept closes the section.
  void keep(bool nblock);
  void flush_kept();
  void commands(std::string_view line);
  void command(const std::vector<std::string_view>& fields);
  void element_type(const std::vector<std::string_view>& fields);
  void pin_fields(const std::vector<std::string_view>& fields, std::initializer_list<std::size_t> places,
                  const std::string& name);
  // A command's node (field `node`) and, where it gives them, the range's
  // end and step (fields `end` and `end + 1`: NEND, NINC of D, F, IC and M;
  // NODE2, NINC of CPNGEN).
  void pin_range(const std::vector<std::string_view>& fields, std::size_t node, std::size_t end,
                 const std::string& name);
  void etblock();
  // A text as a whole number: an integer, a whole real, or a parameter
  // that *SET or NAME=value gave one.
  bool number_of(std::string_view text, long long& value) const;
  void parameter(std::string_view name, std::string_view value);
  BlockFormat block_format(const char* block);
  void nblock();
  void eblock(bool solid, long long nodes_per_record);
  void cmblock(const std::vector<std::string_view>& fields);
  long long int_field(std::string_view record, const BlockFormat& f, std::size_t k, const char* what) const;
  [[noreturn]] void fail(const std::string& what) const;
  [[noreturn]] void fail_at(std::size_t line, const std::string& what) const;

  // ansys_resolve.cpp: numbers into the mesh.
  void resolve();
  void resolve_elements(const IdIndex& nodes);
  void resolve_regions(const IdIndex& elements);
  void resolve_pins(const IdIndex& nodes);
  void keep_notes();

  std::string text_;
  std::string source_;
  std::size_t at_ = 0;       // the next line's first byte in text_
  std::size_t line_no_ = 0;  // the current line's number
  std::string_view line_;    // the current line, without its end ('\n', and a '\r' before it)
  std::string_view raw_;     // the current line with its end

  TetMesh mesh_;
  // The bytes of text_ not yet in a raw section, since the last switch
  // between NBLOCK records and the rest, and which of the two they are.
  std::size_t kept_begin_ = 0, kept_end_ = 0;
  bool kept_nblock_ = false;
  std::vector<long long> node_numbers_;
  std::vector<std::size_t> node_lines_;
  std::vector<Element> elements_;
  std::vector<long long> element_nodes_;
  std::vector<Component> components_;
  std::map<long long, ElementType> types_;
  // Node numbers that commands name: first, first + step, ... up to last
  // (a single node is the range (n, n, 1)), and the command's line.
  struct PinnedRange {
    long long first, last, step;
    std::size_t line;
  };
  std::vector<PinnedRange> pinned_;
  std::vector<std::string> commands_;  // other command names, once each
  std::unordered_set<std::string> seen_commands_;
  std::map<std::string, long long> parameters_;  // scalar parameters with whole values
  // Words that loads give where a node goes (component names, mostly), and
  // the command: those that no CMBLOCK defines are noted.
  std::vector<std::pair<std::string, std::string>> named_components_;
  std::size_t block_closed_ = 0;            // the line of the last block's closing -1
  std::vector<std::string> uncarried_;      // element types that only pin
  std::vector<std::string> by_selection_;   // commands that named nodes through the selection
  std::vector<std::string> cdwrite_forms_;  // commands in a form whose nodes are not read
  std::vector<std::string> generated_;      // commands that make coupled sets or equations from others
  // Each element's tet (or -1).
  std::vector<long long> tet_of_element_;
  // Each element's (block, place in it) where it passes through as a
  // solid, else kNotPassed.
  static constexpr std::pair<std::size_t, std::size_t> kNotPassed{SIZE_MAX, 0};
  std::vector<std::pair<std::size_t, std::size_t>> block_element_;
};

}  // namespace tetsmooth::ansys
