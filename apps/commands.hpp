#pragma once
// One function per subcommand. Each throws the library's exceptions
// (mesh/errors.hpp) on failure; run_cli maps them to exit codes.
#include "apps/command_line.hpp"
#include "apps/console.hpp"

namespace tetsmooth::cli {

void run_generate(const GenerateCommand& command, const Console& console);
void run_smooth(const SmoothCommand& command, const Console& console);
void run_quality(const QualityCommand& command, const Console& console);
void run_convert(const ConvertCommand& command, const Console& console);

}  // namespace tetsmooth::cli
