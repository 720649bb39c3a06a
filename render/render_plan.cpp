#include "render/render_plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <utility>

#include "mesh/predicates/orientation.hpp"
#include "scene/camera.hpp"
#include "render/planar_receivers.hpp"
#include "render/view_culling.hpp"
#include "render/volume_reach.hpp"
#include "silhouette/sphere_volume.hpp"
#include "silhouette/triangle_volume.hpp"

namespace umbra {
namespace {

CasterEntry sphere_entry(const Sphere& s, const Light& light, int segments) {
  CasterEntry e{"sphere", s.where, "", sphere_volume(s.center, s.radius, light.position, segments)};
  e.volume_phrase = "tangent-circle " + std::to_string(segments) + "-gon";
  return e;
}

CasterEntry triangle_entry(const Triangle& t, const Light& light) {
  CasterEntry e{"triangle", t.where, "", {}};
  if (collinear(t.a, t.b, t.c)) {
    e.volume_phrase = "none: degenerate (collinear vertices)";
  } else if (auto volume = triangle_volume(t.a, t.b, t.c, light.position)) {
    e.volume = std::move(*volume);
    e.volume_phrase = "three side quads";
  } else {
    e.volume_phrase = "none: its plane contains the light, so it is seen edge-on";
  }
  return e;
}

// A mesh's entry. Its volume goes to light_plan.mesh_volumes[slot], whose
// index buffer is kept from the previous frame when there is one; with
// --method triangles, every triangle's own volume instead.
CasterEntry mesh_entry(const Scene& scene, size_t index, const MeshCaster& caster, const Light& light, LightPlan& light_plan,
                       size_t& slot, MeshCasterScratch& scratch, bool per_triangle_asked) {
  const Mesh& mesh = scene.meshes[index];
  CasterEntry e{"mesh", mesh.where, "", {}};
  const std::string triangles = std::to_string(mesh.triangles.size()) + " triangles";
  if (per_triangle_asked) {
    e.volume = per_triangle_volume(mesh.positions, mesh.triangles, light.position);
    e.volume_phrase = "per-triangle volumes, the slow reference (--method triangles; " + triangles + ")";
    return e;
  }
  if (slot == light_plan.mesh_volumes.size()) light_plan.mesh_volumes.emplace_back();
  MeshVolumePlan& volume = light_plan.mesh_volumes[slot];
  volume.mesh = index;
  e.mesh_volume = int(slot++);
  mesh_caster_volume_indices(caster, light.position, scratch, volume.volume, light_plan.capped());
  e.volume_phrase = caster.phrase() + " (" + triangles + ")";
  return e;
}

// Every sphere's and triangle's volume in lp.all_volumes, in file order: one
// draw call (the meshes' volumes are drawn from their own buffers).
void gather_volumes(LightPlan& lp) {
  for (const CasterEntry& e : lp.casters)
    if (e.mesh_volume < 0) append_volume(lp.all_volumes, e.volume, lp.capped());
}

CasterEntry culled_entry(const char* kind, const FileLoc& where) {
  return {kind, where, "none: its shadow volume cannot reach the view", {}};
}

// Which casters auto leaves out, and whether a light may be counted with
// z-pass: none of its kept casters can put the near-plane rectangle in shadow.
struct LightCulling {
  std::vector<uint8_t> spheres, triangles, meshes;  // 1: left out
  int culled = 0;
  const FileLoc* shadows_near_plane = nullptr;  // the first caster that may
};

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

// Empties a light's sphere and triangle volumes (not its mesh volumes).
void clear_volumes(LightPlan& lp) {
  lp.all_volumes.vertices.clear();
  lp.all_volumes.triangles.clear();
  lp.all_volumes.side_quads = lp.all_volumes.light_cap_triangles = lp.all_volumes.dark_cap_triangles = 0;
  lp.side_quads = lp.light_cap_triangles = lp.dark_cap_triangles = 0;
}

// Planar projection: which planes receive, and what is projected onto them.
void plan_planar_light(const Scene& scene, const std::vector<ReceiverPlane>& receivers, int segments, const Light& light,
                       LightPlan& lp) {
  clear_volumes(lp);
  lp.mesh_volumes.clear();
  lp.count = DepthCount::kWhereDepthFails;  // nothing is counted: the volumes' defaults
  lp.culled_casters = 0;
  std::string lines;
  int planes = 0;
  for (const ReceiverPlane& r : receivers) {
    const Triangle& t = scene.triangles[r.first_triangle];
    if (orientation(t.a, t.b, t.c, light.position) == 0) continue;  // the light in the plane (exactly): no shadow on it
    const double height = glm::dot(r.plane, glm::dvec4(light.position, 1.0));
    lp.planar.receiver_planes.push_back(height > 0.0 ? r.plane : -r.plane);
    ++planes;
    for (const int line : r.lines) lines += (lines.empty() ? "" : ", ") + std::to_string(line);
  }
  lp.count_reason = "no volume count: every caster projected onto " + std::to_string(planes) +
                    " receiver plane(s) (triangles at lines " + (lines.empty() ? std::string("none") : lines) +
                    "); spheres and meshes receive no shadow";
  const auto add = [&](const char* kind, const FileLoc& where, const std::string& method, const ShadowVolume& v) {
    lp.casters.push_back({kind, where, "projected (Blinn 1988): " + method, {}});
    ShadowVolume finite;  // the triangles whose vertices are all finite (the light cap), and only their vertices
    std::vector<uint32_t> index(v.vertices.size(), UINT32_MAX);
    for (size_t k = 0; k < v.vertices.size(); ++k)
      if (v.vertices[k].w == 1.0) index[k] = uint32_t(finite.vertices.size()), finite.vertices.push_back(v.vertices[k]);
    for (const auto& t : v.triangles)
      if (index[t[0]] != UINT32_MAX && index[t[1]] != UINT32_MAX && index[t[2]] != UINT32_MAX)
        finite.triangles.push_back({index[t[0]], index[t[1]], index[t[2]]});
    append_volume(lp.planar.casters, finite);
  };
  for (const Sphere& s : scene.spheres)
    add("sphere", s.where, "its tangent " + std::to_string(segments) + "-gon disc",
        sphere_volume(s.center, s.radius, light.position, segments));
  for (const Triangle& t : scene.triangles) {
    ShadowVolume v;
    v.vertices = {glm::dvec4(t.a, 1.0), glm::dvec4(t.b, 1.0), glm::dvec4(t.c, 1.0)};
    v.triangles = {{0, 1, 2}};
    add("triangle", t.where, "the triangle", v);
  }
  for (const Mesh& m : scene.meshes) {
    ShadowVolume v;
    for (const glm::dvec3& p : m.positions) v.vertices.emplace_back(p, 1.0);
    v.triangles = m.triangles;
    add("mesh", m.where, "its " + std::to_string(m.triangles.size()) + " triangles", v);
  }
  std::stable_sort(lp.casters.begin(), lp.casters.end(),
                   [](const CasterEntry& a, const CasterEntry& b) { return a.where.line < b.where.line; });
}

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
