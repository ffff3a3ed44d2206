#pragma once
// The named node and element sets of an Abaqus deck (*NSET, *ELSET, and the
// NSET=/ELSET= of *NODE and *ELEMENT), resolved once every line is read, so
// that a set may be used before the lines that define it (not a public API).
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mesh/io/id_index.hpp"

namespace tetsmooth::abaqus {

// What one *NSET or *ELSET keyword (and its data lines) adds to a set.
struct SetPart {
  std::vector<long long> ids;                    // keys (abaqus_scopes.hpp)
  std::vector<std::string> names;                // other sets of the same kind, as set_name() gives them
  std::vector<std::array<long long, 3>> ranges;  // GENERATE: first, last (keys), step
  std::vector<std::string> elsets;               // *NSET, ELSET=: the nodes of these element sets
  std::string where;                             // "file:line" of the keyword
};

class DeckSets {
 public:
  // Names as set_name() gives them (abaqus_deck_lines.hpp).
  void add_nset(const std::string& name, SetPart part) { nsets_[name].parts.push_back(std::move(part)); }
  void add_elset(const std::string& name, SetPart part) { elsets_[name].parts.push_back(std::move(part)); }
  // Items a *NODE, NSET= or *ELEMENT, ELSET= line adds: `count` items from
  // index `first` in read order (elements counted over every kind).
  void add_node_run(const std::string& name, std::size_t first, std::size_t count) {
    nsets_[name].runs.emplace_back(first, count);
  }
  void add_element_run(const std::string& name, std::size_t first, std::size_t count) {
    elsets_[name].runs.emplace_back(first, count);
  }
  bool has_nset(const std::string& name) const { return nsets_.count(name) != 0; }
  // Forgets `count` nodes (elements) from read index `first` that leave
  // the mesh, and the runs that held them; later indices move down.
  void drop_nodes(std::size_t first, std::size_t count) { drop(nsets_, first, count); }
  void drop_elements(std::size_t first, std::size_t count) { drop(elsets_, first, count); }
  // Messages give the numbers of keys within parts (abaqus_scopes.hpp).
  void number_within_parts() { parts_ = true; }

  // The items of an element set, by read index over every kind of element
  // (an item may come more than once). Throws InputError at `where` (the
  // line that uses the set) for a set that is not defined, at a set's own
  // line for an id that no element has, or for sets that contain each other.
  std::vector<std::size_t> elements(const std::string& name, const std::string& where, const IdIndex& element_ids) const;
  // Marks the nodes of a node set in `flags` (one per node, by read index);
  // `mark_element_nodes` marks an element's nodes, for *NSET, ELSET.
  // Throws as elements() does.
  using MarkElementNodes = std::function<void(std::size_t element, std::vector<std::uint8_t>& node_flags)>;
  void mark_nodes(const std::string& name, const std::string& where, const IdIndex& node_ids,
                  const IdIndex& element_ids, const MarkElementNodes& mark_element_nodes,
                  std::vector<std::uint8_t>& flags) const;

 private:
  struct Set {
    std::vector<SetPart> parts;
    std::vector<std::pair<std::size_t, std::size_t>> runs;
  };
  // Appends the items of set `name` of `sets` (and of the sets it names) to
  // `items`, and gathers the parts that name element sets.
  void collect(const std::map<std::string, Set>& sets, const std::string& name, const std::string& where,
               const IdIndex& ids, const char* kind, std::vector<std::size_t>& items,
               std::vector<std::string>& path, std::vector<std::string>& done,
               std::vector<const SetPart*>& parts_with_elsets) const;

  static void drop(std::map<std::string, Set>& sets, std::size_t first, std::size_t count);

  std::map<std::string, Set> nsets_, elsets_;
  bool parts_ = false;
};

}  // namespace tetsmooth::abaqus
