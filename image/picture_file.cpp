#include "image/picture_file.hpp"

#include <algorithm>
#include <cctype>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <jpeglib.h>
#include <png.h>

#include "image/partial_file.hpp"
#include "mesh/file_extension.hpp"
#include "mesh/word_list.hpp"

namespace umbra {

const PictureFormatRow kPictureFormats[2] = {
    {PictureFormat::kPng, "PNG", {".png", nullptr, nullptr}, true},
    {PictureFormat::kJpeg, "JPEG", {".jpg", ".jpeg", nullptr}, false},
};

namespace {

// libjpeg reports an error by calling error_exit, which must not return:
// it jumps back to where the write began, with the library's message.
struct JpegErrors {
  jpeg_error_mgr manager;
  std::jmp_buf back;
  char message[JMSG_LENGTH_MAX];
};

void jump_back(j_common_ptr jpeg) {
  JpegErrors* errors = reinterpret_cast<JpegErrors*>(jpeg->err);
  (*jpeg->err->format_message)(jpeg, errors->message);
  std::longjmp(errors->back, 1);
}

// Baseline JPEG (libjpeg-turbo), 4:2:0 as its default; "" or why not.
std::string write_jpeg(const Image& image, std::FILE* file, int quality) {
  jpeg_compress_struct jpeg;
  JpegErrors errors;
  jpeg.err = jpeg_std_error(&errors.manager);
  errors.manager.error_exit = jump_back;
  if (setjmp(errors.back)) {
    jpeg_destroy_compress(&jpeg);
    return errors.message;
  }
  jpeg_create_compress(&jpeg);
  jpeg_stdio_dest(&jpeg, file);
  jpeg.image_width = JDIMENSION(image.width);
  jpeg.image_height = JDIMENSION(image.height);
  jpeg.input_components = image.channels;
  jpeg.in_color_space = image.channels == 1 ? JCS_GRAYSCALE : JCS_RGB;
  jpeg_set_defaults(&jpeg);
  jpeg_set_quality(&jpeg, quality, TRUE);
  jpeg_start_compress(&jpeg, TRUE);
  const size_t stride = size_t(image.width) * size_t(image.channels);
  while (jpeg.next_scanline < jpeg.image_height) {
    JSAMPROW row = const_cast<JSAMPROW>(image.pixels.data() + jpeg.next_scanline * stride);
    jpeg_write_scanlines(&jpeg, &row, 1);
  }
  jpeg_finish_compress(&jpeg);
  jpeg_destroy_compress(&jpeg);
  return "";
}

// PNG (libpng's simplified API) to an open file; "" or why not.
std::string write_png_to(const Image& image, std::FILE* file) {
  png_image png;
  std::memset(&png, 0, sizeof png);
  png.version = PNG_IMAGE_VERSION;
  png.width = png_uint_32(image.width);
  png.height = png_uint_32(image.height);
  png.format = png_format_of(image.channels);
  const bool written = png_image_write_to_stdio(&png, file, 0, image.pixels.data(), 0, nullptr) != 0;
  const std::string reason = written ? "" : png.message;
  png_image_free(&png);
  return reason;
}

std::string write_in(PictureFormat format, const Image& image, std::FILE* file, const PictureOptions& options) {
  return format == PictureFormat::kJpeg ? write_jpeg(image, file, options.jpeg_quality) : write_png_to(image, file);
}

}  // namespace

const PictureFormatRow& format_row(PictureFormat format) {
  for (const PictureFormatRow& row : kPictureFormats)
    if (row.format == format) return row;
  throw std::logic_error("a picture format outside the table");
}

bool picture_format_keeps_alpha(PictureFormat format) { return format_row(format).alpha; }

std::optional<PictureFormat> picture_format_of(const std::string& path) {
  std::error_code ec;
  const std::filesystem::file_status there = std::filesystem::status(path, ec);
  if (path == "-" || std::filesystem::is_fifo(there) || std::filesystem::is_character_file(there)) return PictureFormat::kPng;
  const std::string extension = lowercase_extension(path);
  for (const PictureFormatRow& row : kPictureFormats)
    for (const char* known : row.extensions)
      if (known && extension == known) return row.format;
  return std::nullopt;
}

std::string picture_extensions() {
  std::vector<std::string> all;
  for (const PictureFormatRow& row : kPictureFormats)
    for (const char* known : row.extensions)
      if (known) all.push_back(known);
  return word_list(all);
}

namespace {

void require_writable(PictureFormat format, const Image& image, const std::string& path) {
  if (image.channels != 1 && image.channels != 3 && image.channels != 4)
    throw std::runtime_error(path + ": cannot write an image of " + std::to_string(image.channels) + " channels");
  if (image.channels == 4 && !picture_format_keeps_alpha(format))
    throw std::runtime_error(path + ": a " + std::string(format_row(format).name) + " picture has no alpha channel for a transparent background");
}

// `image` in `format` into `file_path`, the temporary file of `path`.
void write_file(PictureFormat format, const Image& image, const std::string& path, const std::string& file_path,
                const PictureOptions& options) {
  require_writable(format, image, path);
  std::FILE* file = std::fopen(file_path.c_str(), "wb");
  if (!file) throw std::runtime_error(path + ": cannot write the image: " + std::strerror(errno));
  std::string reason = write_in(format, image, file, options);
  if (std::fclose(file) != 0 && reason.empty()) reason = std::strerror(errno);
  if (!reason.empty()) throw std::runtime_error(path + ": cannot write the image: " + reason);
}

// `image` in `format` to `path`: "-" for standard output, else through a
// temporary file renamed into place (PartialFile).
void write_as(PictureFormat format, const Image& image, const std::string& path, const PictureOptions& options) {
  if (path == "-") {
    require_writable(format, image, path);
    const std::string reason = write_in(format, image, stdout, options);
    if (!reason.empty() || std::fflush(stdout) != 0)
      throw std::runtime_error("cannot write the image to standard output: " + (reason.empty() ? std::strerror(errno) : reason));
    return;
  }
  PartialFile partial(path, "the image");
  write_file(format, image, path, partial.temporary_path(), options);
  partial.commit();
}

PictureFormat format_for(const std::string& path) {
  const std::optional<PictureFormat> format = picture_format_of(path);
  if (!format) throw std::runtime_error(path + ": umbra writes pictures as " + picture_extensions() + " only");
  return *format;
}

}  // namespace

void write_picture(const Image& image, const std::string& path, const PictureOptions& options) {
  write_as(format_for(path), image, path, options);
}

void write_picture_into(const Image& image, const PartialFile& into, const PictureOptions& options) {
  write_file(format_for(into.path()), image, into.path(), into.temporary_path(), options);
}

void write_png(const Image& image, const std::string& path) { write_as(PictureFormat::kPng, image, path, {}); }

}  // namespace umbra
