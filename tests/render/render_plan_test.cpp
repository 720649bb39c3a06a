// The render plan across frames: updating it for a moved light gives the
// plan made afresh, without reallocating the mesh volumes' index buffers.
#include <gtest/gtest.h>

#include "mesh/scene_parser.hpp"
#include "render/render_plan.hpp"

namespace umbra {
namespace {

TEST(RenderPlan, UpdateForAMovedLightEqualsAFreshPlanAndReusesTheIndexBuffers) {
  Scene scene = parse_scene_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/mesh_open_box.scene");
  const std::vector<MeshCaster> casters = prepare_mesh_casters(scene);
  RenderPlan plan = make_render_plan(scene, casters, RenderSettings{});
  ASSERT_EQ(plan.lights[0].mesh_volumes.size(), 1u);  // the pair; the open box uses per-triangle volumes
  const uint32_t* buffer = plan.lights[0].mesh_volumes[0].volume.buffer.data();

  rotate_lights_about_z(scene, 40.0);
  update_render_plan(scene, casters, plan);
  const RenderPlan fresh = make_render_plan(scene, casters, RenderSettings{});
  const MeshVolumeIndices& updated = plan.lights[0].mesh_volumes[0].volume;
  const MeshVolumeIndices& expected = fresh.lights[0].mesh_volumes[0].volume;
  ASSERT_EQ(updated.count, expected.count);
  EXPECT_TRUE(std::equal(updated.buffer.begin(), updated.buffer.begin() + std::ptrdiff_t(updated.count), expected.buffer.begin()));
  EXPECT_EQ(updated.buffer.data(), buffer) << "the index buffer was reallocated";
  EXPECT_EQ(plan.lights[0].all_volumes.triangles, fresh.lights[0].all_volumes.triangles);
  EXPECT_EQ(plan.lights[0].side_quads, fresh.lights[0].side_quads);
  ASSERT_EQ(plan.lights[0].casters.size(), fresh.lights[0].casters.size());
  for (size_t i = 0; i < plan.lights[0].casters.size(); ++i)
    EXPECT_EQ(plan.lights[0].casters[i].method, fresh.lights[0].casters[i].method);
}

}  // namespace
}  // namespace umbra
