#pragma once
// The text of --help and --version.
#include <string>

namespace tetsmooth::cli {

// `command` empty gives the top-level help; otherwise one of command_names().
std::string help_text(const std::string& command);

std::string version_text();

}  // namespace tetsmooth::cli
