// Output files are written whole or not at all (interfaces.md: nothing
// half-written left behind), the one writer of the project (issue 12):
//  - the temporary file is created with O_EXCL | O_NOFOLLOW under a unique
//    name in the target's folder (never a fixed "<out>.tmp" that a planted
//    symlink could redirect), so the final rename(2) stays on one file system;
//  - rename(2) replaces the target entry itself, never a file a link points to;
//  - until commit() the temporary is removed by the destructor, also when an
//    exception (e.g. io::Interrupted after SIGINT) unwinds the stack.
#pragma once
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>

namespace sreh::io {

class AtomicFile {
 public:
  // Creates the temporary next to `path`. Throws std::runtime_error naming
  // `path` if its folder does not exist or cannot be written.
  explicit AtomicFile(std::string path);
  ~AtomicFile(); // not committed: the temporary is removed
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream();                                 // buffered, binary
  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_; }  // for writers that need a name (ffmpeg)
  // Flushes, closes and renames the temporary onto `path`. Throws
  // std::runtime_error naming `path` (the temporary is removed then).
  void commit();

 private:
  struct Buffer;
  std::string path_;
  std::string temp_;
  int fd_ = -1;
  std::unique_ptr<Buffer> buffer_;
  std::unique_ptr<std::ostream> stream_;
  bool committed_ = false;
};

// write_file_atomic(path, [](std::ostream& out) { ... }): the common case.
void write_file_atomic(const std::string& path, const std::function<void(std::ostream&)>& write);

// Creates the output folder `path` if it does not exist (one level: its
// parent must exist, issue 12); a trailing '/' is fine. Throws
// std::runtime_error if it cannot, or if `path` is not a folder.
void make_output_folder(const std::string& path);

// A folder filled whole or not at all (PNG frames): a unique temporary folder
// (mkdtemp) next to `path`, renamed onto `path` by commit(); `path` may exist
// only as an empty folder. The destructor removes an uncommitted one.
class AtomicDir {
 public:
  explicit AtomicDir(std::string path);
  ~AtomicDir();
  AtomicDir(const AtomicDir&) = delete;
  AtomicDir& operator=(const AtomicDir&) = delete;
  const std::string& temp_path() const { return temp_; }
  void commit();

 private:
  std::string path_;
  std::string temp_;
  bool committed_ = false;
};

} // namespace sreh::io
