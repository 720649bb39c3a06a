#pragma once
// What a surface's light becomes before it is rounded to 8 bits: one curve
// for the GL frame and the ray-cast reference (pixel_mean.hpp applies it).

#include <cmath>

namespace umbra {

// How a surface's light becomes a channel's value before it is rounded to 8
// bits: clipped at 1 (kClip, as a spec scene is drawn), or rolled off above
// a knee so that bright areas keep their shape instead of flattening at
// white (kSoft, a staged model's look). The shoulder is exponential, with
// the line's slope at the knee, so the curve is smooth and approaches 1:
// 0.98 takes 1.26 of light.
enum class ToneCurve { kClip, kSoft };

inline double toned(double light, ToneCurve curve) {
  constexpr double kKnee = 0.8;
  if (curve == ToneCurve::kClip || light <= kKnee) return light;
  return kKnee + (1.0 - kKnee) * (1.0 - std::exp(-(light - kKnee) / (1.0 - kKnee)));
}

}  // namespace umbra
