#include "image/mask_error.hpp"

#include <stdexcept>

namespace umbra {

MaskError mask_error(const Image& reference, const Image& mask) {
  if (reference.width != mask.width || reference.height != mask.height || reference.channels != mask.channels)
    throw std::invalid_argument("mask_error: the masks differ in size");
  MaskError e;
  for (size_t i = 0; i < reference.pixels.size(); ++i) {
    if (reference.pixels[i] == kMaskNoSurface) continue;
    ++e.surface_pixels;
    e.wrong_pixels += mask.pixels[i] != reference.pixels[i];
  }
  return e;
}

}  // namespace umbra
