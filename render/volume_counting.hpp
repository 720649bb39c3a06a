#pragma once
// How a light's shadow volumes are counted: which casters auto leaves out
// (their volumes cannot reach the view), and z-pass or z-fail, by whether
// any kept caster may shadow the near plane, with the reason --explain says.

#include <cstdint>
#include <vector>

#include "render/render_plan.hpp"
#include "render/view_culling.hpp"

namespace umbra {

// Which casters auto leaves out, and whether a light may be counted with
// z-pass: none of its kept casters can put the near-plane rectangle in shadow.
struct LightCulling {
  std::vector<uint8_t> spheres, triangles, meshes;  // 1: left out
  int culled = 0;
  const FileLoc* shadows_near_plane = nullptr;  // the first caster that may
};

LightCulling cull_for_light(const Scene& scene, const RenderPlan& plan, const NearRectangle& near, const glm::dvec3& light);
// The box round the casters a light's volumes are made from: those not left out.
SceneBounds kept_casters_box(const Scene& scene, const LightCulling& c);
// Decides z-pass or z-fail for a light and says why.
void choose_count(RenderMethod method, bool orthographic, const LightCulling& c, LightPlan& lp);

}  // namespace umbra
