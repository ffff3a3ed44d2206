// Parts, the assembly and its instances (abaqus_io.hpp): *PART ... *END PART
// holds a part's nodes, elements, sets and sections, numbered and named
// within the part; *ASSEMBLY ... *END ASSEMBLY places parts by *INSTANCE,
// PART= ... *END INSTANCE; outside parts, "Instance.number" and
// "Instance.set" name a part's node and set through its instance (Abaqus
// Analysis User's Guide, "Assembly definition"; Keywords Reference, *PART,
// *ASSEMBLY, *INSTANCE).
#include <algorithm>
#include <cstddef>
#include <sstream>
#include <stdexcept>

#include "mesh/errors.hpp"
#include "mesh/io/abaqus_node_line.hpp"
#include "mesh/io/abaqus_reader.hpp"
#include "mesh/io/number_text.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth::abaqus {
namespace {

constexpr const char* kFlatten =
    " (or write the input file without parts: Abaqus/CAE: Model > Edit Attributes > Do not use parts and assemblies "
    "in input files)";

}  // namespace

bool DeckReader::structure_keyword(const Keyword& kw) {
  const bool structure = kw.name == "PART" || kw.name == "ENDPART" || kw.name == "ASSEMBLY" ||
                         kw.name == "ENDASSEMBLY" || kw.name == "INSTANCE" || kw.name == "ENDINSTANCE";
  if (level_ == Level::Instance && kw.name != "ENDINSTANCE")
    lines_.fail("*" + kw.name + " inside *INSTANCE is not read: an instance of a part takes its data from the part" +
                std::string(kFlatten));
  if (!structure) return false;
  if (kw.name == "PART") {
    if (level_ != Level::Model)
      lines_.fail(std::string("*PART inside ") + (level_ == Level::Part ? "*PART" : "*ASSEMBLY") +
                  " is not read: parts are defined one after another, before the assembly");
    if (mesh_.num_nodes() != 0 && !has_parts())
      lines_.fail("*PART after nodes outside parts: a deck has either parts or nodes of its own" +
                  std::string(kFlatten));
    const std::string* name = kw.param("NAME");
    if (name == nullptr || name->empty()) lines_.fail("*PART without NAME=");
    const std::string key = set_name(*name);
    for (const Part& p : parts_)
      if (p.name == key) lines_.fail("part " + text_excerpt(unquoted(*name)) + " is defined a second time");
    Part& part = parts_.emplace_back();
    part.name = key;
    part.written = unquoted(*name);
    part.where = lines_.where();
    part.node_first = part.node_end = mesh_.num_nodes();
    part.element_first = part.element_end = element_ids_.size();
    level_ = Level::Part;
    scope_ = parts_.size();
  } else if (kw.name == "ENDPART") {
    if (level_ != Level::Part) lines_.fail("*END PART without *PART");
    parts_.back().node_end = mesh_.num_nodes();
    parts_.back().element_end = element_ids_.size();
    level_ = Level::Model;
    scope_ = 0;
  } else if (kw.name == "ASSEMBLY") {
    if (level_ == Level::Part) lines_.fail("*ASSEMBLY inside *PART is not read");
    if (assembly_seen_) lines_.fail("a second *ASSEMBLY (or one inside another) is not read: a model has one");
    if (!has_parts()) lines_.fail("*ASSEMBLY without parts before it: *INSTANCE places parts defined above");
    assembly_seen_ = true;
    assembly_where_ = lines_.where();
    level_ = Level::Assembly;
  } else if (kw.name == "ENDASSEMBLY") {
    if (level_ != Level::Assembly) lines_.fail("*END ASSEMBLY without *ASSEMBLY");
    level_ = Level::Model;
  } else if (kw.name == "INSTANCE") {
    if (level_ != Level::Assembly) lines_.fail("*INSTANCE outside *ASSEMBLY");
    if (kw.param("INSTANCE") != nullptr)
      lines_.fail("*INSTANCE, INSTANCE= (an instance imported from a previous analysis) is not read");
    const std::string* name = kw.param("NAME");
    const std::string* part = kw.param("PART");
    if (name == nullptr || name->empty()) lines_.fail("*INSTANCE without NAME=");
    if (part == nullptr || part->empty())
      lines_.fail("*INSTANCE without PART=: instances that define their own nodes are not read" +
                  std::string(kFlatten));
    const std::string part_key = set_name(*part);
    std::size_t p = 0;
    while (p < parts_.size() && parts_[p].name != part_key) ++p;
    if (p == parts_.size())
      lines_.fail("*INSTANCE of part " + text_excerpt(unquoted(*part)) + ", which no *PART above defines");
    const std::string key = set_name(*name);
    for (const Instance& i : instances_)
      if (i.name == key) lines_.fail("instance " + text_excerpt(unquoted(*name)) + " is defined a second time");
    if (parts_[p].instance != 0)
      lines_.fail("part " + parts_[p].written + " is instanced a second time (first by instance " +
                  instances_[parts_[p].instance - 1].written + ", " + instances_[parts_[p].instance - 1].where +
                  "): its nodes cannot take two places in one smoothed deck; give each instance its own *PART "
                  "(Abaqus/CAE: Part > Copy), or smooth a deck with the part instanced once");
    instances_.push_back(Instance{key, unquoted(*name), lines_.where(), p, Placement()});
    parts_[p].instance = instances_.size();
    instance_lines_.clear();
    instance_mark_ = lines_.mark();
    level_ = Level::Instance;
    block_ = Block::Instance;
  } else {
    if (level_ != Level::Instance) lines_.fail("*END INSTANCE without *INSTANCE");
    level_ = Level::Assembly;
  }
  return true;
}

void DeckReader::finish_instance() {
  std::vector<std::vector<std::string_view>> lines;
  for (const std::vector<std::string>& fields : instance_lines_) lines.emplace_back(fields.begin(), fields.end());
  try {
    instances_.back().placement = Placement::from_lines(lines);
  } catch (const std::invalid_argument& e) {
    throw InputError(lines_.where_of(instance_mark_), "instance " + instances_.back().written + ": " + e.what());
  }
}

void DeckReader::check_mesh_level(const Keyword& kw) const {
  // Nodes of the assembly itself are reference points (Abaqus/CAE writes
  // them so), numbered apart from the parts' and named by number outside
  // parts; no element holds them, so they stay where they are.
  if (level_ == Level::Assembly && kw.name == "ELEMENT")
    lines_.fail("*ELEMENT inside *ASSEMBLY (elements of the assembly itself) is not read" + std::string(kFlatten));
  if (level_ == Level::Model && has_parts())
    lines_.fail("*" + kw.name +
                " outside *PART in a deck with parts is not read: the model's nodes and elements "
                "belong to its parts");
}

void DeckReader::finish_structure() {
  if (level_ == Level::Part) throw InputError(parts_.back().where, "*PART without *END PART");
  if (level_ == Level::Assembly) throw InputError(assembly_where_, "*ASSEMBLY without *END ASSEMBLY");
  if (level_ == Level::Instance) throw InputError(instances_.back().where, "*INSTANCE without *END INSTANCE");
  // A part that no instance places is no body of the assembly (Abaqus
  // builds the model from the instances): its lines stay, as text.
  if (has_parts() && instances_.empty())
    throw InputError(parts_.front().where,
                     "no part has an *INSTANCE, so the model has no body: place the parts in "
                     "the *ASSEMBLY by *INSTANCE, NAME=..., PART=...");
  for (std::size_t p = parts_.size(); p-- > 0;)
    if (parts_[p].instance == 0) drop_part(p);
  if (has_parts()) sets_.number_within_parts();
}

void DeckReader::drop_part(std::size_t p) {
  FileExtras& e = mesh_.extras;
  const Part& part = parts_[p];
  const std::size_t nf = part.node_first, nn = part.node_end - nf;
  // Its node lines become text, as the writer writes every node line.
  for (auto run = node_runs_.begin(); run != node_runs_.end();) {
    auto& [section, first] = *run;
    if (first < nf || first >= nf + nn) {
      if (first >= nf + nn) first -= nn;
      ++run;
      continue;
    }
    auto& [name, body] = e.raw_sections[section];
    std::ostringstream text;
    for (std::size_t i = first, end = first + std::stoull(body); i < end; ++i)
      write_node_line(text, e.node_tags[i], &mesh_.xyz[3 * i]);
    name = "abaqus:text";
    body = text.str();
    run = node_runs_.erase(run);
  }
  const auto erase = [](auto& items, std::size_t first, std::size_t count) {
    items.erase(items.begin() + static_cast<std::ptrdiff_t>(first),
                items.begin() + static_cast<std::ptrdiff_t>(first + count));
  };
  erase(mesh_.xyz, 3 * nf, 3 * nn);
  erase(e.node_tags, nf, nn);
  erase(node_keys_, nf, nn);
  erase(node_marks_, nf, nn);
  sets_.drop_nodes(nf, nn);

  // Its elements: tets and others of each kind come in read order, so the
  // part's are one run of each.
  const std::size_t ef = part.element_first, en = part.element_end - ef;
  std::size_t tf = tet_ids_.size(), tn = 0, of = others_at_.size(), on = 0;
  for (std::size_t g = ef; g < ef + en; ++g) {
    const std::int64_t at = element_at_[g];
    if (at >= 0) {
      tf = std::min(tf, static_cast<std::size_t>(at));
      ++tn;
    } else {
      of = std::min(of, static_cast<std::size_t>(-1 - at));
      ++on;
    }
  }
  if (tn != 0) {
    const auto each = static_cast<std::size_t>(tet_nodes_each_);
    erase(tet_ids_, tf, tn);
    erase(tet_nodes_, each * tf, each * tn);
    erase(tet_elsets_, tf, tn);
  }
  // Per kind, the part's elements: how many, from which.
  std::vector<std::size_t> gone(others_.size(), 0), from(others_.size(), 0);
  for (std::size_t k = of + on; k-- > of;) {
    ++gone[others_at_[k].first];
    from[others_at_[k].first] = others_at_[k].second;
  }
  for (std::size_t b = 0; b < others_.size(); ++b) {
    if (gone[b] == 0) continue;
    Others& o = others_[b];
    const auto n = static_cast<std::size_t>(o.type.nodes);
    erase(o.ids, from[b], gone[b]);
    erase(o.nodes, n * from[b], n * gone[b]);
    erase(o.elsets, from[b], gone[b]);
  }
  erase(others_at_, of, on);
  for (std::size_t k = of; k < others_at_.size(); ++k) others_at_[k].second -= gone[others_at_[k].first];
  // A kind that only the part had is gone.
  for (std::size_t b = others_.size(); b-- > 0;) {
    if (!others_[b].ids.empty()) continue;
    erase(others_, b, 1);
    for (auto& [block, i] : others_at_)
      if (block > b) --block;
  }
  for (std::size_t g = ef + en; g < element_at_.size(); ++g) {
    std::int64_t& at = element_at_[g];
    at = at >= 0 ? at - static_cast<std::int64_t>(tn) : at + static_cast<std::int64_t>(on);
  }
  erase(element_ids_, ef, en);
  erase(element_keys_, ef, en);
  erase(element_marks_, ef, en);
  erase(element_at_, ef, en);
  sets_.drop_elements(ef, en);

  // What the part defines names nothing now; later parts' items move down.
  const std::string prefix = part.name + "/";
  const auto in_part = [&](const std::string& name) { return name.compare(0, prefix.size(), prefix) == 0; };
  sections_.erase(
      std::remove_if(sections_.begin(), sections_.end(), [&](const Section& s) { return in_part(s.elset); }),
      sections_.end());
  for (std::size_t i = elset_order_.size(); i-- > 0;)
    if (in_part(elset_order_[i])) {
      erase(elset_order_, i, 1);
      erase(elset_order_written_, i, 1);
    }
  pin_refs_.erase(std::remove_if(pin_refs_.begin(), pin_refs_.end(), [&](const PinRef& r) { return r.scope == p + 1; }),
                  pin_refs_.end());
  parts_[p].node_end = nf;  // holds nothing now
  parts_[p].element_end = ef;
  for (std::size_t q = p + 1; q < parts_.size(); ++q) {
    parts_[q].node_first -= nn;
    parts_[q].node_end -= nn;
    parts_[q].element_first -= en;
    parts_[q].element_end -= en;
  }
}

long long DeckReader::key(std::size_t scope, long long number) const {
  if (has_parts() && number > kLargestPartNumber)
    lines_.fail("number " + std::to_string(number) + " in a deck with parts: numbers are read up to " +
                std::to_string(kLargestPartNumber));
  return scoped_key(scope, number);
}

std::string DeckReader::set_key(std::size_t scope, const std::string& name) const {
  return scope == 0 ? name : parts_[scope - 1].name + "/" + name;
}

std::string DeckReader::set_written(std::size_t scope, const std::string& written) const {
  return scope == 0 ? written : parts_[scope - 1].written + "." + written;
}

DeckReader::Ref DeckReader::reference(std::string_view field, std::size_t scope, const std::string& where) const {
  long long number = 0;
  // Outside parts, a number is a node of the assembly itself.
  if (parse_integer(field, number)) return Ref{true, scoped_key(scope, number), ""};
  const std::string name = set_name(field);
  if (scope != 0 || !has_parts()) return Ref{false, 0, set_key(scope, name)};
  // Instance names hold no '.', so the first one ends it.
  const std::size_t dot = name.find('.');
  if (dot == std::string::npos) return Ref{false, 0, name};
  const std::string instance = name.substr(0, dot), rest = name.substr(dot + 1);
  for (const Instance& i : instances_) {
    if (i.name != instance) continue;
    const std::size_t part = i.part + 1;
    if (parse_integer(rest, number) && number > 0) {
      if (number > kLargestPartNumber)
        throw InputError(where, "node " + std::to_string(number) + " of instance " + i.written + " is not defined");
      return Ref{true, scoped_key(part, number), ""};
    }
    return Ref{false, 0, set_key(part, rest)};
  }
  return Ref{false, 0, name};
}

}  // namespace tetsmooth::abaqus
