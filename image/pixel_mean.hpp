#pragma once
// What a pixel becomes from the mean of its samples, alike for the GL frame
// and the ray-cast reference. Both count a sample that sees a surface as
// (colour, 1), and one that sees nothing as (background, 0), or (0, 0, 0, 0)
// where the background is transparent. So an RGB picture's mean is its
// colour, background included; an RGBA one's is the colour premultiplied by
// the coverage a (Porter and Duff 1984), kept as alpha beside the straight
// colour.

#include <algorithm>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "image/image.hpp"
#include "image/tone_curve.hpp"

namespace umbra {

// The sample that sees no surface, for a background `color` or a transparent one.
inline glm::dvec4 background_sample(const glm::dvec3& color, bool transparent) {
  return transparent ? glm::dvec4(0.0) : glm::dvec4(color, 0.0);
}

// A sample that sees a shadow catcher is drawn as (lit, unlit, 0, -1): the
// light that reaches it, and the light that would without shadows (white
// light's mean over the channels). It shows the background darkened by the
// share of light the shadows take, or where the background is transparent,
// black with that share as its coverage. Any other sample is as drawn.
inline glm::dvec4 resolved_sample(const glm::dvec4& drawn, const glm::dvec3& background, bool transparent) {
  if (drawn.a >= 0.0) return drawn;
  const double lost = drawn.g > 0.0 ? std::clamp(1.0 - drawn.r / drawn.g, 0.0, 1.0) : 0.0;
  return transparent ? glm::dvec4(0.0, 0.0, 0.0, lost) : glm::dvec4(background * (1.0 - lost), 0.0);
}

// Writes the pixel whose samples' mean is `mean`. The curve applies to the
// surfaces' part of the mean: the background (and a shadow catcher, which
// shows it) keeps the colour it was given. The mean's coverage a splits the
// two, as every surface sample has coverage 1 and every other 0.
inline void put_pixel_mean(Image& image, int x, int y, const glm::dvec4& mean, const glm::dvec3& background,
                           ToneCurve curve = ToneCurve::kClip) {
  const bool alpha = image.channels == 4;
  const double a = mean.a;
  for (int c = 0; c < 3; ++c) {
    if (curve == ToneCurve::kClip) {  // the mean as it is: no split to round
      image.at(x, y, c) = channel_byte(!alpha ? mean[c] : a > 0.0 ? mean[c] / a : 0.0);
      continue;
    }
    const double behind = alpha ? 0.0 : (1.0 - a) * background[c];  // premultiplied: none behind a transparent one
    const double surface = a > 0.0 ? toned((mean[c] - behind) / a, curve) : 0.0;
    image.at(x, y, c) = channel_byte(alpha ? surface : a * surface + behind);
  }
  if (alpha) image.at(x, y, 3) = channel_byte(a);
}

}  // namespace umbra
