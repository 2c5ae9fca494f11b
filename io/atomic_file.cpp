#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <stdexcept>
#include <streambuf>
#include <vector>

namespace sreh::io {
namespace {

namespace fs = std::filesystem;

std::string why(int err) { return std::strerror(err); }

// "<folder>/.<name>.<pid>-<n>" : hidden, unique per process and call; O_EXCL
// makes a clash (or a planted file or link) fail instead of being followed.
std::string temp_name(const std::string& path, unsigned n) {
  fs::path p(path);
  std::string name = p.filename().string();
  if (name.empty()) name = "out";
  const fs::path dir = p.parent_path();
  const std::string base = "." + name + "." + std::to_string(::getpid()) + "-" + std::to_string(n) + ".tmp";
  return (dir.empty() ? fs::path(base) : dir / base).string();
}

unsigned next_serial() {
  static std::atomic<unsigned> serial{0};
  return serial++;
}

} // namespace

// A plain output buffer over a file descriptor (the fd comes from open(2)
// with O_EXCL, which std::ofstream cannot do).
struct AtomicFile::Buffer : std::streambuf {
  explicit Buffer(int fd) : fd_(fd), data_(1 << 16) { setp(data_.data(), data_.data() + data_.size()); }
  bool failed = false;
  int error = 0;
  int flush_all() {
    const char* p = pbase();
    std::size_t left = static_cast<std::size_t>(pptr() - pbase());
    while (left > 0 && !failed) {
      const ssize_t n = ::write(fd_, p, left);
      if (n < 0) {
        if (errno == EINTR) continue;
        failed = true;
        error = errno;
        break;
      }
      p += n;
      left -= static_cast<std::size_t>(n);
      written_ += n;
    }
    setp(data_.data(), data_.data() + data_.size());
    return failed ? -1 : 0;
  }
  int_type overflow(int_type c) override {
    if (flush_all() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override { return flush_all(); }
  // tellp(): bytes written so far (the only position this buffer knows).
  pos_type seekoff(off_type off, std::ios_base::seekdir way, std::ios_base::openmode which) override {
    if (off != 0 || way != std::ios_base::cur || !(which & std::ios_base::out)) return pos_type(off_type(-1));
    return pos_type(written_ + (pptr() - pbase()));
  }

 private:
  off_type written_ = 0;
  int fd_;
  std::vector<char> data_;
};

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    temp_ = temp_name(path_, next_serial());
    fd_ = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ >= 0 || errno != EEXIST) break;
  }
  if (fd_ < 0) {
    const int err = errno;
    temp_.clear();
    throw std::runtime_error("cannot write '" + path_ + "': " + why(err));
  }
  buffer_ = std::make_unique<Buffer>(fd_);
  stream_ = std::make_unique<std::ostream>(buffer_.get());
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temp_.empty()) ::unlink(temp_.c_str());
}

std::ostream& AtomicFile::stream() { return *stream_; }

void AtomicFile::commit() {
  if (committed_) throw std::logic_error("AtomicFile: commit twice");
  stream_->flush();
  int err = buffer_->failed ? buffer_->error : 0;
  if (err == 0 && !*stream_) err = EIO;
  if (::close(fd_) != 0 && err == 0) err = errno;
  fd_ = -1;
  if (err == 0 && ::rename(temp_.c_str(), path_.c_str()) != 0) err = errno;
  if (err != 0) {
    ::unlink(temp_.c_str());
    temp_.clear();
    throw std::runtime_error("cannot write '" + path_ + "': " + why(err));
  }
  committed_ = true;
}

void write_file_atomic(const std::string& path, const std::function<void(std::ostream&)>& write) {
  AtomicFile file(path);
  write(file.stream());
  file.commit();
}

void make_output_folder(const std::string& path) {
  if (::mkdir(path.c_str(), 0777) != 0 && errno != EEXIST) {
    throw std::runtime_error("cannot create the folder '" + path + "': " + why(errno));
  }
  std::error_code ec;
  if (!fs::is_directory(path, ec)) throw std::runtime_error("'" + path + "' is not a folder");
}

AtomicDir::AtomicDir(std::string path) : path_(std::move(path)) {
  // A trailing slash names the same folder.
  while (path_.size() > 1 && path_.back() == '/') path_.pop_back();
  std::string pattern = temp_name(path_, next_serial()) + "XXXXXX";
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw std::runtime_error("cannot create '" + path_ + "': " + why(errno));
  }
  temp_ = pattern;
  // mkdtemp makes it 0700; the frames folder gets the usual mode.
  const mode_t mask = ::umask(0);
  ::umask(mask);
  ::chmod(temp_.c_str(), 0777 & ~mask);
}

AtomicDir::~AtomicDir() {
  if (committed_ || temp_.empty()) return;
  std::error_code ignored;
  fs::remove_all(temp_, ignored);
}

void AtomicDir::commit() {
  if (committed_) throw std::logic_error("AtomicDir: commit twice");
  // rename(2) replaces an empty folder; a non-empty one or a file makes it fail.
  if (::rename(temp_.c_str(), path_.c_str()) != 0) {
    throw std::runtime_error("cannot create '" + path_ + "': " + why(errno));
  }
  committed_ = true;
}

} // namespace sreh::io
