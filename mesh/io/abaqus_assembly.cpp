// Parts, the assembly and its instances (abaqus_io.hpp): *PART ... *END PART
// holds a part's nodes, elements, sets and sections, numbered and named
// within the part; *ASSEMBLY ... *END ASSEMBLY places parts by *INSTANCE,
// PART= ... *END INSTANCE; outside parts, "Instance.number" and
// "Instance.set" name a part's node and set through its instance (Abaqus
// Analysis User's Guide, "Assembly definition"; Keywords Reference, *PART,
// *ASSEMBLY, *INSTANCE).
#include <stdexcept>

#include "mesh/errors.hpp"
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
  // Abaqus analyses only the parts that an instance places; the lines of
  // another would have to be kept as text, which is not done.
  for (const Part& p : parts_)
    if (p.instance == 0)
      throw InputError(p.where, "part " + p.written +
                                    " has no *INSTANCE: its mesh is not part of the model; instance it in the "
                                    "*ASSEMBLY, or delete the part");
  if (has_parts()) sets_.number_within_parts();
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
