#include "serve/state_dir.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <atomic>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "device_logic/device.hpp"
#include "twin/model_card.hpp"

namespace sreh::serve {
namespace {

namespace fs = std::filesystem;

std::optional<std::string> read_if_exists(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument(fmt::format("--state-dir: cannot read '{}'", path));
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Tests only (docs/serve.md, "Tests"): while the file this variable names
// exists, every state write fails as on a full disk (ENOSPC). Lets a test
// that cannot mount a small tmpfs check "durable or refused".
int injected_write_error() {
  const char* flag = std::getenv("SREH_SERVE_TEST_FAIL_STATE_WRITES_WHILE");
  return flag != nullptr && *flag != '\0' && ::access(flag, F_OK) == 0 ? ENOSPC : 0;
}

// Writes `bytes` to `path` durably: a unique temporary in the same folder
// (O_EXCL, O_NOFOLLOW), written, fsync'd, renamed onto `path`, then the
// folder fsync'd so the rename itself survives a power loss. Throws
// std::runtime_error naming `path` and the reason; the temporary is removed.
void write_durably(const std::string& path, const std::string& bytes) {
  static std::atomic<unsigned> counter{0};
  const fs::path target(path);
  const std::string temp = (target.parent_path() / fmt::format(".{}.{}-{}.tmp", target.filename().string(), ::getpid(),
                                                               counter.fetch_add(1)))
                               .string();
  const auto fail = [&](int err) {
    throw std::runtime_error(fmt::format("cannot write '{}': {}", path, std::strerror(err)));
  };
  if (const int err = injected_write_error()) fail(err);
  const int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (fd < 0) fail(errno);
  int err = 0;
  for (std::size_t done = 0; done < bytes.size() && err == 0;) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n > 0) done += static_cast<std::size_t>(n);
    else if (n < 0 && errno != EINTR) err = errno;
  }
  if (err == 0 && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err == 0 && ::rename(temp.c_str(), path.c_str()) != 0) err = errno;
  if (err != 0) {
    ::unlink(temp.c_str());
    fail(err);
  }
  const int dir = ::open(target.parent_path().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir < 0) fail(errno);
  if (::fsync(dir) != 0) err = errno;
  ::close(dir);
  if (err != 0) fail(err);
}

// Temporaries of a run killed mid-write: `.port<P>.<file>.<pid>-<n>.tmp`.
void remove_stale_temporaries(const std::string& dir) {
  static const std::regex stale(R"(^\.port\d+\.(nvm|flange\.json|ds\.json)\..*\.tmp$)");
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (std::regex_match(e.path().filename().string(), stale)) fs::remove(e.path(), ec);
}

} // namespace

bool nvm_image_sound(const std::vector<uint8_t>& image) {
  // A device refuses a bad image (magic, version, CRC, rows) and starts
  // factory-new instead, so its own image then differs from the one given.
  const Device device(default_model_card().module_model().drive, image); // the memory does not depend on the drive
  return device.save_nvm() == image;
}

StateDir::StateDir(std::string dir, int ports) : dir_(std::move(dir)) {
  std::error_code ec;
  if (!fs::is_directory(dir_, ec)) throw std::invalid_argument(fmt::format("--state-dir '{}': folder does not exist", dir_));
  const std::string lock = (fs::path(dir_) / ".lock").string();
  lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (lock_fd_ < 0)
    throw std::invalid_argument(fmt::format("--state-dir '{}': cannot open '{}': {}", dir_, lock, std::strerror(errno)));
  if (::flock(lock_fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(lock_fd_);
    lock_fd_ = -1;
    throw std::invalid_argument(fmt::format("--state-dir '{}': in use by another sreh-twin serve", dir_));
  }
  for (int p = 0; p < ports; ++p) saved_.push_back(std::make_unique<Saved>());
  remove_stale_temporaries(dir_); // ours alone now (the lock is held)
}

StateDir::~StateDir() {
  if (lock_fd_ >= 0) ::close(lock_fd_); // releases the flock
}

std::string StateDir::nvm_path(int p) const { return (fs::path(dir_) / fmt::format("port{}.nvm", p)).string(); }
std::string StateDir::flange_path(int p) const { return (fs::path(dir_) / fmt::format("port{}.flange.json", p)).string(); }
std::string StateDir::ds_path(int p) const { return (fs::path(dir_) / fmt::format("port{}.ds.json", p)).string(); }

PortState StateDir::load(int p) {
  PortState s;
  if (const auto bytes = read_if_exists(nvm_path(p))) {
    std::vector<uint8_t> image(bytes->begin(), bytes->end());
    if (!nvm_image_sound(image))
      throw std::invalid_argument(fmt::format("{}: corrupt memory image (bad header, CRC or content); "
                                              "left as it is: move it away to start port {} factory-new",
                                              nvm_path(p), p));
    s.nvm = std::move(image);
  }
  if (const auto text = read_if_exists(flange_path(p))) {
    const std::string path = flange_path(p);
    nlohmann::json j;
    try {
      j = nlohmann::json::parse(*text);
    } catch (const std::exception&) {
      throw std::invalid_argument(fmt::format("{}: corrupt (not JSON); left as it is", path));
    }
    if (!j.is_object() || !j.contains("flange_angle_deg") || !j["flange_angle_deg"].is_number() ||
        !std::isfinite(j["flange_angle_deg"].get<double>()) || std::abs(j["flange_angle_deg"].get<double>()) > 1e6)
      throw std::invalid_argument(fmt::format("{}: corrupt (expected {{\"flange_angle_deg\": number}}); left as it is", path));
    s.flange_angle_deg = j["flange_angle_deg"].get<double>();
  }
  if (const auto text = read_if_exists(ds_path(p))) {
    try {
      s.ds = ds_backup_from_json(*text, &s.ds_download_owed);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(fmt::format("{}: corrupt: {}; left as it is", ds_path(p), e.what()));
    }
  }
  Saved& saved = *saved_.at(static_cast<std::size_t>(p - 1));
  std::lock_guard lock(saved.mutex);
  saved.nvm = s.nvm;
  saved.flange_angle_deg = s.flange_angle_deg;
  return s;
}

bool StateDir::save_nvm(int p, uint64_t seq, const std::vector<uint8_t>& nvm) {
  Saved& saved = *saved_.at(static_cast<std::size_t>(p - 1));
  std::lock_guard lock(saved.mutex); // one writer per port file at a time
  if (seq < saved.seq || (saved.nvm && *saved.nvm == nvm)) return false; // a newer image is on disk already, or this one
  write_durably(nvm_path(p), std::string(nvm.begin(), nvm.end()));
  saved.nvm = nvm;
  saved.seq = seq;
  return true;
}

bool StateDir::save_flange(int p, double flange_angle_deg, bool force) {
  Saved& saved = *saved_.at(static_cast<std::size_t>(p - 1));
  std::lock_guard lock(saved.mutex);
  if (!force && saved.flange_angle_deg && std::abs(*saved.flange_angle_deg - flange_angle_deg) < kFlangeResolution_deg)
    return false;
  write_durably(flange_path(p), nlohmann::json{{"flange_angle_deg", flange_angle_deg}}.dump() + "\n");
  saved.flange_angle_deg = flange_angle_deg;
  return true;
}

bool StateDir::save_ds(int p, const DsBackup& backup, bool download_owed, uint64_t generation) {
  Saved& saved = *saved_.at(static_cast<std::size_t>(p - 1));
  std::lock_guard lock(saved.mutex);
  if (generation <= saved.ds_generation) return false;
  write_durably(ds_path(p), ds_backup_json(backup, download_owed));
  saved.ds_generation = generation;
  return true;
}

} // namespace sreh::serve
