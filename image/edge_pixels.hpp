#pragma once
// Which pixels of a one-sample picture need more samples: those whose
// footprint may hold an edge (of an object, a shadow or a texture's
// detail). A pixel drawn from its centre alone is its footprint's mean
// wherever the colour is smooth across it; where it is not, a neighbour
// differs. So a pixel is taken for an edge where some channel differs by
// more than kEdgeLevels from one of its eight neighbours: the adaptive
// refinement of Whitted (1980), which cast more rays only where a pixel's
// corners disagree, on a finished frame's pixels (as Mitchell 1987 does on
// samples). A feature thinner than a pixel that no centre meets is missed,
// as it is by the one-sample frame.

#include <cstdint>
#include <vector>

#include "image/image.hpp"

namespace umbra {

// Where a picture's pixels take antialiasing's samples: every pixel (the
// frame drawn that many times larger), or only those edge_pixels finds, the
// rest kept from the one-sample frame.
enum class AntialiasedPixels { kEdges, kAll };

// How far apart two neighbours may be, in levels of 255 on any channel,
// and still be taken for one smooth surface. A smooth face's shading moves
// a level or two from pixel to pixel at 800 x 800; a bound of 2 draws
// edges as close to a 16 x 16 reference as 3 x 3 samples everywhere do
// (bench/antialias_quality.sh: 4 leaves the faceted noise of a fine mesh
// drawn flat, 8 more of it, for 22% and 50% fewer rays there).
constexpr int kEdgeLevels = 2;

// Per pixel, row-major from the top, 1 where it differs from a neighbour by
// more than `levels` on any channel (alpha included), else 0.
std::vector<uint8_t> edge_pixels(const Image& image, int levels = kEdgeLevels);

}  // namespace umbra
