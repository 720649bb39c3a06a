#pragma once
// The accuracy a benchmark reports: how many surface pixels a method puts in
// the wrong class (lit or unlit) against the ray-cast reference's mask.

#include "image/image.hpp"

namespace umbra {

struct MaskError {
  long surface_pixels = 0;  // where the reference sees a surface
  long wrong_pixels = 0;    // of those, the ones whose class differs
  double fraction() const { return surface_pixels ? double(wrong_pixels) / double(surface_pixels) : 0.0; }
  MaskError& operator+=(const MaskError& o) {
    surface_pixels += o.surface_pixels;
    wrong_pixels += o.wrong_pixels;
    return *this;
  }
};

// Both masks are the same size (kMaskLit, kMaskUnlit, kMaskNoSurface).
MaskError mask_error(const Image& reference, const Image& mask);

}  // namespace umbra
