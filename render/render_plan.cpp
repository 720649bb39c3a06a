#include "render/render_plan.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "scene/camera.hpp"
#include "render/caster_entries.hpp"
#include "render/planar_receivers.hpp"
#include "render/volume_counting.hpp"
#include "render/view_culling.hpp"
#include "render/volume_reach.hpp"

namespace umbra {
namespace {

// The scene's camera and its near plane, which is worked out again only when
// the view changes (a viewer whose light moves keeps it): with the eye inside
// a mesh's box it takes a pass over the mesh's triangles.
void place_camera(const Scene& scene, RenderPlan& plan) {
  const Camera& c = scene.camera;
  const double aspect = double(plan.settings.width) / plan.settings.height;
  const std::pair<Camera, double> view{c, aspect};
  plan.camera = c;
  if (view == plan.near_plane_view) return;
  plan.near_plane_view = view;
  const SceneBounds bounds = surface_bounds(scene);
  plan.near_plane = near_plane(c, aspect, bounds, nearest_surface_distance(scene, c.eye));
  plan.far_plane = c.orthographic() ? far_plane(c, bounds) : 0.0;
}

}  // namespace

std::vector<MeshCaster> prepare_mesh_casters(const Scene& scene) {
  std::vector<MeshCaster> casters;
  casters.reserve(scene.meshes.size());
  for (const Mesh& mesh : scene.meshes) {
    casters.push_back(prepare_mesh_caster(mesh.positions, mesh.triangles, mesh.edges, mesh.components));
    if (!mesh.loading_changes.empty()) casters.back().shape += " (" + mesh.loading_changes + ")";
  }
  return casters;
}

void require_caught_shadows_kept(const Scene& scene, RenderMethod method) {
  if (keeps_caught_shadows(method)) return;
  for (const Material& m : scene.materials)
    if (m.shadow_catcher)
      throw InputError({scene.path}, "material \"" + m.name + "\" is a shadow catcher, whose shadows --method " + method_name(method) +
                                         " cannot keep (it marks them in the stencil): use another method");
}

RenderPlan make_render_plan(const Scene& scene, const RenderSettings& settings) {
  RenderPlan plan;
  plan.settings = settings;
  update_render_plan(scene, prepare_mesh_casters(scene), plan);
  return plan;
}

RenderPlan make_render_plan(const Scene& scene, const std::vector<MeshCaster>& meshes, const RenderSettings& settings) {
  RenderPlan plan;
  plan.settings = settings;
  update_render_plan(scene, meshes, plan);
  return plan;
}

void update_render_plan(const Scene& scene, const std::vector<MeshCaster>& meshes, RenderPlan& plan) {
  update_render_view(scene, plan);
  update_render_lights(scene, meshes, plan);
}

void update_render_view(const Scene& scene, RenderPlan& plan) {
  place_camera(scene, plan);
  plan.camera_is_spec_default = !scene.camera_from.has_value();
  plan.lights.resize(scene.lights.size());
  plan.specular_used = false;
  plan.light_adds_direct.assign(scene.lights.size(), 0);
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const glm::dvec3& c = scene.lights[i].color;
    plan.light_adds_direct[i] = c.x > 0.0 || c.y > 0.0 || c.z > 0.0;
    for (const Material& m : scene.materials)
      plan.specular_used = plan.specular_used || (plan.light_adds_direct[i] && (m.specular.x > 0.0 || m.specular.y > 0.0 || m.specular.z > 0.0));
  }
}

void update_render_lights(const Scene& scene, const std::vector<MeshCaster>& meshes, RenderPlan& plan) {
  MeshCasterScratch& scratch = plan.mesh_scratch;
  // The same for every light.
  const ShadowPass pass = method_pass(plan.settings.method);
  const std::vector<ReceiverPlane> receivers = pass == ShadowPass::kPlanar ? receiver_planes(scene) : std::vector<ReceiverPlane>{};
  const NearRectangle near = near_rectangle(plan.camera, double(plan.settings.width) / plan.settings.height, plan.near_plane);
  // What the volumes must be exact in: every surface and the near plane.
  SceneBounds region = surface_bounds(scene);
  for (const glm::dvec3& corner : near.corners) region.grow({corner, corner});
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& light = scene.lights[i];
    LightPlan& lp = plan.lights[i];
    const LightPlanInputs inputs{light.position, plan.camera, plan.near_plane, plan.settings};
    if (lp.made_for == inputs) continue;
    lp.made_for = inputs;
    lp.casters.clear();
    lp.planar = {};
    if (pass == ShadowPass::kShadowMap) {  // no volumes at all
      clear_volumes(lp);
      lp.mesh_volumes.clear();
      lp.count = DepthCount::kWhereDepthFails;  // nothing is counted: the volumes' defaults
      lp.culled_casters = 0;
      lp.count_reason = "no volume count: a cube shadow map of 6 x " + std::to_string(plan.settings.shadow_map_size) + "^2 " +
                        "distances (Williams 1978), biased by two texels";
      continue;
    }
    if (pass == ShadowPass::kPlanar) {
      plan_planar_light(scene, receivers, plan.settings.sphere_segments, light, lp);
      continue;
    }
    const LightCulling culling = cull_for_light(scene, plan, near, light.position);
    lp.culled_casters = culling.culled;
    choose_count(plan.settings.method, plan.camera.orthographic(), culling, lp);
    lp.volume_reach = volume_reach(light.position, kept_casters_box(scene, culling), region);
    if (std::isinf(lp.volume_reach) && plan.camera.orthographic())  // no orthographic picture holds infinity
      lp.volume_reach = finite_volume_reach(light.position, region, nearest_surface_distance(scene, light.position));
    const bool per_triangle = casts_per_triangle(plan.settings.method);
    size_t slot = 0;
    for (size_t k = 0; k < scene.spheres.size(); ++k) {
      const Sphere& s = scene.spheres[k];
      lp.casters.push_back(culling.spheres[k] ? culled_entry("sphere", s.where)
                                              : sphere_entry(s, light, plan.settings.sphere_segments));
    }
    for (size_t k = 0; k < scene.triangles.size(); ++k) {
      const Triangle& t = scene.triangles[k];
      lp.casters.push_back(culling.triangles[k] ? culled_entry("triangle", t.where) : triangle_entry(t, light));
    }
    for (size_t m = 0; m < scene.meshes.size(); ++m)
      lp.casters.push_back(culling.meshes[m] ? culled_entry("mesh", scene.meshes[m].where)
                                             : mesh_entry(scene, m, meshes[m], light, lp, slot, scratch, per_triangle));
    lp.mesh_volumes.resize(slot);
    std::stable_sort(lp.casters.begin(), lp.casters.end(),  // file order, for --explain
                     [](const CasterEntry& a, const CasterEntry& b) { return a.where.line < b.where.line; });
    clear_volumes(lp);
    gather_volumes(lp);
    lp.side_quads = lp.all_volumes.side_quads;
    lp.light_cap_triangles = lp.all_volumes.light_cap_triangles;
    lp.dark_cap_triangles = lp.all_volumes.dark_cap_triangles;
    for (const MeshVolumePlan& m : lp.mesh_volumes) {
      lp.side_quads += m.volume.side_quads;
      if (!lp.capped()) continue;
      lp.light_cap_triangles += m.volume.light_cap_triangles;
      lp.dark_cap_triangles += m.volume.dark_cap_triangles;
    }
  }
}

}  // namespace umbra
