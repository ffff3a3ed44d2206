#pragma once
// Internals of the Gmsh reader. A source hands out the values of an MSH file
// one at a time, as text tokens (ASCII files) or raw bytes (binary files),
// so that one parser per section serves both encodings; both name the file
// and the line (ASCII) or byte offset (binary) in every error. The section
// parsers fill a ReadState, which gmsh_reader.cpp turns into the TetMesh.
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "mesh/io/gmsh_detail.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/tet_mesh.hpp"

namespace tetsmooth::gmsh {

class AsciiSource {
 public:
  static constexpr bool kBinary = false;

  explicit AsciiSource(TextLines& lines) : lines_(lines) {}

  // Section framing: the next "$Name" line, or an empty view at the end of
  // the file; and the check of the "$EndName" that must close a section.
  std::string_view next_section();
  void expect_end(std::string_view end_name);
  // Skips an unknown section up to and including its end line.
  void skip_section(std::string_view end_name);

  // The next whole line (trimmed); for the text parts of a section.
  std::string_view line(const char* what);

  std::uint64_t size_value(const char* what);  // a count or tag, >= 0
  int int_value(const char* what);
  double real_value(const char* what);  // finite values only
  // A count the MSH 2 binary encoding writes as text; here it is any count.
  std::uint64_t text_count(const char* what) { return size_value(what); }

  // How many items to reserve room for when a header announces `count` of
  // them. Text gives no bound on what is left, so the reservation is capped
  // and the containers grow as the items are actually read.
  std::size_t reservable(std::uint64_t count, std::size_t /*min_bytes_each*/) const {
    return count < kReserveCap ? static_cast<std::size_t>(count) : kReserveCap;
  }

  // While recording, every line that is started is appended (trimmed, with a
  // newline) to the record: how a section body is kept verbatim.
  void start_recording();
  std::string stop_recording();

  std::string where() const { return lines_.where(); }
  [[noreturn]] void fail(const std::string& what) const { lines_.fail(what); }

 private:
  static constexpr std::size_t kReserveCap = std::size_t{1} << 16;

  bool advance();  // to the next line holding a token; false at the end
  void alone_on_line(std::string_view name) const;
  std::string_view token(const char* what);
  std::string_view current_line() const;

  TextLines& lines_;
  std::size_t taken_ = 0;  // tokens of the current line already used
  bool started_ = false;
  bool recording_ = false;
  std::string record_;
};

class BinarySource {
 public:
  static constexpr bool kBinary = true;

  // `data` holds the file from byte `base` on; `swap` when the file was
  // written with the other byte order.
  BinarySource(std::string data, std::size_t base, bool swap, std::string source)
      : data_(std::move(data)), base_(base), swap_(swap), source_(std::move(source)) {}

  std::string_view next_section();
  void expect_end(std::string_view end_name);
  void skip_section(std::string_view end_name);

  std::string_view line(const char* what);

  std::uint64_t size_value(const char* what);
  int int_value(const char* what);
  double real_value(const char* what);
  std::uint64_t text_count(const char* what);

  // Fails unless `count` items of at least `min_bytes_each` bytes fit in
  // what is left of the file: a corrupted count must not allocate.
  std::size_t reservable(std::uint64_t count, std::size_t min_bytes_each) const;

  std::string where() const;
  [[noreturn]] void fail(const std::string& what) const;

 private:
  void read_raw(void* out, std::size_t bytes, const char* what);
  void skip_blank();
  std::string_view raw_line();

  std::string data_;
  std::size_t pos_ = 0;
  std::size_t base_;
  bool swap_;
  std::string source_;
};

// The body of a $Entities section (MSH 4.1), either encoding.
template <class Source>
Entities read_entities(Source& src);

// The body of a $PartitionedEntities section (MSH 4.1), either encoding:
// the entities of the partitions, each naming its parent model entity. The
// ghost entities it lists are left out (their elements are in
// $GhostElements, which is skipped).
template <class Source>
Entities read_partitioned_entities(Source& src);

// Node tag -> 0-based index, for tags dense or sparse.
class NodeLookup {
 public:
  // Returns a tag that occurs twice, or -1 when all are distinct.
  long long build(const std::vector<long long>& tags);
  index_t find(long long tag) const;  // -1 when absent

 private:
  std::vector<index_t> dense_;                         // by tag, when tags are dense enough
  std::vector<std::pair<long long, index_t>> sparse_;  // sorted by tag, otherwise
};

// MSH 2.2 element lines beyond one element each: an element in several
// physical groups is listed once per group (see v22_physicals), and a
// partitioned file gives elements partition tags after the elementary one.
struct V22Lines {
  // The previous line's element, to tell a repeat of it from a new element:
  // same number, type, elementary tag and nodes.
  bool any = false;
  bool repeats = false;  // whether it was listed more than once
  long long id = 0;
  int type = 0;
  int elementary = 0;
  std::vector<index_t> nodes;
  // The physical groups met on each entity (dimension, elementary tag), in
  // order, with its element and line counts, whether each element's first
  // line names the first group and whether an element is in none: every
  // element is in all of the entity's groups when lines == elements *
  // groups, each first line names the first and none is in no group.
  struct Groups {
    std::vector<int> physicals;
    std::size_t elements = 0, lines = 0;
    bool first_agrees = true;
    bool ungrouped = false;
  };
  std::map<std::pair<int, int>, Groups> entities;
  std::size_t repeated = 0;     // elements listed more than once
  std::size_t partitioned = 0;  // elements with partition tags
};

// What the section parsers build up while reading one file.
struct ReadState {
  int major = 0;  // MSH version, 2 or 4
  TetMesh mesh;
  NodeLookup lookup;
  bool has_nodes = false;
  bool has_elements = false;
  bool has_entities = false;
  bool has_partitions = false;
  Entities entities;
  Entities partitions;  // of $PartitionedEntities: tags distinct from those of `entities`
  std::vector<std::pair<int, std::size_t>> block_of_type;  // element type id -> index in mesh.extras.blocks
  V22Lines v22;
  int tet_type = 0;  // the type of the first tet read (kTetType or kTet10Type), 0 before it

  PassThroughBlock& block_for(const ElementType& type);
};

// A mesh has 4-node or 10-node tets, not both: fails where the first tet of
// the other kind is read.
template <class Source>
void check_tet_kind(Source& src, ReadState& state, const ElementType& type) {
  if (!is_tet_type(type.id)) return;
  if (state.tet_type == 0) state.tet_type = type.id;
  if (type.id != state.tet_type) src.fail(mixed_tet_kinds(type.nodes));
}

// A node or element tag, a size_t in the format, as the long long it is
// kept in; fails naming `what` when it does not fit.
template <class Source>
long long tag_value(Source& src, const char* what) {
  const std::uint64_t tag = src.size_value(what);
  if (tag > static_cast<std::uint64_t>(INT64_MAX)) src.fail(std::string(what) + " " + std::to_string(tag) + " is too large");
  return static_cast<long long>(tag);
}

// The 0-based index of node `tag`; fails naming the tag when it is unknown.
template <class Source>
index_t node_index(Source& src, const ReadState& state, std::uint64_t tag) {
  const index_t i = tag > static_cast<std::uint64_t>(INT64_MAX) ? -1 : state.lookup.find(static_cast<long long>(tag));
  if (i < 0) src.fail("element refers to node tag " + std::to_string(tag) + ", which is not in $Nodes");
  return i;
}

// Section bodies, read after their "$Name" line and up to their "$EndName".
template <class Source>
void read_nodes_v41(Source& src, ReadState& state);
template <class Source>
void read_elements_v41(Source& src, ReadState& state);
// MSH 2.2 $Nodes, or with `parametric` $ParametricNodes (Mesh.SaveParametric):
// each node then gives the entity it is classified on, dimension and tag,
// and up to two parametric coordinates (u on a curve, u v on a surface).
// Both are read past, the coordinates with the note of parametric_note.
template <class Source>
void read_nodes_v22(Source& src, ReadState& state, bool parametric);
void read_elements_v22(AsciiSource& src, ReadState& state);
void read_elements_v22(BinarySource& src, ReadState& state);

// The read note for parametric coordinates dropped from `nodes` nodes.
std::string parametric_note(std::uint64_t nodes);

// After an MSH 2.2 $Elements: makes the groups of elements listed once per
// group the physical groups of their entities, in a "$Entities" raw section
// that the writer keeps, where every element of an entity is in all of its
// groups (files Gmsh and tetsmooth write are so); otherwise the elements
// keep their first group, with a note. Notes the partition tags dropped.
void finish_elements_v22(ReadState& state);

}  // namespace tetsmooth::gmsh
