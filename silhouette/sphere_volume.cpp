#include "silhouette/sphere_volume.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

#include "silhouette/extrude_to_infinity.hpp"

namespace umbra {

TangentCircle tangent_circle(const glm::dvec3& center, double radius, const glm::dvec3& light) {
  const glm::dvec3 lc = center - light;
  const double lc2 = glm::dot(lc, lc);
  const double lc_len = std::sqrt(lc2);
  const double tangent2 = lc2 - radius * radius;  // LQ^2 = LC^2 - R^2
  if (!(tangent2 > 0.0)) throw std::invalid_argument("tangent_circle: the light is not outside the sphere");

  TangentCircle circle;
  // P = L + PL * LC / |LC| with PL = (LC^2 - R^2) / LC (docs/geometry.md). Since
  // PL = LC - R^2 / LC, the same point is C - (R^2 / LC) * LC / |LC|, which
  // stays accurate when the light is far (no LC - LC cancellation).
  circle.center = center - (radius * radius / lc_len) * (lc / lc_len);
  // r = sqrt(LC^2 - R^2 - PL^2) (docs/geometry.md), rewritten as R sqrt(LC^2 - R^2) / LC,
  // which is the same number without the cancellation when the light is far.
  circle.radius = radius * std::sqrt(tangent2) / lc_len;

  // A perpendicular to LC that skips its smallest coordinate (long, so accurate).
  const glm::dvec3 m = glm::abs(lc);
  glm::dvec3 perpendicular;
  if (m.x <= m.y && m.x <= m.z) perpendicular = {0.0, -lc.z, lc.y};
  else if (m.y <= m.z) perpendicular = {-lc.z, 0.0, lc.x};
  else perpendicular = {-lc.y, lc.x, 0.0};
  circle.u = glm::normalize(perpendicular) * circle.radius;
  circle.v = glm::normalize(glm::cross(circle.u, lc)) * circle.radius;
  return circle;
}

ShadowVolume sphere_volume(const glm::dvec3& center, double radius, const glm::dvec3& light, int segments) {
  if (segments < 3) throw std::invalid_argument("sphere_volume: needs at least 3 segments");
  const TangentCircle circle = tangent_circle(center, radius, light);
  // Q_k by increasing angle turn about v x u = +LC, i.e. clockwise seen from the
  // light; extrude_to_infinity wants counter-clockwise, so list them backwards.
  std::vector<glm::dvec3> loop(static_cast<size_t>(segments));
  for (int k = 0; k < segments; ++k) {
    const double beta = 2.0 * M_PI * k / segments;
    loop[size_t(segments - 1 - k)] = circle.center + std::cos(beta) * circle.v + std::sin(beta) * circle.u;
  }
  return extrude_to_infinity(loop, light, circle.center);
}

}  // namespace umbra
