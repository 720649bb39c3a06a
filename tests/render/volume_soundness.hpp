#pragma once
// Checks every shadow volume a scene's plan holds, for every light.

#include <cmath>

#include <gtest/gtest.h>

#include "render/render_plan.hpp"
#include "silhouette/mesh_caster.hpp"
#include "silhouette/mesh_volume.hpp"
#include "silhouette/volume_topology.hpp"

namespace umbra::test {

// No NaN anywhere; w is 1 (finite) or 0 (at infinity), and a point at
// infinity is a true direction, never (0, 0, 0, 0).
inline void expect_sound_volumes(const Scene& scene) {
  const std::vector<MeshCaster> casters = prepare_mesh_casters(scene);
  const RenderPlan plan = make_render_plan(scene, casters, RenderSettings{});
  for (size_t i = 0; i < plan.lights.size(); ++i) {
    const LightPlan& lp = plan.lights[i];
    for (const glm::dvec4& v : lp.all_volumes.vertices) {
      ASSERT_TRUE(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)) << "light " << i + 1;
      ASSERT_TRUE(v.w == 1.0 || (v.w == 0.0 && (v.x != 0.0 || v.y != 0.0 || v.z != 0.0))) << "light " << i + 1;
    }
    for (const CasterEntry& e : lp.casters) {
      if (!e.volume.triangles.empty()) {
        EXPECT_TRUE(is_closed_and_consistently_oriented(e.volume)) << e.where.str();
      }
    }
    for (const MeshVolumePlan& m : lp.mesh_volumes) {
      const std::vector<glm::dvec3>& positions = scene.meshes[m.mesh].positions;
      for (size_t k = 0; k < m.volume.count; ++k) {
        const uint32_t index = m.volume.buffer[k];
        ASSERT_LT(index, 2 * positions.size());
        if (index >= positions.size()) {
          ASSERT_NE(positions[index - positions.size()], scene.lights[i].position) << "a (0, 0, 0, 0) vertex";
        }
      }
      const ShadowVolume volume = mesh_caster_volume(casters[m.mesh], scene.lights[i].position);
      EXPECT_TRUE(has_no_boundary(volume)) << "light " << i + 1;
    }
  }
}

}  // namespace umbra::test
