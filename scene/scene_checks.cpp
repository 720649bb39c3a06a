#include "scene/scene_checks.hpp"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "mesh/predicates/orientation.hpp"

namespace umbra {

void require_lights_off_casters(const Scene& scene) {
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    const std::string light_name = "light " + std::to_string(i + 1) + " (line " + std::to_string(light.where.line) + ")";
    for (const Sphere& s : scene.spheres) {
      const glm::dvec3 lc = s.center - light.position;
      // The tangent circle needs LC^2 - R^2 > 0 to exist (docs/geometry.md).
      const double tangent2 = glm::dot(lc, lc) - s.radius * s.radius;
      if (!std::isfinite(tangent2))
        throw InputError(s.where, "the distance from " + light_name +
                                      " to this sphere overflows double precision; scale the scene down");
      // Exactly on the surface counts as on it whatever the rounding says; and
      // so does a point the double arithmetic cannot tell from it, where the
      // tangent circle cannot be built.
      if (side_of_sphere(s.center, s.radius, light.position) <= 0 || tangent2 <= 0.0)
        throw InputError(s.where, light_name + " is inside or on this sphere, which then has no shadow volume; "
                                               "move the light outside the sphere");
    }
    for (const Mesh& mesh : scene.meshes) {
      const glm::dvec3& l = light.position;
      if (glm::any(glm::lessThan(l, mesh.bounds_min)) || glm::any(glm::greaterThan(l, mesh.bounds_max))) continue;
      for (const auto& tri : mesh.triangles)
        if (on_triangle(mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]], l))
          throw InputError(mesh.where, light_name + " is on the surface of this mesh, where its shadow volume is "
                                                    "undefined; move the light off the surface");
    }
  }
}

}  // namespace umbra
