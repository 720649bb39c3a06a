#pragma once
// What a frame will draw, derived from the scene and the settings before any
// GL call: the camera, and per light each caster's shadow volume. `umbra
// render --explain` prints it.

#include <ostream>
#include <string>
#include <vector>

#include "mesh/scene.hpp"
#include "silhouette/shadow_volume.hpp"

namespace umbra {

struct RenderSettings {
  int width = 800;
  int height = 800;
  int sphere_segments = 64;  // N of the spec's N-gon (spec 2.2)
};

struct CasterEntry {
  std::string kind;    // "sphere" or "triangle"
  FileLoc where;
  std::string method;  // how its volume was made, or why it has none
  ShadowVolume volume;  // empty when it casts no shadow from this light
};

struct LightPlan {
  std::vector<CasterEntry> casters;
  ShadowVolume all_volumes;  // every caster's volume, one draw call
};

struct RenderPlan {
  RenderSettings settings;
  Camera camera;
  bool camera_is_spec_default = true;
  std::vector<LightPlan> lights;  // one per scene light, same order
};

// Requires the lights outside every sphere (require_lights_outside_spheres).
RenderPlan make_render_plan(const Scene& scene, const RenderSettings& settings);

void print_render_plan(std::ostream& out, const Scene& scene, const RenderPlan& plan);

}  // namespace umbra
