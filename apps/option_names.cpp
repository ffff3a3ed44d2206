#include "apps/option_names.hpp"

#include <utility>

#include "mesh/errors.hpp"

namespace tetsmooth::cli {
namespace {

constexpr std::pair<const char*, Method> kMethods[] = {{"adaptive", Method::Adaptive}, {"ordinary", Method::Ordinary}};
constexpr std::pair<const char*, Form> kForms[] = {{"A", Form::A}, {"B", Form::B}};
constexpr std::pair<const char*, Strategy> kStrategies[] = {
    {"coloured", Strategy::Coloured}, {"multiblock", Strategy::MultiBlock}, {"singleblock", Strategy::SingleBlock}};
constexpr std::pair<const char*, Layout> kLayouts[] = {{"aos", Layout::AoS}, {"soa", Layout::SoA}};
constexpr std::pair<const char*, Device> kDevices[] = {
    {"auto", Device::Auto}, {"cpu", Device::Cpu}, {"cuda", Device::Cuda}};
constexpr std::pair<const char*, Precision> kPrecisions[] = {{"float", Precision::Float},
                                                             {"double", Precision::Double}};
constexpr std::pair<const char*, ProgressMode> kProgressModes[] = {
    {"auto", ProgressMode::Auto}, {"always", ProgressMode::Always}, {"never", ProgressMode::Never}};
constexpr std::pair<const char*, Ordering> kOrderings[] = {{"natural", Ordering::Natural},
                                                           {"coloured", Ordering::Coloured}};

template <class Enum, std::size_t N>
Enum parse_name(const std::pair<const char*, Enum> (&table)[N], const std::string& option, const std::string& text) {
  std::string accepted;
  for (const auto& [name, value] : table) {
    if (text == name) return value;
    accepted += accepted.empty() ? name : std::string("|") + name;
  }
  throw UsageError("invalid value '" + text + "' for " + option + ": expected " + accepted);
}

template <class Enum, std::size_t N>
const char* name_of(const std::pair<const char*, Enum> (&table)[N], Enum value) {
  for (const auto& [name, v] : table)
    if (v == value) return name;
  return "?";
}

}  // namespace

Method parse_method(const std::string& option, const std::string& text) { return parse_name(kMethods, option, text); }
Form parse_form(const std::string& option, const std::string& text) { return parse_name(kForms, option, text); }
Strategy parse_strategy(const std::string& option, const std::string& text) {
  return parse_name(kStrategies, option, text);
}
Layout parse_layout(const std::string& option, const std::string& text) { return parse_name(kLayouts, option, text); }
Device parse_device(const std::string& option, const std::string& text) { return parse_name(kDevices, option, text); }
ProgressMode parse_progress_mode(const std::string& option, const std::string& text) {
  return parse_name(kProgressModes, option, text);
}
Precision parse_precision(const std::string& option, const std::string& text) {
  return parse_name(kPrecisions, option, text);
}

const char* option_name(Method m) { return name_of(kMethods, m); }
const char* option_name(Form f) { return name_of(kForms, f); }
const char* option_name(Strategy s) { return name_of(kStrategies, s); }
const char* option_name(Layout l) { return name_of(kLayouts, l); }
const char* option_name(Device d) { return name_of(kDevices, d); }
const char* option_name(Precision p) { return name_of(kPrecisions, p); }
const char* option_name(Ordering o) { return name_of(kOrderings, o); }

const char* input_format_name(MeshFormat f) {
  const bool gmsh = f == MeshFormat::Msh41 || f == MeshFormat::Msh41Binary || f == MeshFormat::Msh22;
  return gmsh ? "msh" : format_name(f);
}

}  // namespace tetsmooth::cli
