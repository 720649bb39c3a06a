#pragma once
// Compares a rendered shadow mask with the CPU reference pixel by pixel. A
// pixel may differ only where the exact answer itself changes within the
// pixel (its footprint straddles a shadow, silhouette or terminator edge; at
// most a quarter of such pixels, within_boundary_bound), or
// where the point's shadow ray passes through the sliver between a sphere's
// true tangent cone and the cone of its inscribed N-gon (docs/geometry.md), the one
// approximation in the volumes; or where the surface is lit at a grazing
// angle that float and double arithmetic cannot resolve (kGrazing). A
// triangle whose plane holds the light exactly has no such excuse: both
// decide its side of the light exactly, and it is unlit.

#include <array>
#include <cmath>
#include <vector>
#include <sstream>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "mesh/predicates/orientation.hpp"
#include "scene/scene_checks.hpp"
#include "scene/camera.hpp"
#include "render/headless_context.hpp"
#include "image/image.hpp"
#include "reference/ray_cast.hpp"
#include "render/render_plan.hpp"
#include "render/shadow_renderer.hpp"
#include "silhouette/sphere_volume.hpp"

namespace umbra::test {

struct MaskComparison {
  int surface_pixels = 0;
  int differing = 0;
  int excused_boundary = 0;
  int boundary_pixels = 0;  // pixels whose footprint straddles a change of the reference's class
  int excused_ngon = 0;
  int excused_grazing = 0;
  int unexplained = 0;
  std::string first_unexplained;
};

// True when the segment from the light to `point` lies between sphere s's
// true shadow cone and the cone through its N-gon's inscribed circle, beyond
// the tangent circle: the only points where the two cones disagree.
inline bool in_ngon_band(const Sphere& s, const glm::dvec3& light, const glm::dvec3& point, int segments) {
  const TangentCircle c = tangent_circle(s.center, s.radius, light);
  const glm::dvec3 axis = glm::normalize(s.center - light);
  const glm::dvec3 to_point = point - light;
  const double along = glm::dot(to_point, axis);
  const double pl = glm::length(c.center - light);
  if (along <= pl) return false;  // in front of the tangent circle: no volume there
  const double tan_angle = glm::length(to_point - along * axis) / along;
  const double inner = c.radius * std::cos(M_PI / segments) / pl;  // apothem of the N-gon
  const double outer = c.radius / pl;
  return tan_angle >= inner && tan_angle <= outer;
}

// The shader finds a sphere's point in float (about 1e-7 of the scene's
// size per operation, and a few operations), so it cannot tell the sign of
// n . l (unit vectors) below about 1e-5: the light then lies in the
// tangent plane to within its rounding, on the sphere's terminator. A
// triangle's side is exact in both, but a shadow ray that leaves it at such
// an angle skims its neighbours, and where it meets them is rounded: in the
// GL's volumes (float) and in the reference's ray (double) alike.
constexpr double kGrazing = 1e-5;

inline bool grazing(const RayHit& hit, const glm::dvec3& light) {
  if (hit.corners[0] && orientation(*hit.corners[0], *hit.corners[1], *hit.corners[2], light) == 0) return false;
  return std::abs(glm::dot(hit.normal, glm::normalize(light - hit.point))) < kGrazing;
}

// Pixels excused on an edge may be at most a quarter of those whose
// footprint straddles a change of the reference's class. Renders that are
// right excuse at most 13.5% of them (two_spheres.scene; most scenes under
// 6%): a pixel whose centre lies within rounding of an edge. A mask shifted
// by a whole pixel differs along every edge, about half of them.
inline bool within_boundary_bound(const MaskComparison& r) { return 4 * r.excused_boundary <= r.boundary_pixels; }

inline MaskComparison compare_with_reference(const Scene& scene, const RenderPlan& plan, const Image& mask,
                                             size_t light) {
  MaskComparison r;
  const int w = mask.width, h = mask.height;
  const glm::dvec3 l = scene.lights[light].position;
  // The reference at every pixel corner, once: corner (i, j) is (i - 0.5, j - 0.5).
  std::vector<uint8_t> corner(size_t(w + 1) * size_t(h + 1));
  for (int j = 0; j <= h; ++j)
    for (int i = 0; i <= w; ++i) corner[size_t(j) * size_t(w + 1) + size_t(i)] = reference_mask_value(scene, w, h, i - 0.5, j - 0.5, light);
  const auto corners_of = [&](int x, int y) {
    const size_t row = size_t(w + 1);
    return std::array<uint8_t, 4>{corner[size_t(y) * row + size_t(x)], corner[size_t(y) * row + size_t(x + 1)],
                                  corner[size_t(y + 1) * row + size_t(x)], corner[size_t(y + 1) * row + size_t(x + 1)]};
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const uint8_t gl = mask.at(x, y);
      const uint8_t ref = reference_mask_value(scene, w, h, x, y, light);
      const std::array<uint8_t, 4> c = corners_of(x, y);
      const bool straddles = c[0] != ref || c[1] != ref || c[2] != ref || c[3] != ref;
      r.boundary_pixels += straddles;
      if (ref != kMaskNoSurface) ++r.surface_pixels;
      if (gl == ref) continue;
      ++r.differing;
      const bool boundary = c[0] == gl || c[1] == gl || c[2] == gl || c[3] == gl;
      if (boundary) {
        ++r.excused_boundary;
        continue;
      }
      const auto hit = nearest_hit(scene, scene.camera.pixel_ray(w, h, x, y));
      bool ngon = false;
      if (hit && gl == kMaskLit && ref == kMaskUnlit)  // the N-gon cone lies inside the true one
        for (const Sphere& s : scene.spheres) ngon = ngon || in_ngon_band(s, l, hit->point, plan.settings.sphere_segments);
      if (ngon) {
        ++r.excused_ngon;
        continue;
      }
      if (hit && grazing(*hit, l)) {
        ++r.excused_grazing;
        continue;
      }
      if (r.unexplained++ == 0) {
        std::ostringstream s;
        s << "pixel (" << x << ", " << y << "): GL " << int(gl) << ", reference " << int(ref);
        r.first_unexplained = s.str();
      }
    }
  return r;
}

// Renders each light's mask at width x height and checks every pixel.
inline void expect_masks_match_reference(Scene scene, int width, int height, int segments, double light_angle = 0.0,
                                         RenderMethod method = RenderMethod::kAuto) {
  rotate_lights_about_z(scene, light_angle);
  require_lights_off_casters(scene);
  RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.sphere_segments = segments;
  settings.method = method;
  const RenderPlan plan = make_render_plan(scene, settings);
  HeadlessContext context(width, height);
  ShadowRenderer renderer(scene, plan);
  for (size_t light = 0; light < scene.lights.size(); ++light) {
    const Image mask = renderer.render_mask(light);
    const MaskComparison r = compare_with_reference(scene, plan, mask, light);
    EXPECT_EQ(r.unexplained, 0) << scene.path << " (" << method_name(method) << ") light " << light + 1 << ": " << r.first_unexplained << " ("
                                << r.differing << " of " << r.surface_pixels << " surface pixels differ, "
                                << r.excused_boundary << " on an edge, " << r.excused_ngon << " in the N-gon band, " << r.excused_grazing
                                << " lit at a grazing angle)";
    EXPECT_TRUE(within_boundary_bound(r)) << scene.path << " (" << method_name(method) << ") light " << light + 1 << ": "
                                          << r.excused_boundary << " pixels excused on an edge, of "
                                          << r.boundary_pixels << " whose footprint straddles one";
    EXPECT_GT(r.surface_pixels, width * height / 10) << "the scene should fill the view";
  }
}

}  // namespace umbra::test
