#include "serve/state_dir.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "device_logic/device.hpp"
#include "io/atomic_file.hpp"
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
      s.ds = ds_backup_from_json(*text);
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

void StateDir::save(int p, const std::vector<uint8_t>& nvm, double flange_angle_deg) {
  Saved& saved = *saved_.at(static_cast<std::size_t>(p - 1));
  std::lock_guard lock(saved.mutex); // one writer per port file at a time
  if (!saved.nvm || *saved.nvm != nvm) {
    io::write_file_atomic(nvm_path(p), [&](std::ostream& f) {
      f.write(reinterpret_cast<const char*>(nvm.data()), static_cast<std::streamsize>(nvm.size()));
    });
    saved.nvm = nvm;
  }
  if (!saved.flange_angle_deg || std::abs(*saved.flange_angle_deg - flange_angle_deg) >= kFlangeResolution_deg) {
    io::write_file_atomic(flange_path(p), [&](std::ostream& f) {
      f << nlohmann::json{{"flange_angle_deg", flange_angle_deg}}.dump() << "\n";
    });
    saved.flange_angle_deg = flange_angle_deg;
  }
}

void StateDir::save_ds(int p, const DsBackup& backup, uint64_t generation) {
  Saved& saved = *saved_.at(static_cast<std::size_t>(p - 1));
  std::lock_guard lock(saved.mutex);
  if (saved.ds_generation == generation) return;
  io::write_file_atomic(ds_path(p), [&](std::ostream& f) { f << ds_backup_json(backup); });
  saved.ds_generation = generation;
}

} // namespace sreh::serve
