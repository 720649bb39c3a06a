#include "image/animation_file.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <stdexcept>

#include "image/animation_writers.hpp"
#include "mesh/file_extension.hpp"

namespace umbra {

#ifndef UMBRA_HAVE_MP4
#define UMBRA_HAVE_MP4 0
#endif
#ifndef UMBRA_HAVE_WEBP
#define UMBRA_HAVE_WEBP 0
#endif
#ifndef UMBRA_HAVE_GIF
#define UMBRA_HAVE_GIF 0
#endif

const AnimationFormatRow kAnimationFormats[3] = {
    {AnimationFormat::kMp4, "an MP4 video (H.264)", ".mp4", false, false, "libavcodec with libx264",
     "libavcodec-dev libavformat-dev libswscale-dev", UMBRA_HAVE_MP4 != 0},
    {AnimationFormat::kWebp, "an animated WebP", ".webp", true, true, "libwebp's animation encoder", "libwebp-dev",
     UMBRA_HAVE_WEBP != 0},
    {AnimationFormat::kGif, "a GIF", ".gif", false, false, "giflib", "libgif-dev", UMBRA_HAVE_GIF != 0},
};

const AnimationFormatRow& animation_row(AnimationFormat format) { return kAnimationFormats[size_t(format)]; }

std::optional<AnimationFormat> animation_format_of(const std::string& path) {
  const std::string extension = lowercase_extension(path);
  for (const AnimationFormatRow& row : kAnimationFormats)
    if (extension == row.extension) return row.format;
  return std::nullopt;
}

std::string animation_extensions(bool dots) {
  std::string names;
  for (size_t i = 0; i < std::size(kAnimationFormats); ++i)
    names += (i == 0 ? "" : i + 1 == std::size(kAnimationFormats) ? " or " : ", ") + std::string(kAnimationFormats[i].extension + (dots ? 0 : 1));
  return names;
}

std::string animation_unavailable(AnimationFormat format) {
  const AnimationFormatRow& row = animation_row(format);
  if (row.built) return "";
  return std::string(row.name) + " needs " + row.library + ", which this umbra was built without: ./build.sh installs " +
         row.packages + " and builds it in";
}

std::unique_ptr<AnimationWriter> open_animation(AnimationFormat format, const std::string& path, const std::string& shown,
                                                const AnimationSettings& settings) {
  if (const std::string why = animation_unavailable(format); !why.empty()) throw std::runtime_error(shown + ": " + why);
  // Only the writers built are named: the others' files are left out.
#if UMBRA_HAVE_MP4
  if (format == AnimationFormat::kMp4) return open_mp4(path, shown, settings);
#endif
#if UMBRA_HAVE_WEBP
  if (format == AnimationFormat::kWebp) return open_animated_webp(path, shown, settings);
#endif
#if UMBRA_HAVE_GIF
  if (format == AnimationFormat::kGif) return open_gif(path, shown, settings);
#endif
  throw std::logic_error("an animation format with no writer");
}

}  // namespace umbra
