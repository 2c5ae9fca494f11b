#include "io/spool.hpp"

#include "io/fd_buffer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <ostream>
#include <stdexcept>
#include <vector>

namespace sreh::io {
namespace {

std::runtime_error failure(const std::string& what, int err) {
  return std::runtime_error(what + " in '" + Spool::folder() + "' (set TMPDIR to another folder): " +
                            std::strerror(err));
}

int open_anonymous(const std::string& dir) {
#ifdef O_TMPFILE
  // O_EXCL: the file can never be given a name (linkat) afterwards.
  const int fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_EXCL | O_CLOEXEC, 0600);
  if (fd >= 0 || (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL)) return fd;
#endif
  // A file system without O_TMPFILE: a unique name, unlinked at once.
  std::string pattern = dir + "/.sreh-spool-XXXXXX";
  const int named = ::mkostemp(pattern.data(), O_CLOEXEC);
  if (named >= 0) ::unlink(pattern.c_str());
  return named;
}

} // namespace

std::string Spool::folder() {
  const char* t = std::getenv("TMPDIR");
  return t && *t ? std::string(t) : std::string("/tmp");
}

Spool::Spool() {
  fd_ = open_anonymous(folder());
  if (fd_ < 0) throw failure("cannot create a temporary file", errno);
  buffer_ = std::make_unique<detail::FdBuffer>(fd_);
  stream_ = std::make_unique<std::ostream>(buffer_.get());
}

Spool::~Spool() {
  stream_.reset();
  buffer_.reset();
  if (fd_ >= 0) ::close(fd_);
}

std::ostream& Spool::stream() { return *stream_; }

unsigned long long Spool::bytes() const { return static_cast<unsigned long long>(buffer_->written()); }

void Spool::flush_or_throw() {
  stream_->flush();
  if (buffer_->failed() || !*stream_) {
    throw failure("cannot write a temporary file", buffer_->failed() ? buffer_->error() : EIO);
  }
}

void Spool::copy_to(std::ostream& out) {
  flush_or_throw();
  std::vector<char> chunk(1 << 16);
  off_t at = 0;
  for (;;) {
    const ssize_t n = ::pread(fd_, chunk.data(), chunk.size(), at);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw failure("cannot read a temporary file", errno);
    if (n == 0) break;
    out.write(chunk.data(), n);
    at += n;
  }
}

void Spool::read_at(unsigned long long offset, void* out, std::size_t n) {
  flush_or_throw();
  auto* to = static_cast<char*>(out);
  std::size_t done = 0;
  while (done < n) {
    const ssize_t got = ::pread(fd_, to + done, n - done, static_cast<off_t>(offset + done));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw failure("cannot read a temporary file", errno);
    if (got == 0) throw std::runtime_error("read past the end of a temporary file");
    done += static_cast<std::size_t>(got);
  }
}

} // namespace sreh::io
