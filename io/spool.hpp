// A private temporary file for output that grows with run length (issue 12):
// `run --json` spools its checks, failures and moves here while the run goes
// on and copies them into the answer at the end, so memory stays flat.
//  - created in $TMPDIR (else /tmp) with O_TMPFILE | O_EXCL: the file has no
//    name at all, so nothing can be planted or followed, no other process can
//    open it, and nothing is left behind whatever ends the process (exit,
//    an exception, SIGINT / SIGTERM through io/interrupt, even SIGKILL);
//  - where the file system has no O_TMPFILE: a unique O_EXCL | O_NOFOLLOW
//    name, mode 0600, unlinked at once (the same guarantees once unlinked).
#pragma once
#include <cstddef>
#include <iosfwd>
#include <memory>
#include <string>

namespace sreh::io {

namespace detail {
class FdBuffer;
}

class Spool {
 public:
  // Throws std::runtime_error naming the temporary folder if it cannot.
  Spool();
  ~Spool();
  Spool(const Spool&) = delete;
  Spool& operator=(const Spool&) = delete;

  std::ostream& stream();      // append, buffered, binary
  unsigned long long bytes() const;
  // Copies everything written so far to `out` (the spool stays writable).
  // Throws std::runtime_error if the spool could not be written or read.
  void copy_to(std::ostream& out);
  // Reads `n` bytes at `offset` of what was written so far (a spooled
  // record read back, e.g. the report's trace rows). Throws
  // std::runtime_error if fewer than `n` bytes are there or reading fails.
  void read_at(unsigned long long offset, void* out, std::size_t n);

  static std::string folder(); // $TMPDIR if set and not empty, else /tmp

 private:
  void flush_or_throw();
  int fd_ = -1;
  std::unique_ptr<detail::FdBuffer> buffer_;
  std::unique_ptr<std::ostream> stream_;
};

} // namespace sreh::io
