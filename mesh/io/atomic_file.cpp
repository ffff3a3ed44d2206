#include "mesh/io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <memory>
#include <streambuf>

#include "mesh/errors.hpp"
#include "mesh/io/temp_file_cleanup.hpp"

namespace tetsmooth {
namespace {

// `what` leads into strerror(err) when err is set ("cannot rename ...: ").
[[noreturn]] void fail(const std::string& path, const std::string& what, int err) {
  throw OutputError("cannot write '" + path + "': " + what + (err != 0 ? std::strerror(err) : ""));
}

// An output buffer straight over a file descriptor. It keeps the first errno
// of a failed write, so a full disk is reported as "No space left on device"
// rather than as a stream that merely went bad.
class FdBuf : public std::streambuf {
 public:
  explicit FdBuf(int fd) : fd_(fd) { setp(buf_, buf_ + sizeof buf_); }
  int error() const { return error_; }

 protected:
  int_type overflow(int_type ch) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }
  int sync() override { return drain() ? 0 : -1; }

 private:
  bool drain() {
    if (error_ != 0) return false;
    const char* p = pbase();
    std::size_t left = static_cast<std::size_t>(pptr() - pbase());
    while (left > 0) {
      const ssize_t n = ::write(fd_, p, left);
      if (n < 0) {
        if (errno == EINTR) continue;
        error_ = errno;
        return false;
      }
      p += n;
      left -= static_cast<std::size_t>(n);
    }
    setp(buf_, buf_ + sizeof buf_);
    return true;
  }

  int fd_;
  int error_ = 0;
  char buf_[1 << 16];
};

bool same_inode(int fd, const struct stat& st) {
  struct stat held {};
  return ::fstat(fd, &held) == 0 && held.st_dev == st.st_dev && held.st_ino == st.st_ino;
}

bool writable(int fd) {
  const int flags = ::fcntl(fd, F_GETFL);
  return flags >= 0 && (flags & O_ACCMODE) != O_RDONLY;
}

// Where the bytes go: a temporary beside the target, renamed over it by
// commit() and removed otherwise; or, for a target that is a device, FIFO or
// socket, or a file this process holds open through /proc, the target itself.
class TempFile {
 public:
  explicit TempFile(const std::string& target) : target_(target) {
    const LinkEnd end = follow_links(target_);
    if (end.endless) fail(target_, "", ELOOP);
    const bool held = end.held;
    dest_ = end.path;
    struct stat st {};
    const bool exists = ::stat(target_.c_str(), &st) == 0;  // through every link, /proc's too
    if (exists && ((!S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) || held)) {
      direct_ = true;
      if (S_ISREG(st.st_mode) && end.fd >= 0 && same_inode(end.fd, st) && writable(end.fd)) {
        // Our own descriptor of a regular file (stdout sent to a file), open
        // for writing: a copy shares its offset, so the body lands where the
        // process writes and whatever it writes there afterwards (a report
        // on stdout) follows the body instead of overwriting it. Bytes still
        // in stdio's buffers go first.
        std::fflush(nullptr);
        fd_ = ::fcntl(end.fd, F_DUPFD_CLOEXEC, 0);
      } else {
        // A device or pipe is opened afresh (a copy would share the caller's
        // O_NONBLOCK, and a full pipe would fail the write); another
        // process's held file, or ours open read-only, is appended to.
        fd_ = ::open(target_.c_str(), O_WRONLY | O_CLOEXEC | (S_ISREG(st.st_mode) ? O_APPEND : O_TRUNC));
      }
      if (fd_ < 0) fail(target_, "", errno);
      return;
    }
    static std::atomic<unsigned> counter{0};
    const std::size_t slash = dest_.rfind('/');
    const std::string dir = slash == std::string::npos ? "" : dest_.substr(0, slash + 1);
    const std::string base = slash == std::string::npos ? dest_ : dest_.substr(slash + 1);
    // O_EXCL with a fresh name per attempt: concurrent writers of the same
    // target never share a temporary. Mode 0666 lets the umask decide, as for
    // any newly created file; a file that is replaced keeps its own mode.
    for (int attempt = 0; attempt < 100; ++attempt) {
      // Cut to the target's own limit (NAME_MAX bytes): a legal long name
      // must not fail for its temporary's longer one.
      const std::string suffix = ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
      path_ = dir + "." + base.substr(0, NAME_MAX - 1 - suffix.size()) + suffix;
      fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd_ >= 0) break;
      if (errno != EEXIST) break;
    }
    if (fd_ < 0) {
      const int err = errno;
      path_.clear();
      fail(target_, "cannot create a temporary file beside it: ", err);
    }
    slot_ = remember_temp_file(path_);
    if (exists && S_ISREG(st.st_mode) && ::fchmod(fd_, st.st_mode & 07777) != 0) {
      const int err = errno;  // no destructor runs for a throwing constructor
      ::close(fd_);
      ::unlink(path_.c_str());
      forget_temp_file(slot_);
      fail(target_, "cannot give the new file the mode of the old one: ", err);
    }
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!path_.empty()) ::unlink(path_.c_str());
    forget_temp_file(slot_);
  }

  // Runs the body into the file and makes the bytes durable, so that the
  // rename never exposes a file whose data is still only in the page cache
  // (a device or pipe has no such cache to flush).
  void fill(const StreamBody& body) {
    FdBuf buf(fd_);
    std::ostream out(&buf);
    body(out);
    out.flush();
    if (buf.error() != 0) fail(target_, "", buf.error());
    if (!out) fail(target_, "the output stream went bad while formatting", 0);
    if (!direct_ && ::fsync(fd_) != 0) fail(target_, "", errno);
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail(target_, "", errno);
  }

  // The failure commit() would meet that can be seen beforehand: a
  // directory where the file should go (rename cannot replace it).
  void check_destination() const {
    struct stat st {};
    if (!direct_ && ::stat(dest_.c_str(), &st) == 0 && S_ISDIR(st.st_mode))
      fail(target_, "cannot rename the temporary into place: ", EISDIR);
  }

  void commit() {
    if (direct_) return;
    if (::rename(path_.c_str(), dest_.c_str()) != 0) fail(target_, "cannot rename the temporary into place: ", errno);
    path_.clear();
  }

 private:
  std::string target_;  // as the caller named it, for messages
  std::string dest_;    // where it leads
  std::string path_;    // the temporary, while it exists
  bool direct_ = false;
  int fd_ = -1;
  int slot_ = -1;
};

// Marks `end` held when its path's directory resolves into /proc: a path
// given as /dev/fd/N or /proc/self/fd/N names a descriptor's file even
// though lstat shows no hop into /proc (the kernel resolves /dev/fd and
// /proc/self on the way). A directory /proc/<this pid>/fd also names the
// descriptor.
void note_proc_entry(LinkEnd& end) {
  const std::size_t slash = end.path.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : end.path.substr(0, slash);
  char resolved[PATH_MAX];
  if (::realpath(dir.c_str(), resolved) == nullptr) return;
  const std::string real(resolved);
  if (real.compare(0, 6, "/proc/") != 0) return;
  end.held = true;
  const std::string name = end.path.substr(slash + 1);
  if (real != "/proc/" + std::to_string(::getpid()) + "/fd" || name.empty() || name.size() > 9 ||
      name.find_first_not_of("0123456789") != std::string::npos)
    return;
  end.fd = std::stoi(name);
}

}  // namespace

LinkEnd follow_links(const std::string& start) {
  LinkEnd end{start};
  for (int hop = 0; hop < 40; ++hop) {
    note_proc_entry(end);
    struct stat st {};
    if (::lstat(end.path.c_str(), &st) != 0 || !S_ISLNK(st.st_mode)) return end;
    std::string link(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 255) + 1, '\0');
    const ssize_t n = ::readlink(end.path.c_str(), link.data(), link.size());
    if (n < 0 || static_cast<std::size_t>(n) >= link.size()) return end;
    link.resize(static_cast<std::size_t>(n));
    const std::size_t slash = end.path.rfind('/');
    end.path = link[0] == '/' || slash == std::string::npos ? link : end.path.substr(0, slash + 1) + link;
    if (end.path.compare(0, 6, "/proc/") == 0) end.held = true;
  }
  struct stat st {};
  end.endless = ::lstat(end.path.c_str(), &st) == 0 && S_ISLNK(st.st_mode);
  return end;
}

void write_atomically(const std::string& path, const StreamBody& body, bool binary) {
  write_atomically(std::vector<AtomicPart>{{path, body}}, binary);
}

void write_atomically(const std::vector<AtomicPart>& parts, bool /*binary: no text mode on POSIX*/) {
  std::vector<std::unique_ptr<TempFile>> temps;
  temps.reserve(parts.size());
  for (const AtomicPart& part : parts) {
    temps.push_back(std::make_unique<TempFile>(part.path));
    temps.back()->fill(part.body);
  }
  // Every destination checked before the first rename, so that a set does
  // not fail half-way for a reason known in advance.
  for (const auto& temp : temps) temp->check_destination();
  for (auto& temp : temps) temp->commit();
}

}  // namespace tetsmooth
