#pragma once
// The exit status of every tetsmooth command. Scripts branch on these, so
// they are part of the interface: keep the numbers stable and keep the
// --help text (cli_help.cpp) in step.
namespace tetsmooth::cli {

enum ExitCode : int {
  kExitOk = 0,
  kExitInternal = 1,  // a bug or an exhausted resource (out of memory)
  kExitUsage = 2,     // bad command line or options that make no sense together
  kExitInput = 3,     // unreadable, malformed or invalid input mesh
  kExitOutput = 4,    // an output file or report that cannot be written
  kExitDevice = 5,    // GPU missing or failing, or CUDA support not built
};

}  // namespace tetsmooth::cli
