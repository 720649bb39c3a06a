#pragma once
// What a frame will draw, derived from the scene and the settings before any
// GL call: the camera, and per light each caster's shadow volume. `umbra
// render --explain` prints it.

#include <cmath>
#include <limits>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "render/render_method.hpp"
#include "render/render_settings.hpp"
#include "scene/scene.hpp"

#include "silhouette/mesh_caster.hpp"
#include "silhouette/mesh_volume.hpp"
#include "silhouette/shadow_volume.hpp"

namespace umbra {

// What a light's plan is made from besides the scene's casters: a frame
// whose inputs compare equal to the plan's (a paused viewer, or a light that
// stays while another moves) keeps the plan as it is.
struct LightPlanInputs {
  glm::dvec3 light{0.0};
  Camera camera;
  double near_plane = 0.0;
  RenderSettings settings;

  bool operator==(const LightPlanInputs&) const = default;
};

struct CasterEntry {
  std::string kind;    // "sphere", "triangle" or "mesh"
  FileLoc where;
  std::string volume_phrase;  // how its volume was made, or why it has none
  ShadowVolume volume;  // empty when it casts no shadow from this light, or when it is a mesh_volume
  // For a mesh (but with --method triangles): its volume is
  // LightPlan::mesh_volumes[mesh_volume].
  int mesh_volume = -1;
};

// A mesh's volume as indices over its static vertex buffer.
struct MeshVolumePlan {
  size_t mesh = 0;  // index into Scene::meshes
  MeshVolumeIndices volume;
};

// What the planar method (Blinn 1988) projects, for one light: the
// receivers' planes (n, d), each with the light on its positive side, and
// the casters' finite triangles (a sphere's N-gon disc, a triangle, a mesh's
// triangles) to flatten onto each. No volumes, no counts.
struct PlanarProjection {
  std::vector<glm::dvec4> receiver_planes;
  ShadowVolume casters;  // light caps only: every vertex finite
};

enum class DepthCount { kWhereDepthPasses, kWhereDepthFails };

struct LightPlan {
  std::vector<CasterEntry> casters;
  ShadowVolume all_volumes;                  // every other caster's volume, one draw call
  std::vector<MeshVolumePlan> mesh_volumes;  // one draw call each
  // Where the light's volumes are counted: where the depth test passes
  // (z-pass, Heidmann 1991), right only where the near-plane rectangle is
  // outside every volume, or where it fails (z-fail, Everitt and Kilgard
  // 2002), right everywhere.
  DepthCount count = DepthCount::kWhereDepthFails;
  // Whether the volumes above are closed by caps: z-fail counts them where
  // a volume passes behind a surface, and needs them; z-pass never meets
  // them in front of one, and goes without.
  bool capped() const { return count == DepthCount::kWhereDepthFails; }
  std::string count_reason;  // why this light is counted as it is
  // The volumes run from each caster point P to L + volume_reach (P - L),
  // past every surface they can shadow (volume_reach.hpp); infinity: to
  // infinity, w = 0.
  double volume_reach = std::numeric_limits<double>::infinity();
  int culled_casters = 0;    // casters whose volumes cannot reach the view (auto only)
  PlanarProjection planar;  // kPlanar's plan, which counts no volumes; empty for every other method
  int side_quads = 0, light_cap_triangles = 0, dark_cap_triangles = 0;  // of all of them
  std::optional<LightPlanInputs> made_for;  // none until it is first made
};

struct RenderPlan {
  RenderSettings settings;
  Camera camera;
  bool camera_is_spec_default = true;
  double near_plane = 0.05;  // near_plane(camera, aspect, the surfaces' bounds, the nearest surface's distance)
  double far_plane = 0.0;    // orthographic: far_plane(camera, the surfaces' bounds); perspective: at infinity
  // The camera's projection for the picture's shape, with these planes.
  glm::dmat4 projection() const { return camera.projection(double(settings.width) / settings.height, near_plane, far_plane); }
  // The view the near plane was worked out for: a camera and its aspect.
  std::optional<std::pair<Camera, double>> near_plane_view;
  // Shading terms that some material and light use; the shader skips the
  // specular term when none does, and a frame draws neither the shadows nor
  // the direct pass of a light with no colour (its ambient term is in the
  // first pass; its mask is still drawn on request).
  bool specular_used = true;
  std::vector<uint8_t> light_adds_direct;  // per light
  std::vector<LightPlan> lights;  // one per scene light, same order
  MeshCasterScratch mesh_scratch;  // the face classification, kept so that a frame need not allocate it
};

// One caster per scene.meshes entry, in order, each sharing its mesh's
// points: made once per scene and kept across frames.
std::vector<MeshCaster> prepare_mesh_casters(const Scene& scene);

// Requires the lights outside every sphere (require_lights_off_casters).
// `meshes` is prepare_mesh_casters(scene), made once and kept across frames.
RenderPlan make_render_plan(const Scene& scene, const std::vector<MeshCaster>& meshes, const RenderSettings& settings);
// The same for one frame: prepares the mesh casters itself.
RenderPlan make_render_plan(const Scene& scene, const RenderSettings& settings);
// An InputError when `scene` has a shadow catcher that `method` cannot keep
// the shadows of (keeps_caught_shadows).
void require_caught_shadows_kept(const Scene& scene, RenderMethod method);
// The next frame of an animation: recomputes every light's volumes for the
// scene as it is now (its lights moved), keeping the plan's settings and
// reusing its buffers, so that mesh volumes cost only classification and
// extraction.
void update_render_plan(const Scene& scene, const std::vector<MeshCaster>& meshes, RenderPlan& plan);
// update_render_plan in its two parts. The view: the camera, the near plane
// and which lights add direct light, all that a frame's first pass reads.
void update_render_view(const Scene& scene, RenderPlan& plan);
// Then every light's volumes, for the view as it now is: a viewer runs this
// while the GL draws the first pass (ShadowRenderer::draw).
void update_render_lights(const Scene& scene, const std::vector<MeshCaster>& meshes, RenderPlan& plan);

// "800x800, 3 x 3 samples per pixel, averaged (--antialias)"
std::string image_phrase(const RenderSettings& settings);

void print_render_plan(std::ostream& out, const Scene& scene, const RenderPlan& plan);

}  // namespace umbra
