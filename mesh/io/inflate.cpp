#include "mesh/io/inflate.hpp"

#include <lzma.h>
#include <zlib.h>

#include <algorithm>
#include <climits>

namespace tetsmooth {
namespace {

// The decompressed bytes of one stream, appended to a vector in steps of at
// most kStep bytes as the decoder yields them. It offers room for one byte
// more than `size` in all, so that a stream yielding too much is caught
// rather than cut short at `size`.
class Sink {
 public:
  static constexpr std::size_t kStep = std::size_t{1} << 16;

  Sink(std::vector<unsigned char>& out, std::size_t size) : out_(out), start_(out.size()), size_(size) {}

  // Room for the decoder's next output; `room` is set to its size (>= 1).
  unsigned char* room(std::size_t& room) {
    const std::size_t left = size_ - produced_;  // produced_ <= size_ until overflowed()
    room = left < kStep ? left + 1 : kStep;
    out_.resize(start_ + produced_ + room);
    return out_.data() + start_ + produced_;
  }
  // The decoder wrote `n` bytes of the room last offered.
  void wrote(std::size_t n) {
    produced_ += n;
    out_.resize(start_ + produced_);
  }
  bool overflowed() const { return produced_ > size_; }

  // "" when exactly `size` bytes came out.
  std::string check_size() const {
    if (produced_ == size_) return "";
    return "decompresses to " + std::to_string(produced_) + " bytes, the header says " + std::to_string(size_);
  }
  std::string too_much() const {
    return "decompresses to more than the " + std::to_string(size_) + " bytes the header says";
  }

 private:
  std::vector<unsigned char>& out_;
  std::size_t start_, size_;
  std::size_t produced_ = 0;
};

std::string leftover(std::size_t bytes, const char* format) {
  if (bytes == 0) return "";
  return std::to_string(bytes) + (bytes == 1 ? " byte follows" : " bytes follow") + " the end of the " + format +
         " stream";
}

std::string inflate_zlib(const unsigned char* in, std::size_t in_size, Sink& sink) {
  z_stream z{};
  if (inflateInit(&z) != Z_OK) return "zlib cannot start: out of memory";
  std::size_t fed = 0;  // zlib counts its input in 32-bit pieces
  int rc = Z_OK;
  bool overflowed = false;
  while (rc == Z_OK && !overflowed) {
    if (z.avail_in == 0 && fed < in_size) {
      const std::size_t piece = std::min<std::size_t>(in_size - fed, UINT_MAX);
      z.next_in = const_cast<unsigned char*>(in + fed);  // zlib's API is not const, it only reads
      z.avail_in = static_cast<uInt>(piece);
      fed += piece;
    }
    std::size_t room = 0;
    z.next_out = sink.room(room);
    z.avail_out = static_cast<uInt>(room);
    rc = inflate(&z, Z_NO_FLUSH);
    sink.wrote(room - z.avail_out);
    overflowed = sink.overflowed();
  }
  const std::string message = z.msg ? z.msg : "";
  const std::size_t unread = in_size - fed + z.avail_in;
  inflateEnd(&z);
  if (overflowed) return sink.too_much();
  switch (rc) {
    case Z_STREAM_END:
      break;
    case Z_BUF_ERROR:  // there is always output room, so the input ran out
      return "truncated: the zlib stream ends early";
    case Z_MEM_ERROR:
      return "zlib ran out of memory";
    default:
      return "corrupt zlib data" + (message.empty() ? std::string() : " (" + message + ")");
  }
  if (std::string s = sink.check_size(); !s.empty()) return s;
  return leftover(unread, "zlib");
}

std::string xz_error(lzma_ret rc) {
  switch (rc) {
    case LZMA_BUF_ERROR:  // with LZMA_FINISH and output room: the input ran out
      return "truncated: the xz stream ends early";
    case LZMA_FORMAT_ERROR:
      return "not an xz stream";
    case LZMA_OPTIONS_ERROR:
      return "xz options that this liblzma does not support";
    case LZMA_MEMLIMIT_ERROR:
      return "the xz stream needs more than " + std::to_string(kXzMemoryLimit >> 20) + " MiB to decompress";
    case LZMA_MEM_ERROR:
      return "liblzma ran out of memory";
    default:
      return "corrupt xz data";
  }
}

std::string inflate_xz(const unsigned char* in, std::size_t in_size, Sink& sink) {
  lzma_stream s = LZMA_STREAM_INIT;
  if (lzma_stream_decoder(&s, kXzMemoryLimit, 0) != LZMA_OK) return "liblzma cannot start: out of memory";
  s.next_in = in;
  s.avail_in = in_size;
  lzma_ret rc = LZMA_OK;
  bool overflowed = false;
  while (rc == LZMA_OK && !overflowed) {
    std::size_t room = 0;
    s.next_out = sink.room(room);
    s.avail_out = room;
    rc = lzma_code(&s, LZMA_FINISH);
    sink.wrote(room - s.avail_out);
    overflowed = sink.overflowed();
  }
  const std::size_t unread = s.avail_in;
  lzma_end(&s);
  if (overflowed) return sink.too_much();
  if (rc != LZMA_STREAM_END) return xz_error(rc);
  if (std::string m = sink.check_size(); !m.empty()) return m;
  return leftover(unread, "xz");
}

}  // namespace

std::string inflate_stream(Codec codec, const unsigned char* in, std::size_t in_size, std::size_t size,
                           std::vector<unsigned char>& out) {
  Sink sink(out, size);
  return codec == Codec::Zlib ? inflate_zlib(in, in_size, sink) : inflate_xz(in, in_size, sink);
}

}  // namespace tetsmooth
