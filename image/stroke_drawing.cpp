#include "image/stroke_drawing.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace umbra {
namespace {

void blend(Image& image, int x, int y, const std::array<uint8_t, 3>& ink, double alpha) {
  if (alpha <= 0.0) return;
  alpha = std::min(alpha, 1.0);
  for (int c = 0; c < 3; ++c) image.at(x, y, c) = uint8_t(std::lround(image.at(x, y, c) * (1.0 - alpha) + ink[size_t(c)] * alpha));
  if (image.channels == 4) image.at(x, y, 3) = std::max(image.at(x, y, 3), uint8_t(std::lround(alpha * 255.0)));
}

}  // namespace

void draw_stroke(Image& image, const glm::dvec2& a, const glm::dvec2& b, double radius, const std::array<uint8_t, 3>& ink,
                 const std::function<double(int x, int y)>& opacity) {
  const double reach = radius + 1.0;
  const int x0 = std::max(0, int(std::floor(std::min(a.x, b.x) - reach))), x1 = std::min(image.width - 1, int(std::ceil(std::max(a.x, b.x) + reach)));
  const int y0 = std::max(0, int(std::floor(std::min(a.y, b.y) - reach))), y1 = std::min(image.height - 1, int(std::ceil(std::max(a.y, b.y) + reach)));
  const glm::dvec2 along = b - a;
  const double length2 = glm::dot(along, along);
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const glm::dvec2 p(x + 0.5, y + 0.5);
      const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, along) / length2, 0.0, 1.0) : 0.0;
      const double covered = std::clamp(radius + 0.5 - glm::distance(p, a + t * along), 0.0, 1.0);
      if (covered > 0.0) blend(image, x, y, ink, covered * opacity(x, y));
    }
}

void fill_rectangle(Image& image, int x0, int y0, int x1, int y1, const std::array<uint8_t, 3>& ink, double opacity) {
  for (int y = std::max(y0, 0); y < std::min(y1, image.height); ++y)
    for (int x = std::max(x0, 0); x < std::min(x1, image.width); ++x) blend(image, x, y, ink, opacity);
}

}  // namespace umbra
