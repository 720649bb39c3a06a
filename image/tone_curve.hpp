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

// Where kSoft's shoulder starts. (The window's picture takes the same curve
// in a shader, render/shaders.hpp's kShowFragment, with this knee.)
constexpr double kToneKnee = 0.8;

inline double toned(double light, ToneCurve curve) {
  if (curve == ToneCurve::kClip || light <= kToneKnee) return light;
  return kToneKnee + (1.0 - kToneKnee) * (1.0 - std::exp(-(light - kToneKnee) / (1.0 - kToneKnee)));
}

}  // namespace umbra
