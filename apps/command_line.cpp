#include "apps/command_line.hpp"

#include <climits>

#include "apps/arg_parser.hpp"
#include "apps/option_names.hpp"
#include "mesh/errors.hpp"

namespace tetsmooth::cli {
namespace {

const OptionSpec kHelp{"help", 'h', false};
const OptionSpec kQuiet{"quiet", 'q', false};
const OptionSpec kOutput{"output", 'o', true};
const OptionSpec kFormat{"format", 0, true};
const OptionSpec kOutputFormat{"output-format", 0, true};

std::string see_help(const std::string& command) { return " (see 'tetsmooth " + command + " --help')"; }

void expect_positionals(const ParsedArgs& parsed, std::size_t count, const std::string& what,
                        const std::string& command) {
  if (parsed.positionals.size() < count) throw UsageError(command + ": missing " + what + see_help(command));
  if (parsed.positionals.size() > count)
    throw UsageError(command + ": unexpected argument '" + parsed.positionals[count] + "'" + see_help(command));
}

const std::string& required_output(const ParsedArgs& parsed, const std::string& command) {
  if (!parsed.has("output")) throw UsageError(command + ": missing -o OUT" + see_help(command));
  return parsed.value("output");
}

MeshFormat format_option(const ParsedArgs& parsed, const std::string& name) {
  return parsed.has(name) ? parse_format(parsed.value(name)) : MeshFormat::Auto;
}

GenerateCommand parse_generate(const std::vector<std::string>& args) {
  const ParsedArgs p = parse_args(args, {kHelp, kQuiet, kOutput, kOutputFormat, {"seed", 0, true}}, "generate");
  expect_positionals(p, 1, "MODEL", "generate");
  GenerateCommand c;
  c.model = p.positionals[0];
  c.output = required_output(p, "generate");
  c.output_format = format_option(p, "output-format");
  if (p.has("seed")) c.seed = parse_u64_option("--seed", p.value("seed"));
  c.quiet = p.has("quiet");
  return c;
}

SmoothCommand parse_smooth(const std::vector<std::string>& args) {
  const ParsedArgs p = parse_args(args,
                                  {kHelp,
                                   kQuiet,
                                   kOutput,
                                   kFormat,
                                   kOutputFormat,
                                   {"method", 0, true},
                                   {"form", 0, true},
                                   {"strategy", 0, true},
                                   {"layout", 0, true},
                                   {"device", 0, true},
                                   {"threads", 0, true},
                                   {"precision", 0, true},
                                   {"max-iter", 0, true},
                                   {"tol", 0, true},
                                   {"report", 0, true},
                                   {"progress", 0, true}},
                                  "smooth");
  expect_positionals(p, 1, "input mesh IN", "smooth");
  SmoothCommand c;
  c.input = p.positionals[0];
  c.output = required_output(p, "smooth");
  c.input_format = format_option(p, "format");
  c.output_format = format_option(p, "output-format");
  c.options.threads = 0;  // the CLI's default is every core; the library's is serial
  if (p.has("method")) c.options.method = parse_method("--method", p.value("method"));
  if (p.has("form")) c.options.form = parse_form("--form", p.value("form"));
  if (p.has("strategy")) c.options.strategy = parse_strategy("--strategy", p.value("strategy"));
  if (p.has("layout")) c.options.layout = parse_layout("--layout", p.value("layout"));
  if (p.has("device")) c.device = parse_device("--device", p.value("device"));
  if (p.has("threads")) c.options.threads = parse_int_option("--threads", p.value("threads"), 0, 4096);
  if (p.has("precision")) c.options.precision = parse_precision("--precision", p.value("precision"));
  if (p.has("max-iter")) c.options.max_iterations = parse_int_option("--max-iter", p.value("max-iter"), 1, INT_MAX);
  if (p.has("tol")) c.options.tolerance = parse_nonnegative_option("--tol", p.value("tol"));
  if (p.has("progress")) c.progress = parse_progress_mode("--progress", p.value("progress"));
  if (p.has("report")) {
    c.report_path = p.value("report");
    if (c.report_path.empty()) throw UsageError("--report needs a file name");
  }
  // Only the serial reference (--threads 1) runs Form B in natural node order;
  // any other count visits nodes colour by colour, which is race-free and
  // gives the same mesh whatever the number of cores.
  c.options.ordering = c.options.form == Form::B && c.options.threads != 1 ? Ordering::Coloured : Ordering::Natural;
  c.strategy_given = p.has("strategy");
  // Coloured is a Form B scheme: Form A's default is the paper's MultiBlock,
  // and an explicit coloured Form A is refused here, before any reading and
  // whatever the device, rather than by the GPU after the set-up.
  if (c.options.form == Form::A) {
    if (!c.strategy_given)
      c.options.strategy = Strategy::MultiBlock;
    else if (c.options.strategy == Strategy::Coloured)
      throw UsageError("--strategy coloured is an in-place (--form B) scheme; with --form A use multiblock or "
                       "singleblock");
  }
  c.layout_given = p.has("layout");
  c.quiet = p.has("quiet");
  return c;
}

QualityCommand parse_quality(const std::vector<std::string>& args) {
  const ParsedArgs p = parse_args(args, {kHelp, kQuiet, kFormat, {"json", 0, false}, {"worst", 0, true}}, "quality");
  expect_positionals(p, 1, "input mesh IN", "quality");
  QualityCommand c;
  c.input = p.positionals[0];
  c.input_format = format_option(p, "format");
  c.json = p.has("json");
  if (p.has("worst")) c.worst = parse_int_option("--worst", p.value("worst"), 0, INT_MAX);
  c.quiet = p.has("quiet");
  return c;
}

ConvertCommand parse_convert(const std::vector<std::string>& args) {
  const ParsedArgs p = parse_args(args, {kHelp, kQuiet, kFormat, kOutputFormat}, "convert");
  expect_positionals(p, 2, p.positionals.empty() ? "IN and OUT" : "OUT", "convert");
  ConvertCommand c;
  c.input = p.positionals[0];
  c.output = p.positionals[1];
  c.input_format = format_option(p, "format");
  c.output_format = format_option(p, "output-format");
  c.quiet = p.has("quiet");
  return c;
}

bool asks_for_help(const std::vector<std::string>& args) {
  for (const std::string& a : args) {
    if (a == "--") return false;
    if (a == "--help" || a == "-h") return true;
  }
  return false;
}

bool is_command(const std::string& name) {
  for (const std::string& c : command_names())
    if (c == name) return true;
  return false;
}

std::string command_list() {
  std::string list;
  for (const std::string& c : command_names()) list += (list.empty() ? "" : ", ") + c;
  return list;
}

}  // namespace

const std::vector<std::string>& command_names() {
  static const std::vector<std::string> names{"generate", "smooth", "quality", "convert"};
  return names;
}

Command parse_command_line(const std::vector<std::string>& args) {
  if (args.empty()) throw UsageError("no command given (see 'tetsmooth --help')");
  const std::string& first = args[0];
  if (first == "--help" || first == "-h" || first == "help") {
    if (args.size() > 2) throw UsageError("help takes at most one command name");
    const std::string topic = args.size() == 2 ? args[1] : "";
    if (!topic.empty() && !is_command(topic))
      throw UsageError("no help for '" + topic + "': commands are " + command_list());
    return HelpRequest{topic};
  }
  if (first == "--version") {
    if (args.size() > 1) throw UsageError("--version takes no arguments");
    return VersionRequest{};
  }
  if (!is_command(first)) {
    const std::string kind = first.size() > 1 && first[0] == '-' ? "option" : "command";
    throw UsageError("unknown " + kind + " '" + first + "'; commands are " + command_list() +
                     " (see 'tetsmooth --help')");
  }
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (asks_for_help(rest)) return HelpRequest{first};
  if (first == "generate") return parse_generate(rest);
  if (first == "smooth") return parse_smooth(rest);
  if (first == "quality") return parse_quality(rest);
  return parse_convert(rest);
}

}  // namespace tetsmooth::cli
