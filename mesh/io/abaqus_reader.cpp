// Abaqus/CalculiX .inp reading (abaqus_io.hpp), line by line
// (abaqus_deck_lines): nodes, elements, sets, sections and the nodes that
// loads and constraints name, kept by the file's numbers and names for
// abaqus_resolve.cpp. The deck's text is kept as read, but for its node
// lines, which the writer writes anew.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>

#include "mesh/errors.hpp"
#include "mesh/second_order.hpp"
#include "mesh/io/abaqus_io.hpp"
#include "mesh/io/abaqus_reader.hpp"
#include "mesh/io/input_file.hpp"
#include "mesh/io/text_lines.hpp"
#include "mesh/validate.hpp"

namespace tetsmooth {
namespace abaqus {
namespace {

constexpr const char* kNodeGeneration = "node generation is not read: give each node its own *NODE line";
constexpr const char* kElementGeneration = "element generation is not read: give each element its own *ELEMENT line";

struct Refused {
  const char* keyword;
  const char* why;
};
constexpr Refused kRefused[] = {
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
// each line (concentrated loads, fluxes and flows, boundary conditions), in
// every field but the first (*MPC: its type, then its nodes), or in each
// term's first field (*EQUATION: lines of node, degree of freedom,
// coefficient, after a line with the number of terms).
using Names = DeckReader::Names;
struct PinKeyword {
  const char* keyword;
  Names names;
};
constexpr PinKeyword kPinKeywords[] = {
    {"BOUNDARY", Names::First}, {"CLOAD", Names::First},     {"CFLUX", Names::First},
    {"CFLOW", Names::First},    {"MPC", Names::AfterFirst}, {"EQUATION", Names::EveryThird},
};

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

}  // namespace

void DeckReader::flush_nodes() {
  if (node_run_ == 0) return;
  node_runs_.emplace_back(mesh_.extras.raw_sections.size() + 1, mesh_.num_nodes() - node_run_);
  mesh_.extras.raw_sections.emplace_back("abaqus:text", std::move(text_));
  mesh_.extras.raw_sections.emplace_back("abaqus:nodes", std::to_string(node_run_));
  text_.clear();
  node_run_ = 0;
}

void DeckReader::append_text(const std::string& line) {
  flush_nodes();
  text_ += line;
  text_ += '\n';
}

std::string DeckReader::element_text() const {
  return "element " + std::to_string(pending_.front()) + " of type " + type_name_;
}

void DeckReader::note_elset(const std::string& name, const std::string& written) {
  if (!elsets_met_.insert(name).second) return;
  elset_order_.push_back(name);
  elset_order_written_.push_back(unquoted(written));
}

std::uint32_t DeckReader::elset_index(const std::string* name) {
  if (name == nullptr) return 0;
  elset_name_ = set_key(scope_, set_name(*name));
  const std::string written = set_written(scope_, unquoted(*name));
  note_elset(elset_name_, written);
  const auto [it, added] = elset_numbers_.try_emplace(elset_name_, static_cast<std::uint32_t>(elset_names_.size()) + 1);
  if (added) {
    elset_names_.push_back(elset_name_);
    elset_written_.push_back(written);
  }
  return it->second;
}

void DeckReader::finish_block() {
  switch (block_) {
    case Block::Node:
      if (!node_set_.empty()) sets_.add_node_run(node_set_, block_first_, mesh_.num_nodes() - block_first_);
      break;
    case Block::Element:
      if (!pending_.empty())
        throw InputError(lines_.where_of(pending_mark_), element_text() + " lists " +
                                                             std::to_string(pending_.size() - 1) + " of its " +
                                                             std::to_string(type_.nodes) + " nodes");
      if (elset_ != 0) sets_.add_element_run(elset_name_, block_first_, element_ids_.size() - block_first_);
      break;
    case Block::Instance:
      finish_instance();
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

void DeckReader::start_element_block(const Keyword& kw) {
  const std::string* type = kw.param("TYPE");
  if (type == nullptr || type->empty()) lines_.fail("*ELEMENT without TYPE=");
  const auto known = element_type(*type);
  if (!known) lines_.fail(unsupported_element_type(text_excerpt(*type)));
  type_ = *known;
  type_name_ = text_excerpt(*type);
  elset_ = elset_index(kw.param("ELSET"));
  block_first_ = element_ids_.size();
  block_ = Block::Element;
}

void DeckReader::start_set(const Keyword& kw) {
  set_of_nodes_ = kw.name == "NSET";
  const char* key = set_of_nodes_ ? "NSET" : "ELSET";
  const std::string* name = kw.param(key);
  if (name == nullptr || name->empty()) lines_.fail("*" + std::string(key) + " without " + key + "=");
  set_name_ = set_key(scope_, set_name(*name));
  set_scope_ = scope_;
  // In the assembly, INSTANCE= gives the instance whose part's numbers and
  // sets the data lines name.
  if (const std::string* instance = kw.param("INSTANCE"); instance != nullptr) {
    if (level_ != Level::Assembly) lines_.fail("*" + kw.name + ", INSTANCE= outside *ASSEMBLY");
    const std::string wanted = set_name(*instance);
    const auto it =
        std::find_if(instances_.begin(), instances_.end(), [&](const Instance& i) { return i.name == wanted; });
    if (it == instances_.end())
      lines_.fail("*" + kw.name + ", INSTANCE=" + text_excerpt(unquoted(*instance)) +
                  ": no *INSTANCE above has that name");
    set_scope_ = it->part + 1;
  }
  if (!set_of_nodes_) note_elset(set_name_, set_written(scope_, unquoted(*name)));
  generate_ = kw.param("GENERATE") != nullptr;
  part_.where = lines_.where();
  // *NSET, ELSET: the data lines name element sets, whose nodes the set
  // holds (ELSET=name, as some writers put it, names one more).
  const std::string* elset = set_of_nodes_ ? kw.param("ELSET") : nullptr;
  lists_elsets_ = elset != nullptr;
  if (elset != nullptr && !elset->empty()) part_.elsets.push_back(set_in_data(*elset));
  block_ = Block::Set;
}

std::string DeckReader::set_in_data(std::string_view field) const {
  if (set_scope_ != 0) return set_key(set_scope_, set_name(field));
  const Ref ref = reference(field, 0, lines_.where());
  if (ref.is_node) lines_.fail("expected a set name, found " + quoted_token(field));
  return ref.set;
}

void DeckReader::keyword() {
  finish_block();
  const Keyword& kw = lines_.keyword();
  structure_keyword(kw);
  for (const Refused& r : kRefused)
    if (kw.name == r.keyword) lines_.fail("*" + kw.name + ": " + r.why);
  if (kw.name == "NODE" || kw.name == "ELEMENT") check_mesh_level(kw);
  if (kw.name == "NODE") {
    if (const std::string* system = kw.param("SYSTEM"); system != nullptr && normalized(*system) != "R")
      lines_.fail("*NODE, SYSTEM=" + text_excerpt(*system) +
                  ": nodes in cylindrical or spherical coordinates are not read: give them in rectangular ones");
    const std::string* nset = kw.param("NSET");
    node_set_ = nset == nullptr ? "" : set_key(scope_, set_name(*nset));
    block_first_ = mesh_.num_nodes();
    block_ = Block::Node;
  } else if (kw.name == "ELEMENT") {
    start_element_block(kw);
  } else if (kw.name == "NSET" || kw.name == "ELSET") {
    start_set(kw);
  } else if (kw.name == "SOLIDSECTION") {
    const std::string* elset = kw.param("ELSET");
    if (elset == nullptr || elset->empty()) lines_.fail("*SOLID SECTION without ELSET=");
    sections_.push_back(
        Section{set_key(scope_, set_name(*elset)), lines_.where(), set_written(scope_, unquoted(*elset))});
  }
  for (const PinKeyword& p : kPinKeywords)
    if (kw.name == p.keyword) {
      block_ = Block::Pins;
      pin_names_ = p.names;
    }
  // Data that the reader needs must not be missed.
  if (block_ != Block::Other && kw.param("INPUT") != nullptr)
    lines_.fail("*" + kw.name + " lines from another file (INPUT=) are not read: use *INCLUDE");
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

void DeckReader::node_line() {
  const std::vector<std::string_view> fields = split_fields(lines_.text());
  long long id = 0;
  if (!positive_integer(fields[0], id)) lines_.fail("expected a positive node number, found " + quoted_token(fields[0]));
  if (fields.size() > 4)
    lines_.fail("node " + std::to_string(id) + " has " + std::to_string(fields.size()) +
                " fields: a node line is 'number, x, y, z' (directions after the coordinates are not read)");
  mesh_.extras.node_tags.push_back(id);
  node_keys_.push_back(key(scope_, id));
  node_marks_.push_back(lines_.mark());
  for (std::size_t c = 1; c <= 3; ++c) {
    double v = 0;  // an omitted coordinate is 0
    if (c < fields.size() && !fields[c].empty() && !finite_real(fields[c], v))
      lines_.fail("node " + std::to_string(id) + ": expected a finite coordinate, found " + quoted_token(fields[c]));
    mesh_.xyz.push_back(v);
  }
  ++node_run_;
}

void DeckReader::add_element() {
  const long long id = pending_.front();
  element_ids_.push_back(id);
  element_keys_.push_back(key(scope_, id));
  for (std::size_t k = 1; k < pending_.size(); ++k) pending_[k] = key(scope_, pending_[k]);
  element_marks_.push_back(pending_mark_);
  if (type_.kind == "tetra" || type_.kind == "tetra10") {
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
      it->nodes.push_back(pending_[1 + static_cast<std::size_t>(file_place(type_.kind, k))]);
    it->elsets.push_back(elset_);
  }
  pending_.clear();
}

void DeckReader::element_line() {
  const std::string& line = lines_.text();
  const std::vector<std::string_view> fields = split_fields(line);
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
    lines_.fail(element_text() + " lists " + std::to_string(pending_.size() - 1) + " nodes, not " +
                std::to_string(type_.nodes));
  if (pending_.size() == needed) return add_element();
  if (!ends_with_comma(line))
    lines_.fail(element_text() + " lists " + std::to_string(pending_.size() - 1) + " of its " +
                std::to_string(type_.nodes) + " nodes (a line that goes on ends with a comma)");
}

void DeckReader::set_line() {
  const std::vector<std::string_view> fields = split_fields(lines_.text());
  if (generate_) {
    std::array<long long, 3> range{0, 0, 1};
    if (fields.size() < 2 || fields.size() > 3)
      lines_.fail("a GENERATE line is 'first, last' or 'first, last, step'");
    for (std::size_t i = 0; i < fields.size(); ++i)
      if (!positive_integer(fields[i], range[i]))
        lines_.fail("expected a positive number in a GENERATE line, found " + quoted_token(fields[i]));
    if (range[1] < range[0]) lines_.fail("a GENERATE range that ends before it starts");
    range[0] = number_key(range[0]);
    range[1] = number_key(range[1]);
    part_.ranges.push_back(range);
    return;
  }
  for (std::string_view field : fields) {
    if (field.empty()) continue;
    long long id = 0;
    if (lists_elsets_) {
      part_.elsets.push_back(set_in_data(field));
    } else if (!parse_integer(field, id)) {
      // "Instance.number" names an instance's item from the assembly.
      const Ref ref = set_scope_ == 0 ? reference(field, 0, lines_.where()) : Ref{false, 0, ""};
      if (ref.is_node)
        part_.ids.push_back(ref.key);
      else
        part_.names.push_back(set_in_data(field));
    } else if (id <= 0) {
      lines_.fail("expected a positive number or a set name, found " + quoted_token(field));
    } else {
      part_.ids.push_back(number_key(id));
    }
  }
}

long long DeckReader::number_key(long long number) const { return key(set_scope_, number); }

void DeckReader::pin_line() {
  const std::vector<std::string_view> fields = split_fields(lines_.text());
  const auto add = [&](std::string_view field) {
    long long zero = 0;  // *MPC's 0 stands for no node
    if (!field.empty() && !(parse_integer(field, zero) && zero == 0))
      pin_refs_.push_back(PinRef{std::string(field), lines_.mark(), scope_});
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

void DeckReader::data() {
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
    case Block::Instance:
      instance_lines_.emplace_back();
      for (std::string_view field : split_fields(lines_.text())) instance_lines_.back().emplace_back(field);
      break;
    case Block::Other:
      break;
  }
  append_text(lines_.text());
}

TetMesh DeckReader::read(const std::string& source) {
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
  finish_structure();
  if (mesh_.num_nodes() == 0) throw InputError(source, "no *NODE lines: not an Abaqus mesh");
  if (tet_ids_.empty()) throw InputError(source, "no tets (C3D4 or C3D10 elements): a volume mesh is needed");
  resolve();
  keep_deck_notes();
  validate_mesh(mesh_, source);
  return std::move(mesh_);
}

}  // namespace abaqus

TetMesh read_abaqus(std::istream& in, const std::string& source) {
  abaqus::DeckLines lines(in, source);
  return abaqus::DeckReader(lines).read(source);
}

TetMesh read_abaqus_file(const std::string& path) {
  std::ifstream in = open_input(path);
  return read_abaqus(in, path);
}

}  // namespace tetsmooth
