#include "mesh/io/abaqus_sets.hpp"

#include <algorithm>
#include <string>

#include "mesh/errors.hpp"
#include "mesh/io/abaqus_scopes.hpp"

namespace tetsmooth::abaqus {

void DeckSets::collect(const std::map<std::string, Set>& sets, const std::string& name, const std::string& where,
                       const IdIndex& ids, const char* kind, std::vector<std::size_t>& items,
                       std::vector<std::string>& path, std::vector<std::string>& done,
                       std::vector<const SetPart*>& parts_with_elsets) const {
  if (std::find(done.begin(), done.end(), name) != done.end()) return;
  if (std::find(path.begin(), path.end(), name) != path.end())
    throw InputError(where, std::string(kind) + " set " + name + " contains itself, through other sets");
  const auto it = sets.find(name);
  if (it == sets.end()) {
    const auto& others = &sets == &nsets_ ? elsets_ : nsets_;
    throw InputError(where, "no " + std::string(kind) + " set " + name + " is defined" +
                                (others.count(name) != 0 ? " (" + name + " is a set of " +
                                                               (&sets == &nsets_ ? "elements)" : "nodes)")
                                                         : ""));
  }
  path.push_back(name);
  for (const auto& [first, count] : it->second.runs)
    for (std::size_t i = first; i < first + count; ++i) items.push_back(i);
  for (const SetPart& part : it->second.parts) {
    for (long long id : part.ids) {
      const long long item = ids.find(id);
      if (item < 0)
        throw InputError(part.where, std::string(kind) + " set " + name + " lists " + kind + " " +
                                         std::to_string(number_of_key(id, parts_)) +
                                         ", which the deck does not define");
      items.push_back(static_cast<std::size_t>(item));
    }
    for (const auto& [first, last, step] : part.ranges) ids.append_range(first, last, step, items);
    for (const std::string& other : part.names)
      collect(sets, other, part.where, ids, kind, items, path, done, parts_with_elsets);
    if (!part.elsets.empty()) parts_with_elsets.push_back(&part);
  }
  path.pop_back();
  done.push_back(name);
}

void DeckSets::drop(std::map<std::string, Set>& sets, std::size_t first, std::size_t count) {
  // A run lies in one part, so it is either gone or after the part.
  for (auto& [name, set] : sets) {
    auto& runs = set.runs;
    runs.erase(std::remove_if(runs.begin(), runs.end(),
                              [&](const auto& run) { return run.first >= first && run.first < first + count; }),
               runs.end());
    for (auto& run : runs)
      if (run.first >= first + count) run.first -= count;
  }
}

std::vector<std::size_t> DeckSets::elements(const std::string& name, const std::string& where,
                                            const IdIndex& element_ids) const {
  std::vector<std::size_t> items;
  std::vector<std::string> path, done;
  std::vector<const SetPart*> unused;  // element sets name no sets of nodes
  collect(elsets_, name, where, element_ids, "element", items, path, done, unused);
  return items;
}

void DeckSets::mark_nodes(const std::string& name, const std::string& where, const IdIndex& node_ids,
                          const IdIndex& element_ids, const MarkElementNodes& mark_element_nodes,
                          std::vector<std::uint8_t>& flags) const {
  std::vector<std::size_t> items;
  std::vector<std::string> path, done;
  std::vector<const SetPart*> with_elsets;
  collect(nsets_, name, where, node_ids, "node", items, path, done, with_elsets);
  for (std::size_t n : items) flags[n] = 1;
  for (const SetPart* part : with_elsets)
    for (const std::string& elset : part->elsets)
      for (std::size_t e : elements(elset, part->where, element_ids)) mark_element_nodes(e, flags);
}

}  // namespace tetsmooth::abaqus
