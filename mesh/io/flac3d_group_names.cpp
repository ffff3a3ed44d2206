#include "mesh/io/flac3d_group_names.hpp"

#include "mesh/io/text_lines.hpp"

namespace tetsmooth::flac3d {
namespace {

constexpr std::string_view kJoin = " + ";

// A group or slot as a part of a name: quoted where it could be misread.
std::string part(const std::string& word) {
  const bool plain = !word.empty() && word.find('=') == std::string::npos && word.find(kJoin) == std::string::npos &&
                     word.find_first_of("'\"") == std::string::npos;
  if (plain) return word;
  const char quote = word.find('\'') == std::string::npos ? '\'' : '"';
  return quote + word + quote;
}

// Reads a group or slot from `name` at `at`: quoted up to its closing
// quote, else up to the next "=" or " + ". False where a quote is not
// closed or the word is empty.
bool read_word(const std::string& name, std::size_t& at, std::string& word) {
  if (at < name.size() && (name[at] == '\'' || name[at] == '"')) {
    const std::size_t close = name.find(name[at], at + 1);
    if (close == std::string::npos) return false;
    word = name.substr(at + 1, close - at - 1);
    at = close + 1;
    return true;
  }
  std::size_t end = std::min(name.find('=', at), name.find(kJoin, at));
  if (end == std::string::npos) end = name.size();
  word = name.substr(at, end - at);
  at = end;
  return !word.empty();
}

}  // namespace

bool is_default_slot(std::string_view slot) {
  const std::string upper = upper_case(slot);
  return upper.empty() || upper == "DEFAULT" || upper == "1";
}

std::string region_name(const std::vector<Membership>& groups) {
  std::string name;
  for (const Membership& m : groups)
    name +=
        (name.empty() ? "" : std::string(kJoin)) + (is_default_slot(m.slot) ? "" : part(m.slot) + "=") + part(m.group);
  return name;
}

std::vector<Membership> memberships_of(const std::string& name) {
  const std::vector<Membership> whole{Membership{"Default", name}};
  std::vector<Membership> groups;
  std::vector<std::string> slots;  // in upper case, "DEFAULT" for the default one
  for (std::size_t at = 0;;) {
    Membership m{"Default", ""};
    if (!read_word(name, at, m.group)) return whole;
    if (at < name.size() && name[at] == '=') {
      m.slot = m.group;
      if (!read_word(name, ++at, m.group)) return whole;
    }
    const std::string slot = is_default_slot(m.slot) ? "DEFAULT" : upper_case(m.slot);
    for (const std::string& s : slots)
      if (s == slot) return whole;
    slots.push_back(slot);
    groups.push_back(std::move(m));
    if (at == name.size()) return groups;
    if (name.compare(at, kJoin.size(), kJoin) != 0) return whole;
    at += kJoin.size();
  }
}

}  // namespace tetsmooth::flac3d
