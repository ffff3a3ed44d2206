// The command line a result JSON records: a POSIX shell must read it back
// as the very arguments the run had.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <string>
#include <vector>

#include "bench/command_line.hpp"

namespace tetsmooth::bench {
namespace {

// The arguments /bin/sh makes of `line`, each printed on a line of its own
// by printf (so no argument may hold a newline here).
std::vector<std::string> shell_words(const std::string& line) {
  const std::string script = "printf '%s\\n' " + line;
  std::string command = "/bin/sh -c " + shell_quoted(script);
  std::FILE* pipe = popen(command.c_str(), "r");
  EXPECT_NE(pipe, nullptr);
  std::vector<std::string> words;
  if (!pipe) return words;
  std::string word;
  std::array<char, 256> buffer{};
  std::size_t n;
  std::string all;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) all.append(buffer.data(), n);
  EXPECT_EQ(pclose(pipe), 0);
  for (const char c : all) {
    if (c == '\n') {
      words.push_back(word);
      word.clear();
    } else {
      word += c;
    }
  }
  return words;
}

TEST(CommandLine, PlainArgumentsStayAsTheyAre) {
  EXPECT_EQ(shell_quoted("--benchmark_filter=FormB/AoS/Coloured/109k"), "--benchmark_filter=FormB/AoS/Coloured/109k");
  EXPECT_EQ(shell_quoted("--models=5k,109k"), "--models=5k,109k");
}

TEST(CommandLine, TheProgramIsNamedWithoutItsFolder) {
  const char* argv[] = {"/tmp/gpu-bundle/bench_smooth", "--no-cpu"};
  EXPECT_EQ(command_line(2, argv), "bench_smooth --no-cpu");
}

TEST(CommandLine, TheShellReadsBackTheSameArguments) {
  const std::vector<std::string> args = {"bench_smooth",
                                         "--benchmark_filter=Memory|Serial/FormB/109k|FormB/AoS/(Coloured|MultiBlock)/",
                                         "--benchmark_out=/tmp/a b/run's.json",
                                         "",
                                         "$HOME",
                                         "`date`",
                                         "a\"b\\c",
                                         "*",
                                         "--x=~;&>#!"};
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  const std::string line = command_line(static_cast<int>(argv.size()), argv.data());
  EXPECT_EQ(shell_words(line), args) << line;
}

}  // namespace
}  // namespace tetsmooth::bench
