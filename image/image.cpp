#include "image/image.hpp"

#include <cstring>
#include <stdexcept>

#include <png.h>

namespace umbra {

// libpng's simplified API (png_image): no setjmp, errors come back as text.

unsigned png_format_of(int channels) {
  return channels == 1 ? PNG_FORMAT_GRAY : channels == 4 ? PNG_FORMAT_RGBA : PNG_FORMAT_RGB;
}

Image read_png(const std::string& path) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str()))
    throw std::runtime_error(path + ": cannot read the PNG: " + png.message);
  const bool grey = (png.format & PNG_FORMAT_FLAG_COLOR) == 0, alpha = (png.format & PNG_FORMAT_FLAG_ALPHA) != 0;
  const int channels = grey ? 1 : alpha ? 4 : 3;  // grey with alpha: the grey alone
  png.format = png_format_of(channels);
  Image image(int(png.width), int(png.height), channels);
  if (!png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr)) {
    const std::string reason = png.message;
    png_image_free(&png);
    throw std::runtime_error(path + ": cannot read the PNG: " + reason);
  }
  return image;
}

}  // namespace umbra
