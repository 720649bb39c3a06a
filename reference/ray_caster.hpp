#pragma once
// The CPU reference's ray queries through a bounding volume hierarchy
// (Embree), with the same exact double-precision tests and the same answers
// as the brute-force nearest_hit and shadow_ray_blocked (ray_cast.hpp):
// Embree's float boxes only decide which primitives to test, and they are
// padded so that rounding never skips one.

#include <memory>
#include <optional>

#include "scene/scene.hpp"
#include "reference/ray_cast.hpp"

namespace umbra {

class RayCaster {
 public:
  // kAuto searches by brute force below kHierarchyFrom primitives, where the
  // hierarchy saves nothing (bench/reference_benchmark: at 128x128, 6
  // primitives take 1.6 ms by brute force and 1.9 ms through it; 66 take 4.9
  // and 2.2 ms; 1,026 take 57 and 2.2 ms).
  enum class Search { kAuto, kHierarchy, kBruteForce };
  static constexpr size_t kHierarchyFrom = 16;

  // How far from the origin, coordinate by coordinate, a ray of `camera` may
  // start: its eye, or an orthographic camera's plane as far as a picture 64
  // times wider than high reaches. The hierarchy pads its boxes by it.
  static double farthest_ray_start(const Camera& camera);

  // Builds the hierarchy over every sphere, triangle and mesh triangle. The
  // scene must outlive the caster and stay unchanged but for its camera,
  // whose rays start no further out than the scene's own (farthest_ray_start). Throws
  // std::runtime_error when Embree cannot start.
  explicit RayCaster(const Scene& scene, Search search = Search::kAuto);
  ~RayCaster();
  RayCaster(const RayCaster&) = delete;
  RayCaster& operator=(const RayCaster&) = delete;

  // As the free functions of the same names; safe to call from many threads.
  std::optional<RayHit> nearest_hit(const glm::dvec3& origin, const glm::dvec3& direction, int skip = -1,
                                    double t_min = 0.0) const;
  std::optional<RayHit> nearest_hit(const Ray& ray) const { return nearest_hit(ray.origin, ray.direction); }
  bool shadow_ray_blocked(const glm::dvec3& point, int self, const glm::dvec3& light) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace umbra
