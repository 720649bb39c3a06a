#pragma once
// Texture maps' image files for the mesh readers: which files a model may
// name (ReadOptions), read only when they are plain files of a bounded size,
// and decoded (PNG, JPEG, BMP, TGA, ... as stb_image reads them) once each
// and only within a pixel budget, whatever a file downloaded from anywhere
// asks for.

#include <cstddef>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/io/polygon_soup.hpp"
#include "mesh/texture_image.hpp"

namespace umbra {

// The largest image decoded as a texture map: 16384 texels along a side (the
// least OpenGL 4.x implementations offer, llvmpipe's included) and 2^26 in
// all (8192 x 8192, 256 MiB as RGBA). Told from the image's header, before
// anything is decoded.
constexpr int kMostTextureSide = 16384;
constexpr long long kMostTexturePixels = 1LL << 26;
// The largest image file read: a compressed image past 256 MiB would decode
// past the pixel budget anyway.
constexpr size_t kMostTextureFileBytes = size_t(1) << 28;

// What one model's maps may hold decoded, all together: 2^28 pixels (1 GiB
// as RGBA, four maps of the largest size). Twelve maps of 8192 x 8192 once
// took 6.5 GB and 25 s for a picture of 200 x 200; past the budget, a map is
// refused, told from its header before it is decoded.
constexpr long long kMostModelTexturePixels = 1LL << 28;
class TextureBudget {
 public:
  // Takes a map of `pixels` from what is left; false, taking none, where it
  // does not fit.
  bool take(long long pixels) {
    if (pixels > kMostModelTexturePixels - used_) return false;
    used_ += pixels;
    return true;
  }

 private:
  long long used_ = 0;
};

// The image in `bytes`, named `name`; null, with `error` saying why, when it
// cannot be decoded, is larger than the budget above, or (where `budget` is
// given) would take its model's maps past kMostModelTexturePixels.
std::shared_ptr<TextureImage> decode_texture(std::string_view bytes, const std::string& name, std::string& error,
                                             TextureBudget* budget = nullptr);

// Reads the file at `path` whole into `bytes` when it is a regular file (not
// a device, a FIFO or a folder, which could be endless or never answer: see
// MappedFile) of at most `most` bytes; else false, with `error` saying why.
bool read_regular_file(const std::string& path, size_t most, std::vector<unsigned char>& bytes, std::string& error);

// The files one model may read beside it, under `maps`: each decoded once,
// however many materials name it.
class ModelFiles {
 public:
  // `model_path`: the mesh file, whose folder is the root when maps.root is "".
  ModelFiles(const ReadOptions& maps, const std::string& model_path);

  // Why the file at `path` may not be read: "" when it may; else, say, "is
  // outside the folder ... (--any-texture-path reads it)" or "is not a
  // regular file (a FIFO)". Reads nothing.
  std::string refusal(const std::string& path) const;

  // The texture map at `path`, wrapping as `wrap` says (MTL's -clamp on is
  // clamp-to-edge), decoded once for each; null, with `error` saying why
  // the first time it is asked for and "" after (said once is enough).
  std::shared_ptr<const TextureImage> texture(const std::string& path, std::string& error,
                                              TextureImage::Wrap wrap = TextureImage::Wrap::kRepeat);

 private:
  std::filesystem::path root_;  // absolute, its links resolved
  bool anywhere_;
  struct Decoded {
    std::shared_ptr<const TextureImage> image;
    std::string error;
  };
  std::map<std::pair<std::string, TextureImage::Wrap>, Decoded> textures_;  // by path as asked, and wrapping
  TextureBudget budget_;                     // what the maps decoded so far hold
};

}  // namespace umbra
