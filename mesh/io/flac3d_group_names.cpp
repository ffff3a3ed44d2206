#include "mesh/io/flac3d_group_names.hpp"

#include "mesh/io/text_lines.hpp"

namespace tetsmooth::flac3d {
namespace {

constexpr std::string_view kJoin = " + ";

}  // namespace

bool is_default_slot(std::string_view slot) {
  const std::string upper = upper_case(slot);
  return upper.empty() || upper == "DEFAULT" || upper == "1";
}

std::string region_name(const std::vector<Membership>& groups) {
  std::string name;
  for (const Membership& m : groups)
    name += (name.empty() ? "" : std::string(kJoin)) + (is_default_slot(m.slot) ? "" : m.slot + "=") + m.group;
  return name;
}

std::vector<Membership> memberships_of(const std::string& name) {
  std::vector<Membership> groups;
  std::vector<std::string> slots;  // in upper case, "DEFAULT" for the default one
  for (std::size_t start = 0; start <= name.size();) {
    std::size_t end = name.find(kJoin, start);
    if (end == std::string::npos) end = name.size();
    const std::string part = name.substr(start, end - start);
    const std::size_t equals = part.find('=');
    Membership m = equals == std::string::npos ? Membership{"Default", part}
                                               : Membership{part.substr(0, equals), part.substr(equals + 1)};
    const std::string slot = is_default_slot(m.slot) ? "DEFAULT" : upper_case(m.slot);
    bool repeated = false;
    for (const std::string& s : slots) repeated = repeated || s == slot;
    if (m.group.empty() || m.slot.empty() || repeated) return {Membership{"Default", name}};
    slots.push_back(slot);
    groups.push_back(std::move(m));
    start = end + kJoin.size();
  }
  return groups;
}

}  // namespace tetsmooth::flac3d
