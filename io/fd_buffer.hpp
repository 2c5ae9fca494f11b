// A plain output buffer over a file descriptor (the descriptors of
// io::AtomicFile and io::Spool come from open(2) with flags std::ofstream
// cannot ask for: O_EXCL, O_NOFOLLOW, O_TMPFILE). Internal to io/.
#pragma once
#include <streambuf>
#include <vector>

namespace sreh::io::detail {

class FdBuffer : public std::streambuf {
 public:
  explicit FdBuffer(int fd);
  bool failed() const { return failed_; }
  int error() const { return error_; }
  long long written() const { return written_ + (pptr() - pbase()); }

 protected:
  int_type overflow(int_type c) override;
  int sync() override;
  // tellp(): bytes written so far (the only position this buffer knows).
  pos_type seekoff(off_type off, std::ios_base::seekdir way, std::ios_base::openmode which) override;

 private:
  int flush_all();
  int fd_;
  std::vector<char> data_;
  long long written_ = 0;
  bool failed_ = false;
  int error_ = 0;
};

} // namespace sreh::io::detail
