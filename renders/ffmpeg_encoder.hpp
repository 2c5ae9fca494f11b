// H.264 MP4 (or VP8 WebM, GIF) by piping raw RGB frames into the `ffmpeg` program (issue 7).
// Why the program and not libav*: the command line is stable across ffmpeg
// releases (the libav* API is not), the encoder runs in its own process and
// so on the other core for free, and a crash or error there cannot take the
// twin down (docs/assumptions/renders.md A-RENDERS-4).
#pragma once
#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace sreh {

// The container and codec, chosen by the file's extension (issue 16).
enum class VideoContainer : uint8_t {
  Mp4,  // H.264, yuv420p: plays everywhere (A-RENDERS-4)
  WebM, // VP8: browsers without H.264
  Gif,  // palette GIF for a README; large, so keep it short and small
};
// ".mp4", ".webm", ".gif" (any case); nullopt otherwise.
std::optional<VideoContainer> container_for(const std::filesystem::path& path);
const char* container_name(VideoContainer c);

struct EncoderOptions {
  VideoContainer container = VideoContainer::Mp4;
  int width_px = 1280;
  int height_px = 720;
  double fps = 30.0;
  std::string x264_preset = "veryfast"; // A-RENDERS-5
  int crf = 20;                     // constant quality; lower is better and bigger
  bool bottom_up = false;           // rows arrive as OpenGL reads them: ffmpeg flips
};

class FfmpegEncoder {
 public:
  // Starts `ffmpeg` writing the container to `out_path` (exactly that path; the
  // caller does the tmp-then-rename). ffmpeg's messages go to
  // `out_path`.log, removed after success. Throws std::runtime_error if
  // ffmpeg cannot be started.
  FfmpegEncoder(const std::filesystem::path& out_path, const EncoderOptions& options);
  ~FfmpegEncoder(); // unfinished: closes the pipe and reaps ffmpeg, removes the log
  FfmpegEncoder(const FfmpegEncoder&) = delete;
  FfmpegEncoder& operator=(const FfmpegEncoder&) = delete;

  // One frame of width*height*3 bytes. Throws std::runtime_error (with
  // ffmpeg's last message) if ffmpeg has gone. Never raises SIGPIPE.
  void write_frame(const uint8_t* rgb);
  // Closes the input and waits for ffmpeg; throws std::runtime_error unless
  // it exited with status 0.
  void finish();
  uint64_t frames() const { return frames_; }

 private:
  std::string failure(const std::string& what) const;
  void close_and_wait(int* status);

  std::filesystem::path out_path_;
  std::filesystem::path log_path_;
  std::size_t frame_bytes_ = 0;
  int fd_ = -1;
  pid_t pid_ = -1;
  uint64_t frames_ = 0;
};

} // namespace sreh
