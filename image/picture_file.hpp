#pragma once
// Writing a picture in the format its name asks for. The formats live in
// one table (kPictureFormats); "-" names standard output, which gets PNG.

#include <optional>
#include <string>

#include "image/image.hpp"
#include "image/partial_file.hpp"

namespace umbra {

enum class PictureFormat { kPng, kJpeg };

struct PictureFormatRow {
  PictureFormat format;
  const char* name;              // "PNG"
  const char* extensions[3];     // lower case, with the dot; unused ones null
  bool alpha;                    // keeps an alpha channel (a transparent background)
};
extern const PictureFormatRow kPictureFormats[2];
const PictureFormatRow& format_row(PictureFormat format);
bool picture_format_keeps_alpha(PictureFormat format);

// The format `path`'s extension names (case aside); PNG for "-", standard
// output, and for a FIFO or a device such as /dev/null, whatever their names;
// none for any other extension, or none at all.
std::optional<PictureFormat> picture_format_of(const std::string& path);
// ".png, .jpg or .jpeg": what picture_format_of knows, for messages.
std::string picture_extensions();

struct PictureOptions {
  int jpeg_quality = 90;  // 1 to 100, libjpeg's scale
};

// Writes `image` (grey, RGB, or RGBA where the format keeps alpha) to `path` in picture_format_of(path): a file
// through a temporary one renamed into place (PartialFile), or for "-" PNG
// bytes to standard output. Throws std::runtime_error, naming the path, for
// a format it does not know or a write that fails.
void write_picture(const Image& image, const std::string& path, const PictureOptions& options = {});
// The same into `into`'s temporary file, in the format its final name asks
// for, left for the caller to commit with the run's other outputs, so that
// either all of them are written or none is.
void write_picture_into(const Image& image, const PartialFile& into, const PictureOptions& options = {});

}  // namespace umbra
