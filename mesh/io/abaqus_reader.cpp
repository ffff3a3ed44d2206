// Abaqus/CalculiX .inp reading (abaqus_io.hpp). Lines are taken one at a
// time (abaqus_deck_lines); node ids, element ids and set names are
// resolved once every line is read, as Abaqus resolves them.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "mesh/errors.hpp"
#include "mesh/second_order.hpp"
#include "mesh/io/abaqus_deck_lines.hpp"
#include "mesh/io/abaqus_element_types.hpp"
#include "mesh/io/abaqus_io.hpp"
#include "mesh/io/abaqus_regions.hpp"
#include "mesh/io/abaqus_sets.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {
namespace {

using abaqus::DeckLines;

constexpr const char* kParts =
    "decks of parts and assemblies are not read (their node and element numbers belong to a part, placed by "
    "*INSTANCE): write the input file without them (Abaqus/CAE: Model > Edit Attributes > Do not use parts and "
    "assemblies in input files)";
constexpr const char* kNodeGeneration = "node generation is not read: give each node its own *NODE line";
constexpr const char* kElementGeneration = "element generation is not read: give each element its own *ELEMENT line";

struct Refused {
  const char* keyword;
  const char* why;
};
constexpr Refused kRefused[] = {
    {"PART", kParts},
    {"ASSEMBLY", kParts},
    {"INSTANCE", kParts},
    {"NGEN", kNodeGeneration},
    {"NFILL", kNodeGeneration},
    {"NCOPY", kNodeGeneration},
    {"NMAP", "mapped node coordinates are not read: give the nodes in the global coordinate system"},
    {"SYSTEM", "nodes in a local coordinate system are not read: give the nodes in the global coordinate system"},
    {"ELGEN", kElementGeneration},
    {"ELCOPY", kElementGeneration},
};

// Keywords whose data lines name nodes that loads or constraints act on,
// which keep their places: by number or node set, in the first field of
// each line (concentrated loads, fluxes and flows, boundary conditions) or
// in every field but the first (*MPC: its type, then its nodes), or in each
// term's first field (*EQUATION: lines of node, degree of freedom,
// coefficient, after a line with the number of terms).
enum class Names { First, AfterFirst, EveryThird };
struct PinKeyword {
  const char* keyword;
  Names names;
};
constexpr PinKeyword kPinKeywords[] = {
    {"BOUNDARY", Names::First}, {"CLOAD", Names::First},        {"CFLUX", Names::First},
    {"CFLOW", Names::First},    {"MPC", Names::AfterFirst}, {"EQUATION", Names::EveryThird},
};

// More element sets than this are not used to tell regions apart in a deck
// without sections or ELSET= on its *ELEMENT lines (each set takes a pass
// over the elements).
constexpr std::size_t kMaxRegionSets = 64;

// The set of the node pins that the writer leaves (abaqus_io.hpp).
constexpr const char* kPinnedSet = "TETSMOOTH_PINNED";

bool positive_integer(std::string_view field, long long& value) { return parse_integer(field, value) && value > 0; }

// Fortran's D exponent (1.5D+03) is read as E, as Abaqus reads it.
bool finite_real(std::string_view field, double& value) {
  if (!parse_real(field, value)) {
    std::string e(field);
    std::replace_if(e.begin(), e.end(), [](char c) { return c == 'd' || c == 'D'; }, 'E');
    if (!parse_real(e, value)) return false;
  }
  return std::isfinite(value);
}

class AbaqusReader {
 public:
  explicit AbaqusReader(DeckLines& lines) : lines_(lines) {}
  TetMesh read(const std::string& source);

 private:
  enum class Block { None, Other, Node, Element, Set, Pins };
  // Elements of one kind other than tets, in read order.
  struct Others {
    abaqus::ElementType type;
    std::vector<long long> ids, nodes;  // nodes in PassThroughBlock order, by file id
    std::vector<std::uint32_t> elsets;  // see abaqus::tags_from_element_sets
  };
  // A node or node set that a load or constraint names, and its line.
  struct PinRef {
    std::string name;
    std::uint32_t mark;
  };

  void keyword();
  void data();
  // Ends a run of node lines in the kept deck.
  void flush_nodes();
  void append_text(const std::string& line);
  void finish_block();
  void start_element_block(const abaqus::Keyword& kw);
  void start_set(const abaqus::Keyword& kw);
  void node_line();
  void element_line();
  void add_element();
  void set_line();
  void pin_line();
  std::uint32_t elset_index(const std::string* name);
  std::string element_type_text() const { return "element " + std::to_string(pending_.front()) + " of type " + type_name_; }

  void resolve();
  void resolve_regions(const abaqus::IdIndex& element_ids);
  void resolve_pins(const abaqus::IdIndex& node_ids, const abaqus::IdIndex& element_ids);
  std::vector<std::uint8_t> elements_of(const std::string& elset, const std::string& where,
                                        const abaqus::IdIndex& element_ids) const;

  DeckLines& lines_;
  TetMesh mesh_;
  abaqus::DeckSets sets_;
  Block block_ = Block::None;
  Names pin_names_ = Names::First;

  std::string text_;          // the deck since the last run of node lines
  std::size_t node_run_ = 0;  // node lines since the last text
  std::string node_set_;      // NSET= of the current *NODE
  std::size_t block_first_ = 0;
  std::vector<std::uint32_t> node_marks_;  // per node, its line (DeckLines::mark)

  abaqus::ElementType type_;
  std::string type_name_;
  std::uint32_t elset_ = 0;
  std::string elset_name_;
  std::vector<long long> pending_;  // an element's id and nodes so far
  std::uint32_t pending_mark_ = 0;

  std::vector<long long> element_ids_;       // every element, in read order
  std::vector<std::uint32_t> element_marks_;  // per element, its first line
  std::vector<std::int64_t> element_at_;     // per element: tet index, or -1 - its place in others_at_
  std::vector<std::pair<std::size_t, std::size_t>> others_at_;  // (block, element) of each other element
  std::vector<long long> tet_ids_, tet_nodes_;
  int tet_nodes_each_ = 0;
  std::vector<std::uint32_t> tet_elsets_;
  std::vector<Others> others_;
  std::vector<std::string> elset_names_;  // ELSET= names of *ELEMENT lines (set_name)
  std::vector<std::string> elset_order_;  // every element set, in the order defined

  abaqus::SetPart part_;
  std::string set_name_;
  bool set_of_nodes_ = false, generate_ = false;

  std::vector<std::pair<std::string, std::string>> sections_;  // *SOLID SECTION's ELSET, and where
  std::vector<PinRef> pin_refs_;
  std::vector<std::string> other_keywords_;  // as written, each once
};

void AbaqusReader::flush_nodes() {
  if (node_run_ == 0) return;
  mesh_.extras.raw_sections.emplace_back("abaqus:text", std::move(text_));
  mesh_.extras.raw_sections.emplace_back("abaqus:nodes", std::to_string(node_run_));
  text_.clear();
  node_run_ = 0;
}

void AbaqusReader::append_text(const std::string& line) {
  flush_nodes();
  text_ += line;
  text_ += '\n';
}

std::uint32_t AbaqusReader::elset_index(const std::string* name) {
  if (name == nullptr) return 0;
  elset_name_ = abaqus::set_name(*name);
  if (std::find(elset_order_.begin(), elset_order_.end(), elset_name_) == elset_order_.end())
    elset_order_.push_back(elset_name_);
  const auto it = std::find(elset_names_.begin(), elset_names_.end(), elset_name_);
  if (it != elset_names_.end()) return static_cast<std::uint32_t>(it - elset_names_.begin()) + 1;
  elset_names_.push_back(elset_name_);
  return static_cast<std::uint32_t>(elset_names_.size());
}

void AbaqusReader::finish_block() {
  switch (block_) {
    case Block::Node:
      if (!node_set_.empty()) sets_.add_node_run(node_set_, block_first_, mesh_.num_nodes() - block_first_);
      break;
    case Block::Element:
      if (!pending_.empty())
        throw InputError(lines_.where_of(pending_mark_), element_type_text() + " lists " +
                                                             std::to_string(pending_.size() - 1) + " of its " +
                                                             std::to_string(type_.nodes) + " nodes");
      if (elset_ != 0) sets_.add_element_run(elset_name_, block_first_, element_ids_.size() - block_first_);
      break;
    case Block::Set:
      if (set_of_nodes_)
        sets_.add_nset(set_name_, std::move(part_));
      else
        sets_.add_elset(set_name_, std::move(part_));
      part_ = {};
      break;
    default:
      break;
  }
  block_ = Block::Other;
}

void AbaqusReader::start_element_block(const abaqus::Keyword& kw) {
  const std::string* type = kw.param("TYPE");
  if (type == nullptr || type->empty()) lines_.fail("*ELEMENT without TYPE=");
  if (kw.param("INPUT") != nullptr) lines_.fail("element lines from another file (INPUT=) are not read: use *INCLUDE");
  const auto known = abaqus::element_type(*type);
  if (!known) lines_.fail(abaqus::unsupported_element_type(text_excerpt(*type)));
  type_ = *known;
  type_name_ = text_excerpt(*type);
  elset_ = elset_index(kw.param("ELSET"));
  block_first_ = element_ids_.size();
  block_ = Block::Element;
}

void AbaqusReader::start_set(const abaqus::Keyword& kw) {
  set_of_nodes_ = kw.name == "NSET";
  const char* key = set_of_nodes_ ? "NSET" : "ELSET";
  const std::string* name = kw.param(key);
  if (name == nullptr || name->empty()) lines_.fail("*" + std::string(key) + " without " + key + "=");
  set_name_ = abaqus::set_name(*name);
  if (!set_of_nodes_ && std::find(elset_order_.begin(), elset_order_.end(), set_name_) == elset_order_.end())
    elset_order_.push_back(set_name_);
  generate_ = kw.param("GENERATE") != nullptr;
  part_.where = lines_.where();
  if (set_of_nodes_)
    if (const std::string* elset = kw.param("ELSET")) part_.elsets.push_back(abaqus::set_name(*elset));
  block_ = Block::Set;
}

void AbaqusReader::keyword() {
  finish_block();
  const abaqus::Keyword& kw = lines_.keyword();
  for (const Refused& r : kRefused)
    if (kw.name == r.keyword) lines_.fail("*" + kw.name + ": " + r.why);
  if (kw.name == "NODE") {
    if (const std::string* system = kw.param("SYSTEM"); system != nullptr && abaqus::normalized(*system) != "R")
      lines_.fail("*NODE, SYSTEM=" + text_excerpt(*system) +
                  ": nodes in cylindrical or spherical coordinates are not read: give them in rectangular ones");
    if (kw.param("INPUT") != nullptr) lines_.fail("node lines from another file (INPUT=) are not read: use *INCLUDE");
    const std::string* nset = kw.param("NSET");
    node_set_ = nset == nullptr ? "" : abaqus::set_name(*nset);
    block_first_ = mesh_.num_nodes();
    block_ = Block::Node;
  } else if (kw.name == "ELEMENT") {
    start_element_block(kw);
  } else if (kw.name == "NSET" || kw.name == "ELSET") {
    start_set(kw);
  } else if (kw.name == "SOLIDSECTION") {
    const std::string* elset = kw.param("ELSET");
    if (elset == nullptr || elset->empty()) lines_.fail("*SOLID SECTION without ELSET=");
    sections_.emplace_back(abaqus::set_name(*elset), lines_.where());
  }
  for (const PinKeyword& p : kPinKeywords)
    if (kw.name == p.keyword) {
      block_ = Block::Pins;
      pin_names_ = p.names;
    }
  if (kw.name != "HEADING" && kw.name != "NODE" && kw.name != "ELEMENT") {
    // The keyword as written, up to its first parameter.
    const std::string& text = lines_.text();
    std::string written = text.substr(0, std::min(text.find(','), text.find('\n')));
    while (!written.empty() && std::isspace(static_cast<unsigned char>(written.back()))) written.pop_back();
    written = text_excerpt(written);
    if (std::find(other_keywords_.begin(), other_keywords_.end(), written) == other_keywords_.end())
      other_keywords_.push_back(written);
  }
  append_text(lines_.text());
}

void AbaqusReader::node_line() {
  const std::vector<std::string_view> fields = abaqus::split_fields(lines_.text());
  long long id = 0;
  if (!positive_integer(fields[0], id)) lines_.fail("expected a positive node number, found " + quoted_token(fields[0]));
  if (fields.size() > 4)
    lines_.fail("node " + std::to_string(id) + " has " + std::to_string(fields.size()) +
                " fields: a node line is 'number, x, y, z' (directions after the coordinates are not read)");
  mesh_.extras.node_tags.push_back(id);
  node_marks_.push_back(lines_.mark());
  for (std::size_t c = 1; c <= 3; ++c) {
    double v = 0;  // an omitted coordinate is 0
    if (c < fields.size() && !fields[c].empty() && !finite_real(fields[c], v))
      lines_.fail("node " + std::to_string(id) + ": expected a finite coordinate, found " + quoted_token(fields[c]));
    mesh_.xyz.push_back(v);
  }
  ++node_run_;
}

void AbaqusReader::add_element() {
  const long long id = pending_.front();
  element_ids_.push_back(id);
  element_marks_.push_back(pending_mark_);
  const bool tet = type_.kind == "tetra" || type_.kind == "tetra10";
  if (tet) {
    if (tet_nodes_each_ != 0 && tet_nodes_each_ != type_.nodes)
      throw InputError(lines_.where_of(pending_mark_), mixed_tet_kinds(type_.nodes));
    tet_nodes_each_ = type_.nodes;
    element_at_.push_back(static_cast<std::int64_t>(tet_ids_.size()));
    tet_ids_.push_back(id);
    tet_nodes_.insert(tet_nodes_.end(), pending_.begin() + 1, pending_.end());
    tet_elsets_.push_back(elset_);
  } else {
    auto it = std::find_if(others_.begin(), others_.end(), [&](const Others& o) { return o.type.kind == type_.kind; });
    if (it == others_.end()) it = others_.insert(others_.end(), Others{type_, {}, {}, {}});
    element_at_.push_back(-1 - static_cast<std::int64_t>(others_at_.size()));
    others_at_.emplace_back(static_cast<std::size_t>(it - others_.begin()), it->ids.size());
    it->ids.push_back(id);
    for (int k = 0; k < type_.nodes; ++k)
      it->nodes.push_back(pending_[1 + static_cast<std::size_t>(abaqus::file_place(type_.kind, k))]);
    it->elsets.push_back(elset_);
  }
  pending_.clear();
}

void AbaqusReader::element_line() {
  const std::string& line = lines_.text();
  const std::vector<std::string_view> fields = abaqus::split_fields(line);
  if (pending_.empty()) pending_mark_ = lines_.mark();
  for (std::string_view field : fields) {
    long long v = 0;
    if (!positive_integer(field, v))
      lines_.fail(std::string(pending_.empty() ? "expected a positive element number" : "expected a positive node number") +
                  ", found " + (field.empty() ? std::string("an empty field") : quoted_token(field)));
    pending_.push_back(v);
  }
  const std::size_t needed = 1 + static_cast<std::size_t>(type_.nodes);
  if (pending_.size() > needed)
    lines_.fail(element_type_text() + " lists " + std::to_string(pending_.size() - 1) + " nodes, not " +
                std::to_string(type_.nodes));
  if (pending_.size() == needed) return add_element();
  if (!abaqus::ends_with_comma(line))
    lines_.fail(element_type_text() + " lists " + std::to_string(pending_.size() - 1) + " of its " +
                std::to_string(type_.nodes) + " nodes (a line that goes on ends with a comma)");
}

void AbaqusReader::set_line() {
  const std::vector<std::string_view> fields = abaqus::split_fields(lines_.text());
  if (generate_) {
    std::array<long long, 3> range{0, 0, 1};
    if (fields.size() < 2 || fields.size() > 3)
      lines_.fail("a GENERATE line is 'first, last' or 'first, last, step'");
    for (std::size_t i = 0; i < fields.size(); ++i)
      if (!positive_integer(fields[i], range[i]))
        lines_.fail("expected a positive number in a GENERATE line, found " + quoted_token(fields[i]));
    if (range[1] < range[0]) lines_.fail("a GENERATE range that ends before it starts");
    part_.ranges.push_back(range);
    return;
  }
  for (std::string_view field : fields) {
    if (field.empty()) continue;
    long long id = 0;
    if (parse_integer(field, id)) {
      if (id <= 0) lines_.fail("expected a positive number or a set name, found " + quoted_token(field));
      part_.ids.push_back(id);
    } else {
      part_.names.push_back(abaqus::set_name(field));
    }
  }
}

void AbaqusReader::pin_line() {
  const std::vector<std::string_view> fields = abaqus::split_fields(lines_.text());
  const auto add = [&](std::string_view field) {
    long long zero = 0;  // *MPC's 0 stands for no node
    if (!field.empty() && !(parse_integer(field, zero) && zero == 0))
      pin_refs_.push_back(PinRef{std::string(field), lines_.mark()});
  };
  switch (pin_names_) {
    case Names::First:
      return add(fields.front());
    case Names::AfterFirst:
      for (std::size_t i = 1; i < fields.size(); ++i) add(fields[i]);
      return;
    case Names::EveryThird:
      // A line of one field is the number of terms of the next equation.
      if (fields.size() > 1)
        for (std::size_t i = 0; i < fields.size(); i += 3) add(fields[i]);
      return;
  }
}

void AbaqusReader::data() {
  switch (block_) {
    case Block::None:
      lines_.fail("a data line before the first keyword");
    case Block::Node:
      return node_line();  // not kept as text: the writer writes the nodes anew
    case Block::Element:
      element_line();
      break;
    case Block::Set:
      set_line();
      break;
    case Block::Pins:
      pin_line();
      break;
    case Block::Other:
      break;
  }
  append_text(lines_.text());
}

std::vector<std::uint8_t> AbaqusReader::elements_of(const std::string& elset, const std::string& where,
                                                    const abaqus::IdIndex& element_ids) const {
  std::vector<std::uint8_t> in(element_ids_.size(), 0);
  try {
    sets_.mark_elements(elset, where, element_ids, in);
  } catch (const std::invalid_argument& err) {
    throw InputError("", err.what());
  }
  return in;
}

void AbaqusReader::resolve_regions(const abaqus::IdIndex& element_ids) {
  FileExtras& e = mesh_.extras;
  const auto tet_flags = [&](const std::vector<std::uint8_t>& in) {
    std::vector<std::uint8_t> of_tets(tet_ids_.size(), 0);
    for (std::size_t g = 0; g < in.size(); ++g)
      if (element_at_[g] >= 0) of_tets[static_cast<std::size_t>(element_at_[g])] = in[g];
    return of_tets;
  };
  if (!sections_.empty()) {
    e.tet_tags.assign(tet_ids_.size(), 0);
    for (std::size_t s = 0; s < sections_.size(); ++s) {
      const std::vector<std::uint8_t> in = tet_flags(elements_of(sections_[s].first, sections_[s].second, element_ids));
      for (std::size_t t = 0; t < in.size(); ++t)
        if (in[t] && e.tet_tags[t] == 0) e.tet_tags[t] = static_cast<int>(s) + 1;
    }
    return;
  }
  e.tet_tags = abaqus::tags_from_element_sets(tet_elsets_, elset_names_);
  if (!e.tet_tags.empty() || elset_order_.empty()) return;
  if (elset_order_.size() > kMaxRegionSets) {
    e.read_notes.push_back("no regions: the deck has no *SOLID SECTION, no ELSET= on its *ELEMENT lines, and " +
                           std::to_string(elset_order_.size()) + " element sets, more than the " +
                           std::to_string(kMaxRegionSets) +
                           " tetsmooth tells regions apart by; nodes between materials may move");
    return;
  }
  // Regions are the tets that the same element sets hold (meshio writes
  // Gmsh's physical groups so).
  std::vector<int> regions(tet_ids_.size(), 0);
  for (const std::string& name : elset_order_) abaqus::split_regions(regions, tet_flags(elements_of(name, "", element_ids)));
  for (int& r : regions) ++r;
  e.tet_tags = std::move(regions);
}

void AbaqusReader::resolve_pins(const abaqus::IdIndex& node_ids, const abaqus::IdIndex& element_ids) {
  std::vector<std::uint8_t> pinned(mesh_.num_nodes(), 0);
  mark_element_nodes(mesh_.extras.blocks, pinned);
  const auto mark_element = [&](std::size_t g, std::vector<std::uint8_t>& flags) {
    const std::int64_t at = element_at_[g];
    if (at >= 0) {
      const std::size_t t = static_cast<std::size_t>(at);
      for (int k = 0; k < 4; ++k) flags[static_cast<std::size_t>(mesh_.tets[4 * t + static_cast<std::size_t>(k)])] = 1;
      if (!mesh_.midsides.empty())
        for (int k = 0; k < 6; ++k) flags[static_cast<std::size_t>(mesh_.midsides[6 * t + static_cast<std::size_t>(k)])] = 1;
      return;
    }
    const auto [b, i] = others_at_[static_cast<std::size_t>(-1 - at)];
    const PassThroughBlock& block = mesh_.extras.blocks[b];
    const auto n = static_cast<std::size_t>(block.nodes_per_element);
    for (std::size_t k = 0; k < n; ++k) flags[static_cast<std::size_t>(block.connectivity[i * n + k])] = 1;
  };
  try {
    for (const PinRef& ref : pin_refs_) {
      long long id = 0;
      if (!parse_integer(ref.name, id)) {
        sets_.mark_nodes(abaqus::set_name(ref.name), lines_.where_of(ref.mark), node_ids, element_ids,
                         element_ids_.size(), mark_element, pinned);
        continue;
      }
      const long long node = node_ids.find(id);
      if (node < 0) throw InputError(lines_.where_of(ref.mark), "node " + std::to_string(id) + " is not defined");
      pinned[static_cast<std::size_t>(node)] = 1;
    }
    if (sets_.has_nset(kPinnedSet))
      sets_.mark_nodes(kPinnedSet, "", node_ids, element_ids, element_ids_.size(), mark_element, pinned);
  } catch (const std::invalid_argument& err) {
    throw InputError("", err.what());
  }
  if (std::find(pinned.begin(), pinned.end(), 1) != pinned.end()) mesh_.fixed = std::move(pinned);
}

void AbaqusReader::resolve() {
  FileExtras& e = mesh_.extras;
  const abaqus::IdIndex node_ids(e.node_tags), element_ids(element_ids_);
  if (const auto twice = node_ids.repeated())
    throw InputError(lines_.where_of(node_marks_[*twice]),
                     "node " + std::to_string(e.node_tags[*twice]) + " is defined a second time");
  if (const auto twice = element_ids.repeated())
    throw InputError(lines_.where_of(element_marks_[*twice]),
                     "element " + std::to_string(element_ids_[*twice]) + " is defined a second time");
  for (const Others& o : others_) {
    PassThroughBlock& block = e.blocks.emplace_back();
    block.kind = o.type.kind;
    block.nodes_per_element = o.type.nodes;
    block.element_tags = o.ids;
    block.tags = abaqus::tags_from_element_sets(o.elsets, elset_names_);
  }
  // Elements in read order, so that each block's come in its own order.
  const auto each = static_cast<std::size_t>(tet_nodes_each_);
  index_t tet[10];
  for (std::size_t g = 0; g < element_ids_.size(); ++g) {
    const auto node = [&](long long id) {
      const long long n = node_ids.find(id);
      if (n < 0)
        throw InputError(lines_.where_of(element_marks_[g]), "element " + std::to_string(element_ids_[g]) +
                                                                 " names node " + std::to_string(id) +
                                                                 ", which no *NODE line defines");
      return static_cast<index_t>(n);
    };
    if (element_at_[g] >= 0) {
      const auto t = static_cast<std::size_t>(element_at_[g]);
      for (std::size_t k = 0; k < each; ++k) tet[k] = node(tet_nodes_[each * t + k]);
      append_file_tet(mesh_, tet, each == 10, abaqus::kMidsidePlaces);
      continue;
    }
    const auto [b, i] = others_at_[static_cast<std::size_t>(-1 - element_at_[g])];
    const auto n = static_cast<std::size_t>(others_[b].type.nodes);
    for (std::size_t k = 0; k < n; ++k) e.blocks[b].connectivity.push_back(node(others_[b].nodes[i * n + k]));
  }
  e.tet_element_tags = tet_ids_;
  resolve_regions(element_ids);
  resolve_pins(node_ids, element_ids);
}

TetMesh AbaqusReader::read(const std::string& source) {
  while (lines_.next()) {
    switch (lines_.kind()) {
      case DeckLines::Kind::Keyword:
        keyword();
        break;
      case DeckLines::Kind::Data:
        data();
        break;
      case DeckLines::Kind::Comment:
        append_text(lines_.text());
        break;
    }
  }
  finish_block();
  flush_nodes();
  if (!text_.empty()) mesh_.extras.raw_sections.emplace_back("abaqus:text", std::move(text_));
  if (mesh_.num_nodes() == 0) throw InputError(source, "no *NODE lines: not an Abaqus mesh");
  if (tet_ids_.empty()) throw InputError(source, "no tets (C3D4 or C3D10 elements): a volume mesh is needed");
  resolve();
  FileExtras& e = mesh_.extras;
  e.raw_sections.emplace_back("abaqus:deck", std::to_string(mesh_.num_nodes()) + " " + std::to_string(mesh_.num_tets()));
  const auto joined = [](const std::vector<std::string>& items) {
    std::string list;
    for (const std::string& item : items) list += (list.empty() ? "" : ", ") + item;
    return list;
  };
  if (!other_keywords_.empty()) e.raw_sections.emplace_back("abaqus:keywords", joined(other_keywords_));
  if (!lines_.included().empty()) e.raw_sections.emplace_back("abaqus:includes", joined(lines_.included()));
  validate_mesh(mesh_, source);
  return std::move(mesh_);
}

}  // namespace

TetMesh read_abaqus(std::istream& in, const std::string& source) {
  DeckLines lines(in, source);
  return AbaqusReader(lines).read(source);
}

TetMesh read_abaqus_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return read_abaqus(in, path);
}

}  // namespace tetsmooth
