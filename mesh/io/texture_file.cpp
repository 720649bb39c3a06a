#include "mesh/io/texture_file.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <climits>
#include <cstring>

#include <stb_image.h>  // Debian's libstb: its implementation is in libstb.so

#include "mesh/input_error.hpp"
#include "mesh/io/mapped_file.hpp"

namespace umbra {
namespace {

// stb_image's reasons are short codes ("outofdata"), and a truncated PNG
// may give none at all: say what they mean for the file.
std::string decoding_failure(std::string_view bytes) {
  const char* code = stbi_failure_reason();
  const std::string said = code ? code : "";
  const bool png = bytes.substr(0, 8) == "\x89PNG\r\n\x1a\n", jpeg = bytes.substr(0, 2) == "\xff\xd8";
  if (said == "outofdata" || said.empty() || ((png || jpeg) && said == "unknown image type"))
    return std::string("cannot decode the image: ") + (png ? "a PNG" : jpeg ? "a JPEG" : "the file") + " cut short or corrupt" +
           (said.empty() ? "" : " (stb_image: " + said + ")");
  return "cannot decode the image (" + said + ")";
}

std::string not_regular(mode_t mode) {
  return "is not a regular file (" + non_regular_kind(mode) + "), which umbra does not read as an image";
}

std::string size_in_mib(size_t bytes) { return std::to_string((bytes + (size_t(1) << 20) - 1) >> 20) + " MiB"; }

// Whether `path` lies in `folder` or below it (both absolute and normal).
bool lies_in(const std::filesystem::path& path, const std::filesystem::path& folder) {
  auto p = path.begin();
  for (auto f = folder.begin(); f != folder.end(); ++f, ++p) {
    if (f->empty()) continue;  // the trailing "" of "a/b/"
    if (p == path.end() || *p != *f) return false;
  }
  return true;
}

}  // namespace

std::shared_ptr<TextureImage> decode_texture(std::string_view bytes, const std::string& name, std::string& error,
                                             TextureBudget* budget) {
  if (bytes.size() > size_t(INT_MAX)) {
    error = "the image is over 2 GB";
    return nullptr;
  }
  const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
  int width = 0, height = 0, channels = 0;
  // The header first: a small file can claim a huge image.
  if (!stbi_info_from_memory(data, int(bytes.size()), &width, &height, &channels)) {
    error = decoding_failure(bytes);
    return nullptr;
  }
  if (width > kMostTextureSide || height > kMostTextureSide || (long long)width * height > kMostTexturePixels) {
    error = "the image is " + std::to_string(width) + "x" + std::to_string(height) + " pixels, more than umbra decodes (" +
            std::to_string(kMostTextureSide) + " along a side, " + std::to_string(kMostTexturePixels) + " pixels in all)";
    return nullptr;
  }
  if (budget && !budget->take((long long)width * height)) {
    error = "the image is " + std::to_string(width) + "x" + std::to_string(height) + " pixels, more than is left of the " +
            std::to_string(kMostModelTexturePixels) + " pixels umbra decodes of one model's maps in all";
    return nullptr;
  }
  stbi_uc* pixels = stbi_load_from_memory(data, int(bytes.size()), &width, &height, &channels, 4);
  if (!pixels) {
    error = decoding_failure(bytes);
    return nullptr;
  }
  auto texture = std::make_shared<TextureImage>();
  texture->name = name;
  texture->width = width;
  texture->height = height;
  texture->rgba.assign(pixels, pixels + size_t(width) * size_t(height) * 4);
  stbi_image_free(pixels);
  return texture;
}

bool read_regular_file(const std::string& path, size_t most, std::vector<unsigned char>& bytes, std::string& error) {
  try {
    const MappedFile file(path);  // a regular file only, opened without waiting
    const std::string_view mapped = file.bytes();
    if (mapped.size() > most) {
      error = "is " + size_in_mib(mapped.size()) + ", more than the " + size_in_mib(most) + " umbra reads of such a file";
      return false;
    }
    bytes.assign(mapped.begin(), mapped.end());
    if (file.cut_short()) {
      error = "was cut short while it was read";
      return false;
    }
    return true;
  } catch (const InputError& e) {
    error = e.message();
    return false;
  }
}

ModelFiles::ModelFiles(const ReadOptions& maps, const std::string& model_path) : anywhere_(maps.anywhere) {
  std::error_code ec;
  const std::filesystem::path root =
      maps.root.empty() ? std::filesystem::absolute(model_path, ec).parent_path() : std::filesystem::path(maps.root);
  root_ = std::filesystem::weakly_canonical(std::filesystem::absolute(root, ec), ec);
}

std::string ModelFiles::refusal(const std::string& path) const {
  std::error_code ec;
  // Links resolved: a link inside the folder to a file outside it reads
  // the file outside. Said before whether it exists, which outside the
  // folder is none of the model's business.
  const std::filesystem::path real = std::filesystem::weakly_canonical(std::filesystem::absolute(path, ec), ec);
  if (!anywhere_ && !lies_in(real, root_))
    return "lies outside " + root_.string() + ", the folder umbra reads this model's files from (--any-texture-path reads it)";
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) return errno == ENOENT ? "does not exist" : std::string("cannot be read: ") + std::strerror(errno);
  if (!S_ISREG(st.st_mode)) return not_regular(st.st_mode);
  return "";
}

std::shared_ptr<const TextureImage> ModelFiles::texture(const std::string& path, std::string& error, TextureImage::Wrap wrap) {
  const auto [cached, first_time] = textures_.try_emplace({path, wrap});
  Decoded& d = cached->second;
  if (first_time) {
    std::vector<unsigned char> bytes;
    d.error = refusal(path);
    if (d.error.empty() && read_regular_file(path, kMostTextureFileBytes, bytes, d.error))
      if (auto image = decode_texture(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), path, d.error,
                                      &budget_)) {
        image->file = path;
        image->wrap_u = image->wrap_v = wrap;
        d.image = std::move(image);
      }
  }
  error = first_time ? d.error : "";
  return d.image;
}

}  // namespace umbra
