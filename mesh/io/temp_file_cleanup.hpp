#pragma once
// Temporary files that an interrupting signal removes.
//
// write_atomically (atomic_file.hpp) writes beside its target and renames at
// the end; a Ctrl-C or a kill during a long write would otherwise leave the
// hidden temporary behind. While a temporary is registered here, every
// signal whose default action ends the process (Ctrl-C, SIGTERM, SIGHUP,
// SIGPIPE, SIGABRT, SIGSEGV, the timers, the user and real-time signals,
// ...: all but SIGKILL, which cannot be caught) unlinks it and then ends the
// process as that default action would (with a core dump where it dumps). The handlers are installed on first use, and only
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
