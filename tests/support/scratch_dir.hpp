#pragma once
// A fresh folder for one test's files, removed when the test is done.
#include <filesystem>
#include <string>

namespace tetsmooth::testing {

// <temp>/tetsmooth_<tag>_<suite>_<test>_<pid>, created empty. The running
// test's names keep the tests of one binary apart (CTest runs them side by
// side), the process id two runs of the binary at once (two build trees, two
// workers on one host, a death test's child). Removed with its contents when
// the object goes; a death-test child that ends with _Exit removes it itself.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& tag);
  ~ScratchDir();
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return dir_; }
  // The path of `name` inside the folder.
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

 private:
  std::filesystem::path dir_;
};

}  // namespace tetsmooth::testing
