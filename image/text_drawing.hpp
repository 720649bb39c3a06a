#pragma once
// Labels drawn into a picture in Sean Barrett's stb_easy_font (Debian's
// libstb-dev): an ASCII bitmap font made of quads, no font file or
// texture, which is all a label needs. The contact sheet's names and the
// defect picture's legend.

#include <array>
#include <cstdint>
#include <string>

#include "image/image.hpp"

namespace umbra {

// The font's pixels drawn `scale` times larger: 2 makes about 14 pixels a line.
constexpr int kTextScale = 2;
constexpr int kTextLineHeight = 12 * kTextScale;

// `label` in the font's characters: stb_easy_font draws printable ASCII
// only, and reads outside its tables for any other byte; each other
// character (a UTF-8 sequence, a control byte) shows as one '?'.
std::string printable(const std::string& label);
// How wide `text` (printable) draws, in pixels.
int text_width(const std::string& text);
// Draws `text` (printable) with its top left at (x, y) in `ink`, clipped to the image.
void draw_text(Image& image, int x, int y, const std::string& text, const std::array<uint8_t, 3>& ink);

}  // namespace umbra
