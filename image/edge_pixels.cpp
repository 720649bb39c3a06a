#include "image/edge_pixels.hpp"

#include <cstdlib>
#include <utility>

namespace umbra {

std::vector<uint8_t> edge_pixels(const Image& image, int levels) {
  std::vector<uint8_t> edge(size_t(image.width) * size_t(image.height), 0);
  const auto differ = [&](int x, int y, int u, int v) {
    for (int c = 0; c < image.channels; ++c)
      if (std::abs(int(image.at(x, y, c)) - int(image.at(u, v, c))) > levels) return true;
    return false;
  };
  // Each pair of neighbours once (right, and the three below), marking both.
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 1}, {0, 1}, {1, 1}}) {
        const int u = x + dx, v = y + dy;
        if (u < 0 || u >= image.width || v >= image.height || !differ(x, y, u, v)) continue;
        edge[size_t(y) * size_t(image.width) + size_t(x)] = 1;
        edge[size_t(v) * size_t(image.width) + size_t(u)] = 1;
      }
  return edge;
}

}  // namespace umbra
