#include "reference/texture_sampling.hpp"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>

namespace umbra {
namespace {

// Texel index i (any integer) of a row or column of n, wrapped.
int wrapped(int64_t i, int n, TextureImage::Wrap wrap) {
  switch (wrap) {
    case TextureImage::Wrap::kClampToEdge: return int(std::clamp<int64_t>(i, 0, n - 1));
    case TextureImage::Wrap::kMirroredRepeat: {
      const int64_t m = ((i % (2 * n)) + 2 * n) % (2 * n);
      return int(m < n ? m : 2 * n - 1 - m);
    }
    case TextureImage::Wrap::kRepeat: break;
  }
  return int(((i % n) + n) % n);
}

}  // namespace

glm::dvec3 sample_bilinear(const TextureImage& texture, const glm::dvec2& uv) {
  const int w = texture.width, h = texture.height;
  if (w <= 0 || h <= 0) return glm::dvec3(1.0);
  // Texel centres sit at (i + 1/2) / w: the point's place among them.
  const double x = uv.x * w - 0.5, y = uv.y * h - 0.5;
  if (!std::isfinite(x) || !std::isfinite(y)) return glm::dvec3(0.0);
  const double fx = std::floor(x), fy = std::floor(y);
  const double ax = x - fx, ay = y - fy;
  const int64_t i0 = int64_t(fx), j0 = int64_t(fy);
  const auto texel = [&](int64_t i, int64_t j) {
    const size_t at = (size_t(wrapped(j, h, texture.wrap_v)) * size_t(w) + size_t(wrapped(i, w, texture.wrap_u))) * 4;
    return glm::dvec3(texture.rgba[at], texture.rgba[at + 1], texture.rgba[at + 2]) / 255.0;
  };
  const glm::dvec3 blend = (1 - ax) * (1 - ay) * texel(i0, j0) + ax * (1 - ay) * texel(i0 + 1, j0) +
                           (1 - ax) * ay * texel(i0, j0 + 1) + ax * ay * texel(i0 + 1, j0 + 1);
  // The filtered value in the texture's own precision, 8 bits a channel, as
  // Mesa's llvmpipe returns it: unrounded, pixels of a map lit more than
  // fully differed from its image by 2 levels.
  return blend;
}

}  // namespace umbra
