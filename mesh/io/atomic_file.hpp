#pragma once
// Writing files so that a reader never sees a half-written one: the body is
// written to a temporary file beside the target (same directory, so the
// rename cannot cross file systems), flushed to disk, and renamed over the
// target. On any failure the temporary is removed and OutputError names the
// path and the reason (strerror). Exceptions thrown by the body itself are
// passed on unchanged, after the same clean-up, and an interrupting signal
// (SIGINT, SIGTERM, SIGHUP, ...) removes the temporary too
// (temp_file_cleanup.hpp).
//
// What stands at the target decides the rest:
//  * a symbolic link is followed (to its end, even a dangling one): the file
//    it names is replaced and the link stays a link; links that never end (a
//    cycle, or more than 40) fail as open() would, with ELOOP;
//  * an existing regular file keeps its permission bits;
//  * a device, FIFO or socket (a terminal, a pipe), or a file a process
//    holds open, reached through /proc (/dev/stdout or /dev/fd/1 sent to a
//    file), is written directly, as there is nothing to rename over it, or
//    renaming would cut it off from its descriptor: such a write is not
//    atomic. A regular file this process holds open for writing is written
//    through a copy of that descriptor, so that the bytes land at its
//    offset and what the process writes there next comes after them
//    (stdout's buffers are flushed first; a file opened with <> keeps
//    whatever lies past the bytes written); another process's held file is
//    appended to, and a device or pipe opened afresh.
#include <functional>
#include <ostream>
#include <string>
#include <vector>

#include "mesh/errors.hpp"

namespace tetsmooth {

using StreamBody = std::function<void(std::ostream&)>;

// Where a write to `path` lands: symbolic links followed to their end, each
// relative one against its own directory. `held` when the chain goes through
// /proc, by a link's target (/dev/stdout is a link to /proc/self/fd/1) or by
// a directory that resolves there (/dev/fd is a link to /proc/self/fd, which
// the kernel follows inside lstat, so /dev/fd/1's only visible hop leads
// straight to the file): the file is one a process has open, and renaming
// another over it would cut it off from that descriptor. `fd` is this
// process's descriptor the chain went through (/proc/self/fd/N, N), or -1.
// `endless` when the links do not end (a cycle, or more than 40 of them);
// `path` is then the last one reached.
struct LinkEnd {
  std::string path;
  bool held = false, endless = false;
  int fd = -1;
};
LinkEnd follow_links(const std::string& path);

// `binary` states the body's intent; on POSIX both modes write the bytes as
// given (no newline translation), so it only matters on platforms with a
// text mode.
void write_atomically(const std::string& path, const StreamBody& body, bool binary = false);

// One file of a set written together (TetGen X.node + X.ele).
struct AtomicPart {
  std::string path;
  StreamBody body;
};

// Writes every part to its temporary first and renames only when all of
// them are complete, so a failure in any body leaves every target as it was.
// Every target is checked before the first rename (a directory in the way
// fails the whole set), but renames are atomic one by one, not as a set: if
// a rename itself fails after an earlier one succeeded, the earlier target
// is already replaced.
void write_atomically(const std::vector<AtomicPart>& parts, bool binary = false);

// Returns what `check` returns; an OutputError it throws (a mesh the format
// cannot hold) is thrown again as "cannot write 'path': <its message>". For
// the checks a writer makes before it creates any file.
template <class Check>
auto checked_for(const std::string& path, Check&& check) -> decltype(check()) {
  try {
    return check();
  } catch (const OutputError& e) {
    throw OutputError("cannot write '" + path + "': " + e.what());
  }
}

}  // namespace tetsmooth
