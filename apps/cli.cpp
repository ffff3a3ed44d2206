#include "apps/cli.hpp"

#include <new>
#include <type_traits>

#include "apps/cli_help.hpp"
#include "apps/command_line.hpp"
#include "apps/commands.hpp"
#include "apps/exit_codes.hpp"
#include "mesh/errors.hpp"

namespace tetsmooth::cli {
namespace {

bool is_quiet(const Command& command) {
  return std::visit(
      [](const auto& c) {
        if constexpr (std::is_same_v<std::decay_t<decltype(c)>, HelpRequest> ||
                      std::is_same_v<std::decay_t<decltype(c)>, VersionRequest>)
          return false;
        else
          return c.quiet;
      },
      command);
}

void run_command(const Command& command, const Console& console) {
  struct Runner {
    const Console& console;
    void operator()(const HelpRequest& h) const { console.out << help_text(h.command); }
    void operator()(const VersionRequest&) const { console.out << version_text(); }
    void operator()(const GenerateCommand& c) const { run_generate(c, console); }
    void operator()(const SmoothCommand& c) const { run_smooth(c, console); }
    void operator()(const QualityCommand& c) const { run_quality(c, console); }
    void operator()(const ConvertCommand& c) const { run_convert(c, console); }
  };
  std::visit(Runner{console}, command);
}

int fail(std::ostream& err, ExitCode code, const std::string& message) {
  err << "tetsmooth: error: " << message << '\n';
  return code;
}

}  // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, bool err_is_terminal) {
  try {
    const Command command = parse_command_line(args);
    const Console console{out, err, err_is_terminal, is_quiet(command)};
    run_command(command, console);
    // Results on stdout are output too: a full disk or closed pipe must not
    // pass for success.
    out.flush();
    if (!out) return fail(err, kExitOutput, "cannot write to standard output");
    return kExitOk;
  } catch (const UsageError& e) {
    return fail(err, kExitUsage, e.what());
  } catch (const InputError& e) {
    return fail(err, kExitInput, e.what());
  } catch (const OutputError& e) {
    return fail(err, kExitOutput, e.what());
  } catch (const DeviceError& e) {
    return fail(err, kExitDevice, e.what());
  } catch (const std::bad_alloc&) {
    return fail(err, kExitInternal, "out of memory");
  } catch (const std::exception& e) {
    return fail(err, kExitInternal, std::string("internal error: ") + e.what());
  } catch (...) {
    return fail(err, kExitInternal, "internal error: unknown exception");
  }
}

}  // namespace tetsmooth::cli
