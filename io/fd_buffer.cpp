#include "io/fd_buffer.hpp"

#include <unistd.h>

#include <cerrno>

namespace sreh::io::detail {

FdBuffer::FdBuffer(int fd) : fd_(fd), data_(1 << 16) { setp(data_.data(), data_.data() + data_.size()); }

int FdBuffer::flush_all() {
  const char* p = pbase();
  std::size_t left = static_cast<std::size_t>(pptr() - pbase());
  while (left > 0 && !failed_) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      failed_ = true;
      error_ = errno;
      break;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
    written_ += n;
  }
  setp(data_.data(), data_.data() + data_.size());
  return failed_ ? -1 : 0;
}

FdBuffer::int_type FdBuffer::overflow(int_type c) {
  if (flush_all() != 0) return traits_type::eof();
  if (!traits_type::eq_int_type(c, traits_type::eof())) {
    *pptr() = traits_type::to_char_type(c);
    pbump(1);
  }
  return traits_type::not_eof(c);
}

int FdBuffer::sync() { return flush_all(); }

FdBuffer::pos_type FdBuffer::seekoff(off_type off, std::ios_base::seekdir way, std::ios_base::openmode which) {
  if (off != 0 || way != std::ios_base::cur || !(which & std::ios_base::out)) return pos_type(off_type(-1));
  return pos_type(written());
}

} // namespace sreh::io::detail
