#include "renders/ffmpeg_encoder.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <ctime>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <vector>

#include <fmt/format.h>

extern char** environ;

namespace sreh {

std::optional<VideoContainer> container_for(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".mp4") return VideoContainer::Mp4;
  if (ext == ".webm") return VideoContainer::WebM;
  if (ext == ".gif") return VideoContainer::Gif;
  return std::nullopt;
}

const char* container_name(VideoContainer c) {
  switch (c) {
    case VideoContainer::Mp4: return "MP4 (H.264)";
    case VideoContainer::WebM: return "WebM (VP8)";
    case VideoContainer::Gif: return "GIF";
  }
  return "";
}

namespace {

// Writes all of `data` to a pipe; a dead reader gives EPIPE instead of a
// process-killing SIGPIPE (blocked for this thread, pending one consumed).
bool write_all_no_sigpipe(int fd, const uint8_t* data, std::size_t size) {
  sigset_t pipe_set, old_set;
  sigemptyset(&pipe_set);
  sigaddset(&pipe_set, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_set, &old_set);
  bool ok = true;
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      ok = false;
      break;
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  if (!ok && errno == EPIPE) {
    const timespec zero{0, 0};
    while (sigtimedwait(&pipe_set, nullptr, &zero) == SIGPIPE) {
    }
  }
  pthread_sigmask(SIG_SETMASK, &old_set, nullptr);
  return ok;
}

} // namespace

FfmpegEncoder::FfmpegEncoder(const std::filesystem::path& out_path, const EncoderOptions& o)
    : out_path_(out_path), log_path_(out_path.string() + ".log") {
  if (o.width_px <= 0 || o.height_px <= 0 || o.width_px % 2 || o.height_px % 2) {
    throw std::invalid_argument("video size must be positive and even (yuv420p)");
  }
  if (!(o.fps > 0)) throw std::invalid_argument("video frame rate must be positive");
  frame_bytes_ = static_cast<std::size_t>(o.width_px) * static_cast<std::size_t>(o.height_px) * 3;

  std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-nostats", "-loglevel", "error",
                                   "-f", "rawvideo", "-pix_fmt", "rgb24",
                                   "-s", fmt::format("{}x{}", o.width_px, o.height_px),
                                   "-framerate", fmt::format("{}", o.fps), "-i", "pipe:0"};
  switch (o.container) {
    case VideoContainer::Mp4:
      if (o.bottom_up) args.insert(args.end(), {"-vf", "vflip"});
      args.insert(args.end(), {"-c:v", "libx264", "-preset", o.x264_preset, "-crf", std::to_string(o.crf),
                               "-pix_fmt", "yuv420p", "-movflags", "+faststart", "-f", "mp4"});
      break;
    case VideoContainer::WebM:
      // VP8 at constant quality; realtime deadline keeps it near H.264's speed (A-RENDERS-4).
      if (o.bottom_up) args.insert(args.end(), {"-vf", "vflip"});
      args.insert(args.end(), {"-c:v", "libvpx", "-deadline", "realtime", "-cpu-used", "8", "-b:v", "0", "-crf",
                               std::to_string(std::clamp(o.crf - 10, 4, 63)), "-pix_fmt", "yuv420p", "-f", "webm"});
      break;
    case VideoContainer::Gif:
      // One palette per video for clean colours (two passes inside ffmpeg).
      args.insert(args.end(), {"-vf", std::string(o.bottom_up ? "vflip," : "") +
                                           "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=bayer",
                               "-f", "gif"});
      break;
  }
  args.insert(args.end(), {"-y", out_path.string()});
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);

  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[0], 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  // The log sits next to the (uniquely named) output: never follow a link (issue 12).
  posix_spawn_file_actions_addopen(&actions, 2, log_path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW, 0644);
  const int rc = posix_spawnp(&pid_, "ffmpeg", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[0]);
  if (rc != 0) {
    ::close(fds[1]);
    pid_ = -1;
    std::error_code ignored;
    std::filesystem::remove(log_path_, ignored);
    throw std::runtime_error(fmt::format("cannot start ffmpeg (is it installed and on PATH?): {}", std::strerror(rc)));
  }
  fd_ = fds[1];
}

FfmpegEncoder::~FfmpegEncoder() {
  if (pid_ >= 0) {
    int status = 0;
    close_and_wait(&status);
  }
  std::error_code ignored;
  std::filesystem::remove(log_path_, ignored);
}

std::string FfmpegEncoder::failure(const std::string& what) const {
  std::ifstream log(log_path_);
  std::string line, last;
  while (std::getline(log, line))
    if (!line.empty()) last = line;
  return fmt::format("ffmpeg writing {}: {}{}{}", out_path_.string(), what, last.empty() ? "" : ": ", last);
}

void FfmpegEncoder::close_and_wait(int* status) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  while (waitpid(pid_, status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
}

void FfmpegEncoder::write_frame(const uint8_t* rgb) {
  if (fd_ < 0) throw std::logic_error("FfmpegEncoder: write after finish");
  if (!write_all_no_sigpipe(fd_, rgb, frame_bytes_)) {
    const int err = errno;
    int status = 0;
    close_and_wait(&status);
    throw std::runtime_error(failure(err == EPIPE ? "ffmpeg stopped reading" : std::strerror(err)));
  }
  ++frames_;
}

void FfmpegEncoder::finish() {
  if (pid_ < 0) throw std::logic_error("FfmpegEncoder: finish twice");
  int status = 0;
  close_and_wait(&status);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error(failure(WIFEXITED(status) ? fmt::format("exit status {}", WEXITSTATUS(status))
                                                       : std::string("killed by a signal")));
  }
  std::error_code ignored;
  std::filesystem::remove(log_path_, ignored);
}

} // namespace sreh
