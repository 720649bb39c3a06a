#pragma once
// Decoding a texture map's image (PNG, JPEG, BMP, TGA, ... as stb_image
// reads them) for the mesh readers.

#include <memory>
#include <string>
#include <string_view>

#include "mesh/texture_image.hpp"

namespace umbra {

// The image in `bytes`, named `name`; null, with `error` saying why, when it
// cannot be decoded.
std::shared_ptr<const TextureImage> decode_texture(std::string_view bytes, const std::string& name, std::string& error);

// The image file at `path`; null, with `error` saying why, when it cannot be
// read or decoded.
std::shared_ptr<const TextureImage> read_texture_file(const std::string& path, std::string& error);

}  // namespace umbra
