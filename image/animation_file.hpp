#pragma once
// Writing frames as an animation in the format its name asks for: H.264
// video in MP4, animated WebP or GIF. The formats live in one table
// (kAnimationFormats); each one's library is optional at build time, and a
// format whose library was not built says which package builds it.

#include <memory>
#include <optional>
#include <string>

#include "image/image.hpp"

namespace umbra {

enum class AnimationFormat { kMp4, kWebp, kGif };

struct AnimationFormatRow {
  AnimationFormat format;
  const char* name;       // "an MP4 video (H.264)"
  const char* extension;  // lower case, with the dot
  bool alpha;             // keeps an alpha channel (a transparent background)
  bool quality;           // takes --quality (lossy at that quality; lossless without)
  const char* library;    // what encodes it: "libavcodec with libx264"
  const char* packages;   // the Debian packages that build it in
  bool built;             // whether this build has the library
};
extern const AnimationFormatRow kAnimationFormats[3];
const AnimationFormatRow& animation_row(AnimationFormat format);

// The format `path`'s extension names (case aside), or none.
std::optional<AnimationFormat> animation_format_of(const std::string& path);
// ".mp4, .webp or .gif": for messages; "mp4, webp or gif" without `dots`.
std::string animation_extensions(bool dots = true);

struct AnimationSettings {
  int width = 0, height = 0;  // every frame's
  double fps = 30.0;          // frames a second
  std::optional<int> quality;  // 1 to 100 where the format takes it; none: lossless (WebP) or the format's default
};

// Frames added one by one, written to a file once finished. Frames are RGB,
// or RGBA where the format keeps alpha, of the settings' size.
class AnimationWriter {
 public:
  virtual ~AnimationWriter() = default;
  virtual void add(const Image& frame) = 0;
  // Writes what is left; the file is whole once this returns.
  virtual void finish() = 0;
};

// A writer of `format` into the file at `path` (a temporary file, renamed
// into place by the caller once finished). Throws std::runtime_error,
// naming `shown` (the final path), where the format's library was not
// built, or cannot start, or the settings are not the format's (an MP4's
// width and height must be even).
std::unique_ptr<AnimationWriter> open_animation(AnimationFormat format, const std::string& path, const std::string& shown,
                                                const AnimationSettings& settings);

// Why a format cannot be written by this build, or "" where it can: "an MP4
// video (H.264) needs libavcodec with libx264, which this umbra was built
// without: ./build.sh installs libavcodec-dev libavformat-dev libswscale-dev and
// builds it in".
std::string animation_unavailable(AnimationFormat format);

}  // namespace umbra
