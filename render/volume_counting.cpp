#include "render/volume_counting.hpp"

#include <string>

namespace umbra {

LightCulling cull_for_light(const Scene& scene, const RenderPlan& plan, const NearRectangle& near, const glm::dvec3& light) {
  LightCulling c;
  const RenderMethod method = plan.settings.method;
  const bool cull = culls_casters(method);
  // Only auto's choice and forced z-pass's warning need the near plane.
  const VolumeCounting counting = method_counting(method);
  const bool test_near_plane = counting == VolumeCounting::kPerLight || counting == VolumeCounting::kZPass;
  // `near_test` decides more closely than the ball where a caster can (a triangle's plane).
  const auto visit = [&](const BoundingSphere& ball, const FileLoc& where, std::vector<uint8_t>& out, const auto& near_test) {
    const bool left_out = cull && !volume_may_reach_view(plan.camera, near, light, ball);
    out.push_back(left_out);
    c.culled += left_out;
    if (test_near_plane && !left_out && !c.shadows_near_plane && may_shadow_near_rectangle(near, light, ball) && near_test())
      c.shadows_near_plane = &where;
  };
  const auto unsure = [] { return true; };
  for (const Sphere& s : scene.spheres) visit(bounding_sphere(s), s.where, c.spheres, unsure);
  for (const Triangle& t : scene.triangles)
    visit(bounding_sphere(t), t.where, c.triangles, [&] { return triangle_may_shadow_near_rectangle(near, light, t); });
  for (const Mesh& m : scene.meshes) visit(bounding_sphere(m), m.where, c.meshes, unsure);
  return c;
}

// The box round the casters a light's volumes are made from: those not left out.
SceneBounds kept_casters_box(const Scene& scene, const LightCulling& c) {
  SceneBounds box;
  for (size_t k = 0; k < scene.spheres.size(); ++k)
    if (!c.spheres[k]) box.grow(surface_bounds(scene.spheres[k]));
  for (size_t k = 0; k < scene.triangles.size(); ++k)
    if (!c.triangles[k]) box.grow(surface_bounds(scene.triangles[k]));
  for (size_t k = 0; k < scene.meshes.size(); ++k)
    if (!c.meshes[k]) box.grow(surface_bounds(scene.meshes[k]));
  return box;
}

// Decides z-pass or z-fail for a light and says why.
void choose_count(RenderMethod method, bool orthographic, const LightCulling& c, LightPlan& lp) {
  const std::string near_plane_hit =
      c.shadows_near_plane ? "the caster at line " + std::to_string(c.shadows_near_plane->line) + " may shadow the near plane"
                           : "the near plane is outside every volume";
  switch (method_counting(method)) {
    case VolumeCounting::kZPass:
      lp.count = DepthCount::kWhereDepthPasses;
      lp.count_reason = std::string("z-pass without caps (--method ") + method_name(method) + ")";
      if (c.shadows_near_plane) lp.count_reason += "; may be wrong here: " + near_plane_hit;
      return;
    case VolumeCounting::kPerLight:
      if (orthographic) {  // volume parts behind its eye's plane clamp to depth 0, which z-pass would count
        lp.count = DepthCount::kWhereDepthFails;
        lp.count_reason = "z-fail with caps: the camera is orthographic";
        return;
      }
      lp.count = c.shadows_near_plane ? DepthCount::kWhereDepthFails : DepthCount::kWhereDepthPasses;
      lp.count_reason = lp.capped() ? "z-fail with caps: " + near_plane_hit : "z-pass without caps: " + near_plane_hit;
      return;
    case VolumeCounting::kZFail:
    case VolumeCounting::kNone:  // not reached: such a method's pass counts nothing
      lp.count = DepthCount::kWhereDepthFails;
      lp.count_reason = std::string("z-fail with caps (--method ") + method_name(method) + ")";
  }
}

}  // namespace umbra
