#include "mesh/scene/scene.hpp"

#include <cmath>

#include <glm/common.hpp>

namespace umbra {

std::string FileLoc::str() const {
  std::string s = file;
  if (line > 0) s += ":" + std::to_string(line);
  if (line > 0 && column > 0) s += ":" + std::to_string(column);
  return s;
}

Camera spec_camera() {
  // tan(45deg / 2) * (3.4 - 1) = 0.994: the face z = 1 spans 99.4% of the height.
  return Camera{{0.0, 0.0, 3.4}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 45.0};
}

SceneBounds surface_bounds(const Scene& scene) {
  SceneBounds b;
  const auto grow = [&b](const glm::dvec3& lo, const glm::dvec3& hi) {
    if (b.empty()) b.lo = lo, b.hi = hi;
    else b.lo = glm::min(b.lo, lo), b.hi = glm::max(b.hi, hi);
  };
  for (const Sphere& s : scene.spheres) grow(s.center - s.radius, s.center + s.radius);
  for (const Triangle& t : scene.triangles) grow(glm::min(t.a, glm::min(t.b, t.c)), glm::max(t.a, glm::max(t.b, t.c)));
  for (const Mesh& m : scene.meshes)
    if (!m.triangles.empty()) grow(m.bounds_min, m.bounds_max);
  return b;
}

void rotate_lights_about_z(Scene& scene, double degrees) {
  const double a = degrees * M_PI / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  for (Light& light : scene.lights) {
    const glm::dvec3 p = light.position;
    light.position = {c * p.x - s * p.y, s * p.x + c * p.y, p.z};
  }
}

}  // namespace umbra
