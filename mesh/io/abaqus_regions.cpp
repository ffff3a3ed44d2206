#include "mesh/io/abaqus_regions.hpp"

#include <algorithm>
#include <cctype>
#include <unordered_map>
#include <unordered_set>
#include <string_view>
#include <utility>

#include "mesh/io/text_lines.hpp"

namespace tetsmooth::abaqus {
namespace {

// The whole number a set name ends with, if it has one that fits an int;
// "_M" before it makes it negative.
bool trailing_number(const std::string& name, int& value) {
  std::size_t start = name.size();
  while (start > 0 && std::isdigit(static_cast<unsigned char>(name[start - 1]))) --start;
  long long v = 0;
  if (start == name.size() || name.size() - start > 9 || !parse_integer(std::string_view(name).substr(start), v))
    return false;
  const bool negative = start >= 2 && name.compare(start - 2, 2, "_M") == 0;
  value = static_cast<int>(negative ? -v : v);
  return true;
}

std::vector<int> numbers_of(const std::vector<std::string>& names) {
  std::vector<int> numbers;
  std::unordered_set<int> taken;
  for (const std::string& name : names) {
    int n = 0;
    // 0 is the tag of elements without a set.
    if (!trailing_number(name, n) || n == 0 || !taken.insert(n).second) {
      numbers.clear();
      for (std::size_t i = 0; i < names.size(); ++i) numbers.push_back(static_cast<int>(i) + 1);
      return numbers;
    }
    numbers.push_back(n);
  }
  return numbers;
}

}  // namespace

std::vector<int> tags_from_element_sets(const std::vector<std::uint32_t>& elsets, const std::vector<std::string>& names) {
  std::vector<std::uint32_t> order;  // name indices in the order met
  std::vector<std::uint8_t> met_already(names.size() + 1, 0);
  for (std::uint32_t e : elsets)
    if (e != 0 && !met_already[e]) {
      met_already[e] = 1;
      order.push_back(e);
    }
  if (order.empty()) return {};
  std::vector<std::string> met;
  for (std::uint32_t e : order) met.push_back(names[e - 1]);
  const std::vector<int> numbers = numbers_of(met);
  std::vector<int> number_of_name(names.size() + 1, 0);
  for (std::size_t i = 0; i < order.size(); ++i) number_of_name[order[i]] = numbers[i];
  std::vector<int> tags;
  tags.reserve(elsets.size());
  for (std::uint32_t e : elsets) tags.push_back(number_of_name[e]);
  return tags;
}

}  // namespace tetsmooth::abaqus
