#include "io/atomic_file.hpp"

#include "io/fd_buffer.hpp"

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

struct AtomicFile::Buffer : detail::FdBuffer {
  using FdBuffer::FdBuffer;
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
  int err = buffer_->failed() ? buffer_->error() : 0;
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
