#include "apps/console.hpp"

namespace tetsmooth::cli {

void Console::warn(const std::string& text) const {
  if (!quiet) err << "tetsmooth: warning: " << text << '\n';
}

void Console::note(const std::string& text) const {
  if (!quiet) err << text << '\n';
}

}  // namespace tetsmooth::cli
