// The render plan across frames: updating it for a moved light gives the
// plan made afresh, without reallocating the mesh volumes' index buffers.
#include <gtest/gtest.h>

#include <sstream>

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

TEST(RenderPlan, SplitsMoreThan255VolumesIntoStencilBatches) {
  // 600 level triangles over one point (8 volume triangles each) and one
  // degenerate triangle (no volume): batches end after volumes 255 and 510.
  std::string text = "light 0 0 2\ntriangle 0 0 0  1 0 0  2 0 0\n";
  for (int k = 0; k < 600; ++k) text += "triangle -0.1 -0.1 " + std::to_string(k * 0.001) + "  0.1 -0.1 " +
                                        std::to_string(k * 0.001) + "  0 0.1 " + std::to_string(k * 0.001) + "\n";
  const RenderPlan plan = make_render_plan(parse_scene_text(text, "many.scene"), RenderSettings{});
  EXPECT_EQ(plan.lights[0].stencil_batch_ends, (std::vector<uint32_t>{255 * 8, 510 * 8, 600 * 8}));
  std::ostringstream out;
  print_render_plan(out, parse_scene_text(text, "many.scene"), plan);
  EXPECT_NE(out.str().find("counted in 3 stencil batches (at most 255 sphere and triangle volumes each, and one per "
                           "mesh), so that no count wraps to zero\n"),
            std::string::npos)
      << out.str();

  const RenderPlan small = make_render_plan(parse_scene_text("light 0 0 2\nsphere 0 0 0 0.5\n", "one.scene"), RenderSettings{});
  EXPECT_EQ(small.lights[0].stencil_batch_ends, (std::vector<uint32_t>{uint32_t(small.lights[0].all_volumes.triangles.size())}));
}

}  // namespace
}  // namespace umbra
