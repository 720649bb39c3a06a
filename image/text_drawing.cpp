#include "image/text_drawing.hpp"

#include <algorithm>
#include <vector>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_easy_font.h>
#pragma GCC diagnostic pop

namespace umbra {

std::string printable(const std::string& label) {
  std::string out;
  for (const char ch : label) {
    const auto byte = static_cast<unsigned char>(ch);
    if (byte >= 0x20 && byte < 0x7f) out += ch;
    else if ((byte & 0xc0) != 0x80) out += '?';  // a UTF-8 continuation byte belongs to the '?' before it
  }
  return out;
}

int text_width(const std::string& text) { return stb_easy_font_width(const_cast<char*>(text.c_str())) * kTextScale; }

void draw_text(Image& image, int x, int y, const std::string& text, const std::array<uint8_t, 3>& ink) {
  // A quad (64 bytes) for each stroke of each character, counted from the
  // font's own tables: the header's "about 270 bytes a character" is an
  // average, and a label of many-stroke letters overran it, losing the last
  // strokes of its last letters.
  size_t bytes = 64;
  for (const char ch : text) {
    const int k = static_cast<unsigned char>(ch) - 32;
    if (k < 0 || k >= 95) continue;  // stb_easy_font draws printable ASCII alone
    const auto& info = stb_easy_font_charinfo;
    bytes += 64 * size_t(info[k + 1].h_seg - info[k].h_seg + info[k + 1].v_seg - info[k].v_seg);
  }
  std::vector<char> quads(bytes);
  const int count = stb_easy_font_print(0, 0, const_cast<char*>(text.c_str()), nullptr, quads.data(), int(quads.size()));
  for (int q = 0; q < count; ++q) {
    const float* v = reinterpret_cast<const float*>(quads.data() + q * 4 * 16);  // 4 vertices of 16 bytes: x, y, z, colour
    const int x0 = x + int(v[0]) * kTextScale, y0 = y + int(v[1]) * kTextScale;
    const int x1 = x + int(v[8]) * kTextScale, y1 = y + int(v[9]) * kTextScale;  // the opposite corner, vertex 2
    for (int py = std::max(y0, 0); py < std::min(y1, image.height); ++py)
      for (int px = std::max(x0, 0); px < std::min(x1, image.width); ++px)
        for (int c = 0; c < 3; ++c) image.at(px, py, c) = ink[size_t(c)];
  }
}

}  // namespace umbra
