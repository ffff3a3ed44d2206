#include "mesh/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <memory>
#include <streambuf>

#include "mesh/errors.hpp"

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

// A temporary file beside its target, removed unless commit() renamed it.
class TempFile {
 public:
  explicit TempFile(std::string target) : target_(std::move(target)) {
    static std::atomic<unsigned> counter{0};
    const std::size_t slash = target_.rfind('/');
    const std::string dir = slash == std::string::npos ? "" : target_.substr(0, slash + 1);
    const std::string base = slash == std::string::npos ? target_ : target_.substr(slash + 1);
    // O_EXCL with a fresh name per attempt: concurrent writers of the same
    // target never share a temporary. Mode 0666 lets the umask decide, as for
    // any newly created file.
    for (int attempt = 0; attempt < 100; ++attempt) {
      path_ = dir + "." + base + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
      fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (fd_ >= 0) return;
      if (errno != EEXIST) break;
    }
    const int err = errno;
    path_.clear();
    fail(target_, "cannot create a temporary file beside it: ", err);
  }
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  ~TempFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!path_.empty()) ::unlink(path_.c_str());
  }

  // Runs the body into the file and makes the bytes durable, so that the
  // rename never exposes a file whose data is still only in the page cache.
  void fill(const StreamBody& body) {
    FdBuf buf(fd_);
    std::ostream out(&buf);
    body(out);
    out.flush();
    if (buf.error() != 0) fail(target_, "", buf.error());
    if (!out) fail(target_, "the output stream went bad while formatting", 0);
    if (::fsync(fd_) != 0) fail(target_, "", errno);
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail(target_, "", errno);
  }

  void commit() {
    if (::rename(path_.c_str(), target_.c_str()) != 0) fail(target_, "cannot rename the temporary into place: ", errno);
    path_.clear();
  }

 private:
  std::string target_;
  std::string path_;
  int fd_ = -1;
};

}  // namespace

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
  for (auto& temp : temps) temp->commit();
}

}  // namespace tetsmooth
