// Nastran bulk data reading (nastran_io.hpp): entries taken one by one
// (nastran_cards), kept by the file's ids, then turned into the mesh, its
// regions and its pins once every entry is read, since an entry may name a
// grid point defined after it.
#include <algorithm>
#include <cctype>
#include <cstdint>
#include <sstream>

#include "mesh/errors.hpp"
#include "mesh/io/id_index.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/kept_deck.hpp"
#include "mesh/io/nastran_cards.hpp"
#include "mesh/io/nastran_entry_types.hpp"
#include "mesh/io/nastran_fields.hpp"
#include "mesh/io/nastran_io.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/second_order.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {
namespace nastran {
namespace {

// CTETRA lists its midside nodes in kTetEdges order, after the corners.
constexpr MidsidePlaces kMidsidePlaces = {4, 5, 6, 7, 8, 9};

// The comment that keeps pins no entry keeps (nastran_io.hpp), upper case.
constexpr std::string_view kPinnedComment = "TETSMOOTH PINNED";

std::string joined(const std::vector<std::string>& items) {
  std::string list;
  for (const std::string& item : items) list += (list.empty() ? "" : ", ") + item;
  return list;
}

void add_once(std::vector<std::string>& list, const std::string& item) {
  if (std::find(list.begin(), list.end(), item) == list.end()) list.push_back(item);
}

// A PID field: blank is 0.
int pid_field(const std::string& field, const std::string& where) {
  long long pid = 0;
  if (!field.empty() && (!parse_integer(field, pid) || pid < 0 || pid > INT32_MAX))
    throw InputError(where, "expected a property id (PID), found " + quoted_token(field));
  return static_cast<int>(pid);
}

// Elements of one shape other than tets, in read order.
struct Others {
  std::string kind;
  int nodes = 0;
  bool tagged = false;  // the type has a PID
  std::vector<long long> ids, grids;
  std::vector<int> pids;
  std::vector<std::uint32_t> marks;  // each element's line
};

// Grid points that a load, a constraint or an element that only pins names.
struct PinRef {
  long long first, last;
  std::uint32_t mark;  // its line
};

class DeckReader {
 public:
  DeckReader(BulkCards& cards, std::string source) : cards_(cards), source_(std::move(source)) {}
  TetMesh read();

 private:
  void keep(const std::string& text, bool grid);
  void grid(const Card& card);
  void tet(const Card& card);
  void element(const EntryType& type, const Card& card);
  void pinned_comment(const std::string& line);
  index_t node_of(long long id, const IdIndex& nodes, std::uint32_t mark, long long element) const;
  void resolve();
  void resolve_pins(const IdIndex& nodes);

  BulkCards& cards_;
  std::string source_;
  TetMesh mesh_;
  std::string kept_;         // the deck's text since the last change between GRID runs and the rest
  bool kept_grids_ = false;  // whether kept_ is a run of GRID entries
  // Marks of the lines that define each node and element (BulkCards::where).
  std::vector<std::uint32_t> node_marks_;
  std::vector<std::uint8_t> ps_pinned_;
  std::vector<long long> element_ids_;  // every element, for repeats
  std::vector<std::uint32_t> element_marks_;
  std::vector<long long> tet_grids_;
  std::vector<std::uint32_t> tet_marks_;
  int tet_nodes_each_ = 0;
  std::vector<Others> others_;
  std::vector<PinRef> pin_refs_;
  std::vector<std::string> types_, uncarried_;
};

void DeckReader::keep(const std::string& text, bool grid) {
  if (grid != kept_grids_ && !kept_.empty()) {
    mesh_.extras.raw_sections.emplace_back(kept_grids_ ? "nastran:grids" : "nastran:text", std::move(kept_));
    kept_.clear();
  }
  kept_grids_ = grid;
  kept_ += text;
}

void DeckReader::grid(const Card& card) {
  const std::string where = cards_.where(card.mark);
  const long long id = id_field(card.field(0), "a grid point id", where);
  if (const std::string& cp = card.field(1); !cp.empty() && cp != "0")
    throw InputError(where, "GRID " + std::to_string(id) + " is given in coordinate system " + text_excerpt(cp) +
                                ": nodes in other coordinate systems than the basic one are not read");
  for (std::size_t c = 0; c < 3; ++c) {
    double v = 0;  // a blank coordinate is 0
    const std::string& f = card.field(2 + c);
    if (!f.empty() && !parse_real_field(f, v))
      throw InputError(where,
                       "GRID " + std::to_string(id) + ": expected a finite coordinate, found " + quoted_token(f));
    mesh_.xyz.push_back(v);
  }
  mesh_.extras.node_tags.push_back(id);
  node_marks_.push_back(card.mark);
  const std::string& ps = card.field(6);
  ps_pinned_.push_back(!ps.empty() && ps != "0");
}

void DeckReader::tet(const Card& card) {
  const std::string where = cards_.where(card.mark);
  const long long id = id_field(card.field(0), "an element id", where);
  int listed = 0;
  for (std::size_t k = 0; k < 10; ++k) listed += !card.field(2 + k).empty();
  const bool four = listed == 4 && std::all_of(card.fields.begin() + 2, card.fields.begin() + 6,
                                               [](const std::string& f) { return !f.empty(); });
  if (!four && listed != 10)
    throw InputError(where, "CTETRA " + std::to_string(id) + " lists " + std::to_string(listed) +
                                " grid points: a CTETRA has 4, or 10 with its midside nodes");
  if (tet_nodes_each_ != 0 && tet_nodes_each_ != listed) throw InputError(where, mixed_tet_kinds(listed));
  tet_nodes_each_ = listed;
  for (std::size_t k = 0; k < static_cast<std::size_t>(listed); ++k)
    tet_grids_.push_back(id_field(card.field(2 + k), "a grid point id", where));
  mesh_.extras.tet_element_tags.push_back(id);
  mesh_.extras.tet_tags.push_back(pid_field(card.field(1), where));
  tet_marks_.push_back(card.mark);
  element_ids_.push_back(id);
  element_marks_.push_back(card.mark);
}

void DeckReader::element(const EntryType& type, const Card& card) {
  const std::string where = cards_.where(card.mark);
  const long long id = id_field(card.field(0), "an element id", where);
  element_ids_.push_back(id);
  element_marks_.push_back(card.mark);
  // A shape other formats have: its first shape_grids fields given, no more.
  bool shaped = type.kind != nullptr;
  for (int k = 0; shaped && k < type.count; ++k)
    shaped = card.field(static_cast<std::size_t>(type.first + k)).empty() == (k >= type.shape_grids);
  if (!shaped) {
    add_once(uncarried_, type.name);
    for (const auto& [first, last] : grid_ranges(type, card, where))
      pin_refs_.push_back(PinRef{first, last, card.mark});
    return;
  }
  auto it = std::find_if(others_.begin(), others_.end(), [&](const Others& o) { return o.kind == type.kind; });
  if (it == others_.end())
    it = others_.insert(others_.end(), Others{type.kind, type.shape_grids, type.has_pid, {}, {}, {}, {}});
  it->tagged = it->tagged && type.has_pid;
  it->ids.push_back(id);
  for (int k = 0; k < type.shape_grids; ++k)
    it->grids.push_back(id_field(card.field(static_cast<std::size_t>(type.first + k)), "a grid point id", where));
  it->pids.push_back(type.has_pid ? pid_field(card.field(1), where) : 0);
  it->marks.push_back(card.mark);
}

void DeckReader::pinned_comment(const std::string& line) {
  std::string head = line.substr(line.find('$') + 1);
  std::transform(head.begin(), head.end(), head.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  const std::size_t at = head.find_first_not_of(" \t");
  if (at == std::string::npos || head.compare(at, kPinnedComment.size(), kPinnedComment) != 0) return;
  std::istringstream ids(head.substr(at + kPinnedComment.size()));
  const std::string where = cards_.where(cards_.text_mark());
  for (std::string token; ids >> token;) {
    const long long id = id_field(token, "a grid point id", where);
    pin_refs_.push_back(PinRef{id, id, cards_.text_mark()});
  }
}

index_t DeckReader::node_of(long long id, const IdIndex& nodes, std::uint32_t mark, long long element) const {
  const long long n = nodes.find(id);
  if (n < 0)
    throw InputError(cards_.where(mark), "element " + std::to_string(element) + " names grid point " +
                                             std::to_string(id) + ", which no GRID defines");
  return static_cast<index_t>(n);
}

void DeckReader::resolve_pins(const IdIndex& nodes) {
  std::vector<std::uint8_t> pinned = std::move(ps_pinned_);
  mark_element_nodes(mesh_.extras.blocks, pinned);
  std::vector<std::size_t> in_range;
  for (const PinRef& ref : pin_refs_) {
    if (ref.first == ref.last) {
      const long long n = nodes.find(ref.first);
      if (n < 0)
        throw InputError(cards_.where(ref.mark), "grid point " + std::to_string(ref.first) + " is not defined");
      pinned[static_cast<std::size_t>(n)] = 1;
      continue;
    }
    in_range.clear();  // THRU: grid points the range holds, those defined
    nodes.append_range(ref.first, ref.last, 1, in_range);
    for (std::size_t n : in_range) pinned[n] = 1;
  }
  if (std::find(pinned.begin(), pinned.end(), 1) != pinned.end()) mesh_.fixed = std::move(pinned);
}

void DeckReader::resolve() {
  FileExtras& e = mesh_.extras;
  const IdIndex nodes(e.node_tags), elements(element_ids_);
  if (const auto twice = nodes.repeated())
    throw InputError(cards_.where(node_marks_[*twice]),
                     "grid point " + std::to_string(e.node_tags[*twice]) + " is defined a second time");
  if (const auto twice = elements.repeated())
    throw InputError(cards_.where(element_marks_[*twice]),
                     "element id " + std::to_string(element_ids_[*twice]) + " is used a second time");
  const auto each = static_cast<std::size_t>(tet_nodes_each_);
  index_t tet[10];
  for (std::size_t t = 0; t < tet_marks_.size(); ++t) {
    for (std::size_t k = 0; k < each; ++k)
      tet[k] = node_of(tet_grids_[each * t + k], nodes, tet_marks_[t], e.tet_element_tags[t]);
    append_file_tet(mesh_, tet, each == 10, kMidsidePlaces);
  }
  for (const Others& o : others_) {
    PassThroughBlock& block = e.blocks.emplace_back();
    block.kind = o.kind;
    block.nodes_per_element = o.nodes;
    block.element_tags = o.ids;
    if (o.tagged) block.tags = o.pids;
    const auto n = static_cast<std::size_t>(o.nodes);
    for (std::size_t i = 0; i < o.ids.size(); ++i)
      for (std::size_t k = 0; k < n; ++k)
        block.connectivity.push_back(node_of(o.grids[i * n + k], nodes, o.marks[i], o.ids[i]));
  }
  resolve_pins(nodes);
}

TetMesh DeckReader::read() {
  for (BulkCards::Kind kind; (kind = cards_.next()) != BulkCards::Kind::End;) {
    if (kind == BulkCards::Kind::Text) {
      if (cards_.bulk_comment()) pinned_comment(cards_.text());
      keep(cards_.text(), false);
      continue;
    }
    const Card& card = cards_.card();
    if (card.name == "GRID") {
      grid(card);
      keep(card.text, true);
      continue;
    }
    keep(card.text, false);
    if (card.name == "CTETRA") {
      tet(card);
      continue;
    }
    const EntryType* type = entry_type(card.name);
    if (type != nullptr && type->element) {
      element(*type, card);
      continue;
    }
    add_once(types_, text_excerpt(card.name));
    if (type != nullptr)
      for (const auto& [first, last] : grid_ranges(*type, card, cards_.where(card.mark)))
        pin_refs_.push_back(PinRef{first, last, card.mark});
  }
  keep("", !kept_grids_);  // the last piece
  if (mesh_.num_nodes() == 0) throw InputError(source_, "no GRID entries: not a Nastran mesh");
  if (tet_marks_.empty()) throw InputError(source_, "no CTETRA elements: a volume mesh of tets is needed");
  resolve();
  FileExtras& e = mesh_.extras;
  stamp_kept_deck(mesh_, "nastran");
  if (!types_.empty()) e.raw_sections.emplace_back("nastran:types", joined(types_));
  if (!uncarried_.empty()) e.raw_sections.emplace_back("nastran:uncarried", joined(uncarried_));
  if (!cards_.included().empty()) e.raw_sections.emplace_back("nastran:includes", joined(cards_.included()));
  validate_mesh(mesh_, source_);
  return std::move(mesh_);
}

}  // namespace
}  // namespace nastran

TetMesh read_nastran(std::istream& in, const std::string& source) {
  nastran::BulkCards cards(in, source);
  return nastran::DeckReader(cards, source).read();
}

TetMesh read_nastran_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return read_nastran(in, path);
}

}  // namespace tetsmooth
