#pragma once
// A small command-line tokenizer: long options (--name, --name=value,
// --name value), short ones (-o value, -q), positionals, and "--" to end the
// options. It knows nothing about what the options mean; command_line.cpp
// turns the tokens into commands.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace tetsmooth::cli {

struct OptionSpec {
  std::string name;     // long name without the dashes, e.g. "max-iter"
  char short_name = 0;  // e.g. 'o'; 0 for none
  bool takes_value = false;
};

struct ParsedArgs {
  std::vector<std::string> positionals;
  std::map<std::string, std::string> values;  // by long name; flags map to ""; an option with a value may be given once

  bool has(const std::string& name) const { return values.count(name) != 0; }
  const std::string& value(const std::string& name) const { return values.at(name); }
};

// Throws UsageError for an unknown option (suggesting the nearest known one),
// a missing value, or a value given to a flag. `command` names the
// subcommand in messages.
ParsedArgs parse_args(const std::vector<std::string>& args, const std::vector<OptionSpec>& specs,
                      const std::string& command);

// Value parsers for option `option` (named in the UsageError they throw).
int parse_int_option(const std::string& option, const std::string& text, int min, int max);
std::uint64_t parse_u64_option(const std::string& option, const std::string& text);
// A finite number >= 0.
double parse_nonnegative_option(const std::string& option, const std::string& text);

}  // namespace tetsmooth::cli
