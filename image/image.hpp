#pragma once
// Images in memory, row 0 at the top, and writing them as PNG.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace umbra {

struct Image {
  int width = 0;
  int height = 0;
  int channels = 0;  // 1: grey, 3: RGB, 4: RGBA (straight alpha)
  std::vector<uint8_t> pixels;  // row-major, row 0 at the top

  Image() = default;
  Image(int w, int h, int c, uint8_t fill = 0) : width(w), height(h), channels(c), pixels(size_t(w) * h * c, fill) {}
  uint8_t& at(int x, int y, int c = 0) { return pixels[(size_t(y) * width + x) * channels + c]; }
  uint8_t at(int x, int y, int c = 0) const { return pixels[(size_t(y) * width + x) * channels + c]; }
};

// A colour channel in [0, 1] (clamped) as a byte, rounded to the nearest
// level: the one conversion the GL image and the ray-cast one share.
inline uint8_t channel_byte(double c) { return uint8_t(std::lround(std::clamp(c, 0.0, 1.0) * 255.0)); }

// Shadow mask values (see `umbra render --mask`).
constexpr uint8_t kMaskNoSurface = 128;
constexpr uint8_t kMaskLit = 255;
constexpr uint8_t kMaskUnlit = 0;

// Writes `image` as PNG to `path`, whatever its name, through a temporary
// file renamed into place, so a failure never leaves a partial file
// (picture_file.cpp, which writes every picture). Throws std::runtime_error.
void write_png(const Image& image, const std::string& path);

// libpng's simplified format for an image of `channels` (1, 3 or 4).
unsigned png_format_of(int channels);

// Reads an 8-bit grey, RGB or RGBA PNG (used by tests). Throws std::runtime_error.
Image read_png(const std::string& path);

}  // namespace umbra
