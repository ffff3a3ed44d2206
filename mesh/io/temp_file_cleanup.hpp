#pragma once
// Temporary files that an interrupting signal removes.
//
// write_atomically (atomic_file.hpp) writes beside its target and renames at
// the end; a Ctrl-C or a kill during a long write would otherwise leave the
// hidden temporary behind. While a temporary is registered here, the
// signals whose default action ends the process (SIGINT, SIGTERM, SIGHUP,
// SIGQUIT, SIGPIPE, SIGALRM, SIGUSR1/2, SIGXCPU, SIGXFSZ, SIGVTALRM, SIGPROF)
// unlink it and then end the process as that default action would. The handlers are installed on first use, and only
// for signals whose disposition is still the default: a program that
// handles them itself keeps its own handlers (and its own clean-up).
#include <string>

namespace tetsmooth {

// Registers `path` for removal on an interrupting signal; returns the slot
// to pass to forget_temp_file, or -1 when it could not be registered (more
// than a few temporaries at once, or a path too long to keep), in which case
// only the signal clean-up is lost.
int remember_temp_file(const std::string& path);

// Ends the registration of `slot` (ignores -1).
void forget_temp_file(int slot);

}  // namespace tetsmooth
