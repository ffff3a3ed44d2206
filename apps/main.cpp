// The tetsmooth executable; everything lives in the tetsmooth_cli library.
#include <unistd.h>

#include <csignal>
#include <iostream>

#include "apps/cli.hpp"

int main(int argc, char** argv) {
  // Past a file-size limit (ulimit -f) a write then fails with EFBIG, which
  // the writers report as an output error (exit 4, temporary removed),
  // instead of SIGXFSZ ending the process without a word.
  std::signal(SIGXFSZ, SIG_IGN);
  return tetsmooth::cli::run_cli({argv + 1, argv + argc}, std::cout, std::cerr, ::isatty(STDERR_FILENO) != 0);
}
