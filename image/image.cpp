#include "image/image.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include <png.h>

#include "image/partial_file.hpp"

namespace umbra {

// libpng's simplified API (png_image): no setjmp, errors come back as text.

void write_png(const Image& image, const std::string& path) {
  if (image.channels != 1 && image.channels != 3) throw std::runtime_error("write_png: 1 or 3 channels only");
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = png_uint_32(image.width);
  png.height = png_uint_32(image.height);
  png.format = image.channels == 1 ? PNG_FORMAT_GRAY : PNG_FORMAT_RGB;

  PartialFile partial(path, "the image");
  const bool written = png_image_write_to_file(&png, partial.temporary_path().c_str(), 0, image.pixels.data(), 0, nullptr) != 0;
  const std::string reason = written ? "" : png.message;
  png_image_free(&png);
  if (!written) throw std::runtime_error(path + ": cannot write the image: " + reason);
  partial.commit();
}

Image read_png(const std::string& path) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&png, path.c_str()))
    throw std::runtime_error(path + ": cannot read the PNG: " + png.message);
  const bool grey = (png.format & PNG_FORMAT_FLAG_COLOR) == 0;
  png.format = grey ? PNG_FORMAT_GRAY : PNG_FORMAT_RGB;
  Image image(int(png.width), int(png.height), grey ? 1 : 3);
  if (!png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr)) {
    const std::string reason = png.message;
    png_image_free(&png);
    throw std::runtime_error(path + ": cannot read the PNG: " + reason);
  }
  return image;
}

}  // namespace umbra
