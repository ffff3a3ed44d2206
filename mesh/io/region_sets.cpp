#include "mesh/io/region_sets.hpp"

#include <algorithm>
#include <sstream>
#include <unordered_map>

namespace tetsmooth {

void RegionNames::add(int dimension, int tag, const std::string& name) {
  // MSH output gives negative tags new positive ones (negative_tag_renumbering).
  // A deck may have a section per grain: tens of thousands of names.
  if (tag < 0 || !named_.insert({dimension, tag}).second) return;
  entries_.push_back(Entry{dimension, tag, name});
}

void RegionNames::add(int dimension, const std::vector<int>& tags, const std::vector<std::uint32_t>& elsets,
                      const std::vector<std::string>& names) {
  std::vector<std::uint8_t> named(names.size() + 1, 0);
  for (std::size_t e = 0; e < tags.size() && e < elsets.size(); ++e)
    if (elsets[e] != 0 && !named[elsets[e]]) {
      named[elsets[e]] = 1;
      add(dimension, tags[e], names[elsets[e] - 1]);
    }
}

std::string RegionNames::msh_body() const {
  std::string body = std::to_string(entries_.size()) + "\n";
  for (const Entry& e : entries_) {
    // A name is one quoted field of one line.
    std::string name = e.name;
    std::replace(name.begin(), name.end(), '"', '\'');
    std::replace_if(
        name.begin(), name.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; }, ' ');
    body += std::to_string(e.dimension) + " " + std::to_string(e.tag) + " \"" + name + "\"\n";
  }
  return body;
}

void RegionSplitter::split(const std::vector<std::size_t>& members) {
  // The members of each region leave it for a new one; the rest stay.
  std::unordered_map<int, int> moved_to;
  ++round_;
  for (std::size_t e : members) {
    if (round_of_[e] == round_) continue;
    round_of_[e] = round_;
    const auto [it, added] = moved_to.try_emplace(regions_[e], next_);
    if (added) ++next_;
    regions_[e] = it->second;
  }
}

std::vector<int> RegionSplitter::tags() const {
  std::unordered_map<int, int> tag_of;
  std::vector<int> tags;
  tags.reserve(regions_.size());
  for (int r : regions_) tags.push_back(tag_of.try_emplace(r, static_cast<int>(tag_of.size()) + 1).first->second);
  return tags;
}

std::map<int, std::string> physical_names_of(const std::string& msh_body, int dimension) {
  std::map<int, std::string> names;
  std::istringstream in(msh_body);
  std::string line;
  std::getline(in, line);  // the count
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    int dim = 0, tag = 0;
    if (!(fields >> dim >> tag) || dim != dimension) continue;
    const std::size_t open = line.find('"'), close = line.rfind('"');
    if (open != std::string::npos && close > open) names.emplace(tag, line.substr(open + 1, close - open - 1));
  }
  return names;
}

}  // namespace tetsmooth
