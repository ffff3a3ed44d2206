#include "mesh/io/flac3d_records.hpp"

#include <algorithm>

#include "mesh/io/text_lines.hpp"

namespace tetsmooth::flac3d {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == ','; }

}  // namespace

bool is_comment(std::string_view line) {
  for (char c : line)
    if (c != ' ' && c != '\t') return c == '*';
  return false;
}

bool split_values(std::string_view line, std::vector<std::string_view>& values) {
  values.clear();
  std::size_t i = 0;
  while (true) {
    while (i < line.size() && is_blank(line[i])) ++i;
    if (i == line.size()) return true;
    if (line[i] == '"' || line[i] == '\'') {
      const std::size_t close = line.find(line[i], i + 1);
      if (close == std::string_view::npos) return false;
      values.push_back(line.substr(i + 1, close - i - 1));
      i = close + 1;
      continue;
    }
    const std::size_t start = i;
    while (i < line.size() && !is_blank(line[i])) ++i;
    values.push_back(line.substr(start, i - start));
  }
}

bool is_gridpoint(const std::vector<std::string_view>& values) {
  return !values.empty() && (values[0] == "G" || values[0] == "g");
}

PinComment pin_comment(std::string_view line, std::vector<std::string_view>& ids) {
  if (!is_comment(line)) return PinComment::None;
  std::vector<std::string_view> words;
  const bool split = split_values(line.substr(line.find('*') + 1), words);
  if (words.size() < 2 || upper_case(words[0]) != "TETSMOOTH" || upper_case(words[1]) != "PINNED")
    return PinComment::None;
  ids.assign(words.begin() + 2, words.end());
  long long id = 0;
  const bool all_ids = split && !ids.empty() &&
                       std::all_of(ids.begin(), ids.end(), [&](std::string_view w) { return parse_integer(w, id); });
  return all_ids ? PinComment::Pins : PinComment::Unread;
}

}  // namespace tetsmooth::flac3d
