// The tetsmooth executable; everything lives in the tetsmooth_cli library.
#include <unistd.h>

#include <iostream>

#include "apps/cli.hpp"

int main(int argc, char** argv) {
  return tetsmooth::cli::run_cli({argv + 1, argv + argc}, std::cout, std::cerr, ::isatty(STDERR_FILENO) != 0);
}
