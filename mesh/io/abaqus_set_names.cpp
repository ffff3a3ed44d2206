#include "mesh/io/abaqus_set_names.hpp"

#include <cctype>
#include <set>
#include <unordered_map>

#include "mesh/io/abaqus_regions.hpp"
#include "mesh/io/file_numbers.hpp"
#include "mesh/io/region_sets.hpp"
#include "mesh/io/text_lines.hpp"

namespace tetsmooth::abaqus {
namespace {

// Abaqus takes set names of 1 to 80 characters, the first a letter. Names
// with other characters than letters, digits and '_' would need quotes,
// which not every reader of decks (CalculiX, meshio, converters) honours,
// so those are left to the tag.
bool plain_set_name(const std::string& name) {
  if (name.empty() || name.size() > 80 || !std::isalpha(static_cast<unsigned char>(name[0]))) return false;
  for (char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

}  // namespace

std::string tag_set_name(const std::string& prefix, int tag) {
  return upper_case(prefix) +
         (tag < 0 ? "_M" + std::to_string(-static_cast<long long>(tag)) : "_" + std::to_string(tag));
}

NewSetNames::NewSetNames(const TetMesh& mesh) {
  const FileExtras& e = mesh.extras;
  const std::string* body = raw_section(e, "$PhysicalNames");
  if (body == nullptr) return;
  // The (dimension, tag) pairs the deck writes, and the names made of tags
  // that it may use: a region's name must not be one of another's.
  std::map<std::pair<int, int>, std::set<std::string>> own_tag_names;
  const auto add = [&](const std::string& prefix, int dimension, const std::vector<int>& tags, std::size_t count) {
    if (tags.size() != count) return;  // untagged elements get no ELSET=
    for (int t : tags) own_tag_names[{dimension, t}].insert(tag_set_name(prefix, t));
  };
  add("REGION", 3, e.tet_tags, mesh.num_tets());
  for (const PassThroughBlock& b : e.blocks) add(b.kind, kind_dimension(b.kind), b.tags, elements_in(b));
  std::set<std::string> tag_names;
  for (const auto& [key, names] : own_tag_names) tag_names.insert(names.begin(), names.end());

  std::map<int, std::map<int, std::string>> physical;  // by dimension, then tag
  std::map<std::pair<int, int>, std::string> candidates;
  std::unordered_map<std::string, int> uses;  // by upper-case name: Abaqus ignores case
  for (const auto& [key, own] : own_tag_names) {
    const auto [dimension, tag] = key;
    if (physical.count(dimension) == 0) physical[dimension] = physical_names_of(*body, dimension);
    const auto it = physical[dimension].find(tag);
    if (it == physical[dimension].end()) continue;
    candidates[key] = it->second;
    ++uses[upper_case(it->second)];
  }
  for (const auto& [key, name] : candidates) {
    const std::string upper = upper_case(name);
    const bool taken = uses[upper] > 1 || (tag_names.count(upper) != 0 && own_tag_names[key].count(upper) == 0);
    if (plain_set_name(name) && !taken)
      written_[key] = name;
    else if (!name.empty())
      not_written_.push_back(name);
  }
}

bool NewSetNames::tags_read_back(const TetMesh& mesh) const {
  // The sets in the order the deck writes them (tets, then each block), by
  // first appearance, and the tags the reader gives them back.
  std::vector<std::string> names;
  std::vector<int> tags;
  std::set<std::pair<int, int>> seen;
  const auto add = [&](const std::string& prefix, int dimension, const std::vector<int>& of_elements) {
    for (int tag : of_elements)
      if (seen.insert({dimension, tag}).second) {
        names.push_back(of(prefix, dimension, tag));
        tags.push_back(tag);
      }
  };
  if (mesh.extras.tet_tags.size() == mesh.num_tets()) add("REGION", 3, mesh.extras.tet_tags);
  for (const PassThroughBlock& b : mesh.extras.blocks)
    if (b.tags.size() == elements_in(b)) add(b.kind, kind_dimension(b.kind), b.tags);
  std::vector<std::uint32_t> sets(names.size());
  for (std::size_t i = 0; i < sets.size(); ++i) sets[i] = static_cast<std::uint32_t>(i + 1);
  return tags_from_element_sets(sets, names) == tags || names.empty();
}

std::string NewSetNames::of(const std::string& prefix, int dimension, int tag) const {
  const auto it = written_.find({dimension, tag});
  return it != written_.end() ? it->second : tag_set_name(prefix, tag);
}

}  // namespace tetsmooth::abaqus
