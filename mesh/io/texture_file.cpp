#include "mesh/io/texture_file.hpp"

#include <climits>
#include <fstream>
#include <iterator>

#include <stb_image.h>  // Debian's libstb: its implementation is in libstb.so

namespace umbra {

std::shared_ptr<const TextureImage> decode_texture(std::string_view bytes, const std::string& name, std::string& error) {
  if (bytes.size() > size_t(INT_MAX)) {
    error = "the image is over 2 GB";
    return nullptr;
  }
  int width = 0, height = 0, channels = 0;
  stbi_uc* pixels = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()), int(bytes.size()), &width,
                                          &height, &channels, 4);
  if (!pixels) {
    const char* reason = stbi_failure_reason();
    error = std::string("cannot decode the image (") + (reason ? reason : "unknown format") + ")";
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

std::shared_ptr<const TextureImage> read_texture_file(const std::string& path, std::string& error) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    error = "cannot open it";
    return nullptr;
  }
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return decode_texture(bytes, path, error);
}

}  // namespace umbra
