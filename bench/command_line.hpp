#pragma once
// The command a run was started with, as one line a POSIX shell reads back
// as the same arguments: the result JSON's context records it
// ("command_line"), so that a result says how to make it again.
#include <string>

namespace tetsmooth::bench {

// One argument as the shell would need it: unchanged when it holds only
// characters no shell treats specially, otherwise in single quotes (a quote
// inside written '\'').
std::string shell_quoted(const std::string& arg);

// argv[0]'s file name (the folder it ran from says nothing of the run) and
// the other arguments, each shell_quoted, joined by spaces.
std::string command_line(int argc, const char* const* argv);

}  // namespace tetsmooth::bench
