#pragma once
// What the stage gives a mesh file by default, shared by its framing
// (stage_framing.cpp) and its staging (staged_scene.cpp): where the camera
// and the light stand, seen from the model's centre (StageView's
// convention), and when a model comes before its shadow in the frame.

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

namespace umbra::stage_defaults {

// The unit vector from the model's centre toward azimuth and elevation
// (StageView's convention).
inline glm::dvec3 toward(double azimuth_deg, double elevation_deg) {
  const double a = glm::radians(azimuth_deg), e = glm::radians(elevation_deg);
  return {std::sin(a) * std::cos(e), -std::cos(a) * std::cos(e), std::sin(e)};
}

// The light by default (StageView's defaults for the view): from the front
// and to the left, high up, so that the shadow falls to the back and right.
inline const glm::dvec3 kToLight = glm::normalize(glm::dvec3(-0.55, -0.5, 1.3));
inline const double kLightAzimuthDeg = glm::degrees(std::atan2(kToLight.x, -kToLight.y));
inline const double kLightElevationDeg = glm::degrees(std::asin(kToLight.z));
inline constexpr double kCameraAzimuthDeg = 35.0;  // StageView's default
inline constexpr double kCameraElevationDeg = 30.0, kLowModelElevationDeg = 60.0;

// A spindly model, which covers under kSpindly of the box it shows the
// camera (a diplodocus's neck and legs, a lamp post), has its shadow framed
// only as far as lets the camera stand kShadowRoom times as far back as
// the model alone needs, under the default light: its shadow, which shows
// more mass than the model does, would leave it small in the frame. A solid
// model keeps its whole shadow in view, and so does a light the user moved.
inline constexpr double kSpindly = 0.42, kShadowRoom = 1.25;

}  // namespace umbra::stage_defaults
