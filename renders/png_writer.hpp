// PNG frames with libpng (design/mujoco.md: fastest of the tried encoders).
#pragma once
#include <cstdint>
#include <filesystem>

namespace sreh {

// Writes an 8-bit RGB image to `path`; rows top-down, or bottom-up as
// OpenGL reads them when `bottom_up`. zlib level 1..9 trades size for time
// (A-RENDERS-6). Throws std::runtime_error on failure.
void write_png(const std::filesystem::path& path, const uint8_t* rgb, int width, int height, bool bottom_up = false,
               int zlib_level = 3);

} // namespace sreh
