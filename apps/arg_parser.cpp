#include "apps/arg_parser.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "mesh/errors.hpp"

namespace tetsmooth::cli {
namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitute});
    }
  }
  return row[b.size()];
}

std::string unknown_option_message(const std::string& token, const std::vector<OptionSpec>& specs,
                                   const std::string& command) {
  std::string message = "unknown option '" + token + "' for '" + command + "'";
  // Typos are the usual cause: name the closest long option when it is close.
  const std::size_t start = token.find_first_not_of('-');
  const std::string bare = start == std::string::npos ? std::string() : token.substr(start);
  const OptionSpec* best = nullptr;
  std::size_t best_distance = 3;
  for (const OptionSpec& spec : specs) {
    const std::size_t d = edit_distance(bare, spec.name);
    if (d < best_distance) best = &spec, best_distance = d;
  }
  if (best) message += "; did you mean '--" + best->name + "'?";
  return message + " (see 'tetsmooth " + command + " --help')";
}

const OptionSpec* find_long(const std::vector<OptionSpec>& specs, const std::string& name) {
  for (const OptionSpec& spec : specs)
    if (spec.name == name) return &spec;
  return nullptr;
}

const OptionSpec* find_short(const std::vector<OptionSpec>& specs, char c) {
  for (const OptionSpec& spec : specs)
    if (spec.short_name != 0 && spec.short_name == c) return &spec;
  return nullptr;
}

[[noreturn]] void bad_value(const std::string& option, const std::string& text, const std::string& expected) {
  throw UsageError("invalid value '" + text + "' for " + option + ": expected " + expected);
}

}  // namespace

ParsedArgs parse_args(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs,
                      const std::string& command) {
  ParsedArgs parsed;
  bool options_ended = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& token = args[i];
    // "-" alone is a positional by convention (a file name), never an option.
    if (options_ended || token.size() < 2 || token[0] != '-') {
      parsed.positionals.push_back(token);
      continue;
    }
    if (token == "--") {
      options_ended = true;
      continue;
    }
    const OptionSpec* spec = nullptr;
    std::string shown;  // the option as the user spelled it, for messages
    std::string inline_value;
    bool has_inline_value = false;
    if (token[1] == '-') {
      const std::size_t eq = token.find('=');
      spec = find_long(specs, token.substr(2, eq == std::string::npos ? std::string::npos : eq - 2));
      shown = token.substr(0, eq);
      if (eq != std::string::npos) inline_value = token.substr(eq + 1), has_inline_value = true;
    } else if (token.size() == 2) {
      spec = find_short(specs, token[1]);
      shown = token;
    }
    if (!spec) throw UsageError(unknown_option_message(shown.empty() ? token : shown, specs, command));
    // The last of two values would win unseen (-o a.msh ... -o b.msh).
    if (spec->takes_value && parsed.values.count(spec->name) != 0)
      throw UsageError("option " + shown + " is given more than once");
    if (!spec->takes_value) {
      if (has_inline_value) throw UsageError("option " + shown + " takes no value");
      parsed.values[spec->name] = "";
      continue;
    }
    if (has_inline_value) {
      parsed.values[spec->name] = inline_value;
    } else {
      if (i + 1 >= args.size()) throw UsageError("option " + shown + " needs a value");
      parsed.values[spec->name] = args[++i];
    }
  }
  return parsed;
}

int parse_int_option(const std::string& option, const std::string& text, int min, int max) {
  int value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || value < min || value > max)
    bad_value(option, text, "an integer from " + std::to_string(min) + " to " + std::to_string(max));
  return value;
}

std::uint64_t parse_u64_option(const std::string& option, const std::string& text) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end) bad_value(option, text, "a non-negative integer");
  return value;
}

double parse_nonnegative_option(const std::string& option, const std::string& text) {
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value) || value < 0)
    bad_value(option, text, "a finite number >= 0");
  return value;
}

}  // namespace tetsmooth::cli
