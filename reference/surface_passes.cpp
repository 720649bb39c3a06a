#include "reference/surface_passes.hpp"

#include <limits>

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include "reference/hit_surface.hpp"
#include "reference/ray_caster.hpp"

namespace umbra {

SurfacePasses surface_passes(const Scene& scene, const RayCaster& caster, size_t model, int width, int height) {
  const size_t pixels = size_t(width) * size_t(height);
  SurfacePasses passes{width, height, std::vector<float>(pixels, std::numeric_limits<float>::infinity()),
                       std::vector<glm::vec3>(pixels, glm::vec3(0.0f)), std::vector<uint8_t>(pixels, 0)};
  const Mesh* const mesh = &scene.meshes.at(model);
  const PixelRays rays(scene.camera, width, height);
  const glm::dvec3 forward = scene.camera.axes().forward;
  tbb::parallel_for(0, height, [&](int y) {
    for (int x = 0; x < width; ++x) {
      const Ray ray = rays.ray(x, y);
      const std::optional<RayHit> hit = caster.nearest_hit(ray);
      if (!hit) continue;
      const Surface surface = surface_of(scene, hit->object);
      if (surface.mesh != mesh) continue;
      const size_t k = size_t(y) * size_t(width) + size_t(x);
      glm::dvec3 n = hit->normal;
      if (glm::dot(n, ray.direction) > 0.0) n = -n;  // the side the eye sees
      if (const std::optional<glm::dvec3> smooth = shading_normal(surface, hit->point))
        n = glm::dot(*smooth, n) < 0.0 ? -*smooth : *smooth;
      passes.depth[k] = float(hit->t * glm::dot(ray.direction, forward));
      passes.normal[k] = glm::vec3(n);
      passes.object[k] = 255;
    }
  });
  return passes;
}

}  // namespace umbra
