#include "reference/ray_cast.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "mesh/predicates/orientation.hpp"
#include "scene/camera.hpp"
#include "reference/ray_primitives.hpp"

namespace umbra {
namespace {

// Does the ray meet the box at t >= 0? (The slab test; a box is only a
// shortcut, so rounding on its edges must err towards yes.)
bool may_hit_box(const glm::dvec3& lo, const glm::dvec3& hi, const glm::dvec3& o, const glm::dvec3& d, double t_max) {
  double t0 = 0.0, t1 = t_max;
  for (int i = 0; i < 3; ++i) {
    const double slack = 1e-9 * (1.0 + std::abs(lo[i]) + std::abs(hi[i]));
    if (d[i] == 0.0) {
      if (o[i] < lo[i] - slack || o[i] > hi[i] + slack) return false;
      continue;
    }
    double near = (lo[i] - slack - o[i]) / d[i], far = (hi[i] + slack - o[i]) / d[i];
    if (near > far) std::swap(near, far);
    t0 = std::max(t0, near);
    t1 = std::min(t1, far);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

std::optional<RayHit> nearest_hit(const Scene& scene, const glm::dvec3& origin, const glm::dvec3& direction,
                                  int skip, double t_min) {
  std::optional<RayHit> best;
  const int sphere_count = int(scene.spheres.size());
  for (int i = 0; i < sphere_count; ++i) {
    if (i == skip) continue;
    const auto t = hit_sphere(scene.spheres[size_t(i)], origin, direction, t_min);
    if (t && (!best || *t < best->t)) {
      const glm::dvec3 p = origin + *t * direction;
      best = RayHit{*t, p, (p - scene.spheres[size_t(i)].center) / scene.spheres[size_t(i)].radius, i};
    }
  }
  for (size_t j = 0; j < scene.triangles.size(); ++j) {
    const int id = sphere_count + int(j);
    if (id == skip) continue;
    const Triangle& tri = scene.triangles[j];
    const auto t = hit_triangle(tri.a, tri.b, tri.c, origin, direction, t_min);
    if (t && (!best || *t < best->t))
      best = RayHit{*t, origin + *t * direction, glm::normalize(glm::cross(tri.b - tri.a, tri.c - tri.a)), id,
                    {&tri.a, &tri.b, &tri.c}};
  }
  int first_id = sphere_count + int(scene.triangles.size());
  for (const Mesh& mesh : scene.meshes) {
    const int mesh_first = first_id;
    first_id += int(mesh.triangles.size());
    const double t_max = best ? best->t : std::numeric_limits<double>::infinity();
    if (!may_hit_box(mesh.bounds_min, mesh.bounds_max, origin, direction, t_max)) continue;
    for (size_t j = 0; j < mesh.triangles.size(); ++j) {
      const int id = mesh_first + int(j);
      if (id == skip) continue;
      const glm::dvec3& a = mesh.positions[mesh.triangles[j][0]];
      const glm::dvec3& b = mesh.positions[mesh.triangles[j][1]];
      const glm::dvec3& c = mesh.positions[mesh.triangles[j][2]];
      const auto t = hit_triangle(a, b, c, origin, direction, t_min);
      if (t && (!best || *t < best->t))
        best = RayHit{*t, origin + *t * direction, glm::normalize(glm::cross(b - a, c - a)), id, {&a, &b, &c}};
    }
  }
  return best;
}

double shadow_ray_start(const glm::dvec3& point, double distance) {
  const double scale = 1.0 + std::max({std::abs(point.x), std::abs(point.y), std::abs(point.z)});
  return kShadowRayStart * std::min(distance, kFarLight * scale);
}

bool shadow_ray_blocked(const Scene& scene, const glm::dvec3& point, int self, const glm::dvec3& light) {
  // A sphere cannot shadow the lit side of itself, nor a triangle itself, so
  // `self` is skipped rather than nudging the ray's origin by an epsilon.
  // But a point on a shared edge lies on its neighbour too, which rounding
  // may then hit at t of about 1e-16 of the distance: hits closer than
  // kShadowRayStart of it are the point's own surface, not a blocker.
  const glm::dvec3 to_light = light - point;
  const double distance = glm::length(to_light);
  const auto hit = nearest_hit(scene, point, to_light / distance, self, shadow_ray_start(point, distance));
  return hit && hit->t < distance;
}

bool seen_side_faces_light(const RayHit& hit, const glm::dvec3& eye, const glm::dvec3& light) {
  if (const auto& [a, b, c] = hit.corners; a) {
    const int light_side = orientation(*a, *b, *c, light);
    return light_side != 0 && light_side == orientation(*a, *b, *c, eye);
  }
  glm::dvec3 n = hit.normal;
  if (glm::dot(n, eye - hit.point) < 0.0) n = -n;  // the side facing the camera
  return glm::dot(n, light - hit.point) > 0.0;
}

uint8_t reference_mask_value(const Scene& scene, int width, int height, double px, double py, size_t light) {
  const Ray ray = scene.camera.pixel_ray(width, height, px, py);
  const glm::dvec3 eye = ray.origin;
  const auto hit = nearest_hit(scene, ray);
  if (!hit) return kMaskNoSurface;
  const glm::dvec3 l = scene.lights[light].position;
  if (!seen_side_faces_light(*hit, eye, l)) return kMaskUnlit;
  return shadow_ray_blocked(scene, hit->point, hit->object, l) ? kMaskUnlit : kMaskLit;
}

}  // namespace umbra
