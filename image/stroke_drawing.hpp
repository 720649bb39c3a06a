#pragma once
// Strokes laid over a finished picture: thick segments (a dot is a segment
// of no length) with antialiased edges, blended at an opacity that may
// vary from pixel to pixel (the defect picture draws what a surface hides
// fainter). Coordinates are in pixels, x right and y down, a pixel's
// centre at its index + 0.5.

#include <array>
#include <cstdint>
#include <functional>

#include <glm/vec2.hpp>

#include "image/image.hpp"

namespace umbra {

// Blends `ink` into the pixels within `radius` of the segment from `a` to
// `b`, each by opacity(x, y) times how much of it the stroke covers (a
// pixel's width of soft edge). An RGBA picture's alpha rises to the
// stroke's. Pixels off the picture are left out.
void draw_stroke(Image& image, const glm::dvec2& a, const glm::dvec2& b, double radius, const std::array<uint8_t, 3>& ink,
                 const std::function<double(int x, int y)>& opacity);

// Blends `ink` into the rectangle [x0, x1) x [y0, y1) at `opacity` (a
// legend's ground).
void fill_rectangle(Image& image, int x0, int y0, int x1, int y1, const std::array<uint8_t, 3>& ink, double opacity);

}  // namespace umbra
