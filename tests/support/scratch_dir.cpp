#include "scratch_dir.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

namespace tetsmooth::testing {

ScratchDir::ScratchDir(const std::string& tag) {
  std::string name = "tetsmooth_" + tag;
  if (const auto* info = ::testing::UnitTest::GetInstance()->current_test_info())
    name += std::string("_") + info->test_suite_name() + "_" + info->name();
  name += "_" + std::to_string(::getpid());
  // Parameterised tests are named "Suite/Name/3": one path component only.
  for (char& c : name)
    if (c == '/') c = '_';
  dir_ = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir_);
  std::filesystem::create_directories(dir_);
}

ScratchDir::~ScratchDir() {
  std::error_code ignored;  // a destructor must not throw; a leftover folder in /tmp is harmless
  std::filesystem::remove_all(dir_, ignored);
}

}  // namespace tetsmooth::testing
