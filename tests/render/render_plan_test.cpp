// The render plan across frames: updating it for a moved light gives the
// plan made afresh, without reallocating the mesh volumes' index buffers.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include <glm/trigonometric.hpp>

#include "scene/scene_parser.hpp"
#include "render/planar_receivers.hpp"
#include "scene/camera.hpp"
#include "render/render_plan.hpp"

namespace umbra {
namespace {

TEST(RenderPlan, UpdateForAMovedLightEqualsAFreshPlanAndReusesTheIndexBuffers) {
  Scene scene = parse_scene_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/mesh_open_box.scene");
  const std::vector<MeshCaster> casters = prepare_mesh_casters(scene);
  RenderPlan plan = make_render_plan(scene, casters, RenderSettings{});
  ASSERT_EQ(plan.lights[0].mesh_volumes.size(), 2u);  // the open box and the pair
  // The buffers only grow: once they have held the volumes at 40 degrees,
  // going back to 0 and forth again reallocates nothing.
  rotate_lights_about_z(scene, 40.0);
  update_render_plan(scene, casters, plan);
  rotate_lights_about_z(scene, -40.0);
  update_render_plan(scene, casters, plan);
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
    EXPECT_EQ(plan.lights[0].casters[i].volume_phrase, fresh.lights[0].casters[i].volume_phrase);
}

TEST(RenderPlan, AFrameThatChangesNothingForALightKeepsItsPlanAndAnyChangeRemakesIt) {
  Scene scene = parse_scene_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/mesh_open_box.scene");
  scene.lights.push_back(scene.lights[0]);
  scene.lights[1].position.z += 0.5;
  const std::vector<MeshCaster> casters = prepare_mesh_casters(scene);
  RenderPlan plan = make_render_plan(scene, casters, RenderSettings{});
  const std::string reason = plan.lights[0].count_reason;
  // A marker in each light's plan shows whether the next update remade it.
  const auto mark = [&plan] { plan.lights[0].count_reason = plan.lights[1].count_reason = "kept"; };
  mark();
  update_render_plan(scene, casters, plan);
  EXPECT_EQ(plan.lights[0].count_reason, "kept");
  EXPECT_EQ(plan.lights[1].count_reason, "kept");
  scene.lights[1].position.x += 0.1;  // only the second light moves
  update_render_plan(scene, casters, plan);
  EXPECT_EQ(plan.lights[0].count_reason, "kept");
  EXPECT_NE(plan.lights[1].count_reason, "kept");
  mark();
  scene.camera.eye.x += 0.2;  // the view changes what auto culls and how it counts
  update_render_plan(scene, casters, plan);
  EXPECT_EQ(plan.lights[0].count_reason, reason);
  EXPECT_NE(plan.lights[1].count_reason, "kept");
  mark();
  plan.settings.method = RenderMethod::kZPass;
  update_render_plan(scene, casters, plan);
  EXPECT_NE(plan.lights[0].count_reason, "kept");
  // Every setting is an input of the plan, not only the method.
  mark();
  plan.settings.shadow_map_size = 512;
  update_render_plan(scene, casters, plan);
  EXPECT_NE(plan.lights[0].count_reason, "kept");
  mark();
  plan.settings.sphere_segments = 32;
  update_render_plan(scene, casters, plan);
  EXPECT_NE(plan.lights[1].count_reason, "kept");
}

// A floor far larger than the view has a bounding ball round the eye; its
// plane shows that its volume lies below it, so auto still counts with z-pass.
// A triangle between the light and the eye puts the eye in its volume: z-fail.
TEST(RenderPlan, AutoDecidesByATrianglesPlaneWhetherItsVolumeCanReachTheNearPlane) {
  const std::string light_and_floor = "light 0 0 3\ntriangle -1000 -1000 -1  1000 -1000 -1  1000 1000 -1\n";
  const RenderPlan floor = make_render_plan(parse_scene_text(light_and_floor, "floor.scene"), RenderSettings{});
  EXPECT_EQ(floor.lights[0].count, DepthCount::kWhereDepthPasses) << floor.lights[0].count_reason;
  const RenderPlan ceiling =
      make_render_plan(parse_scene_text(light_and_floor + "triangle -1000 -1000 3.2  1000 -1000 3.2  1000 1000 3.2\n", "ceiling.scene"),
                       RenderSettings{});
  EXPECT_EQ(ceiling.lights[0].count, DepthCount::kWhereDepthFails);
  EXPECT_EQ(ceiling.lights[0].count_reason, "z-fail with caps: the caster at line 3 may shadow the near plane");
}

TEST(RenderPlan, CountsEveryVolumeTogetherHowEverManyOverlap) {
  // 600 level triangles over one point (8 volume triangles each, with z-fail's
  // caps) and one degenerate triangle (no volume): all 600 volumes in one
  // buffer, in file order, counted in one pass; no bound on their layers.
  std::string text = "light 0 0 2\ntriangle 0 0 0  1 0 0  2 0 0\n";
  for (int k = 0; k < 600; ++k) text += "triangle -0.1 -0.1 " + std::to_string(k * 0.001) + "  0.1 -0.1 " +
                                        std::to_string(k * 0.001) + "  0 0.1 " + std::to_string(k * 0.001) + "\n";
  RenderSettings zfail;
  zfail.method = RenderMethod::kZFail;
  const Scene scene = parse_scene_text(text, "many.scene");
  const RenderPlan plan = make_render_plan(scene, zfail);
  const LightPlan& lp = plan.lights[0];
  EXPECT_EQ(lp.all_volumes.triangles.size(), 600u * 8);
  EXPECT_EQ(lp.side_quads, 600 * 3);
  EXPECT_EQ(lp.light_cap_triangles, 600);
  EXPECT_EQ(lp.dark_cap_triangles, 600);
  // The first volume is the second triangle's (line 3): its light cap is the triangle itself.
  EXPECT_EQ(glm::dvec3(lp.all_volumes.vertices[lp.all_volumes.triangles[0][0]]), glm::dvec3(-0.1, -0.1, 0.0));
  EXPECT_EQ(lp.casters[0].volume_phrase, "none: degenerate (collinear vertices)");
}

TEST(PlanarReceivers, CoplanarTrianglesAreOnePlaneAndDegenerateOnesNone) {
  const Scene scene = parse_scene_text(
      "light 0 0 2\n"
      "triangle -1 -1 -1  1 -1 -1  1 1 -1\n"
      "triangle -1 -1 -1  1 1 -1  -1 1 -1\n"
      "triangle -1 -1 -1  -1 1 -1  -1 1 1\n"
      "triangle 0 0 0  1 1 1  2 2 2\n"
      "triangle 1 1 -1  -1 -1 -1  -1 1 -1\n",  // the floor again, wound the other way
      "planes.scene");
  const std::vector<ReceiverPlane> planes = receiver_planes(scene);
  ASSERT_EQ(planes.size(), 2u);
  EXPECT_EQ(planes[0].lines, (std::vector<int>{2, 3, 6}));
  EXPECT_EQ(planes[0].plane, glm::dvec4(0, 0, 1, 1));  // z = -1
  EXPECT_EQ(planes[1].lines, (std::vector<int>{4}));
  EXPECT_EQ(planes[1].plane, glm::dvec4(1, 0, 0, 1));  // x = -1
}

TEST(PlanarReceivers, TheShadowMatrixProjectsAlongTheLightRay) {
  // Light (0, 0, 2), floor z = -1: (0.5, 0, 0) is 2 below the light of 3,
  // so it lands at 1.5 times its offset: (0.75, 0, -1).
  const glm::dvec4 p = planar_shadow_matrix({0, 0, 1, 1}, {0, 0, 2}) * glm::dvec4(0.5, 0, 0, 1);
  EXPECT_DOUBLE_EQ(p.x / p.w, 0.75);
  EXPECT_DOUBLE_EQ(p.y / p.w, 0.0);
  EXPECT_DOUBLE_EQ(p.z / p.w, -1.0);
}

TEST(RenderPlan, PlanarListsTheReceiversSeenFromTheLightsSide) {
  const Scene scene = parse_scene_text(
      "light 0 0 2\n"
      "triangle -1 -1 -1  1 -1 -1  1 1 -1\n"
      "triangle -1 -1 0  1 -1 0  1 1 4\n"  // its plane holds the light (0, 0, 2): no receiver
      "sphere 0 0 0 0.3\n",
      "planar.scene");
  RenderSettings settings;
  settings.method = RenderMethod::kPlanar;
  settings.sphere_segments = 8;
  const RenderPlan plan = make_render_plan(scene, settings);
  const LightPlan& lp = plan.lights[0];
  ASSERT_EQ(lp.planar.receiver_planes.size(), 1u);
  EXPECT_EQ(lp.planar.receiver_planes[0], glm::dvec4(0, 0, 1, 1));  // the light on its positive side
  EXPECT_EQ(lp.count_reason,
            "no volume count: every caster projected onto 1 receiver plane(s) (triangles at lines 2); spheres and meshes "
            "receive no shadow");
  // Projected: the floor, the wall, and the sphere's 8-gon disc as a fan of 8.
  EXPECT_EQ(lp.planar.casters.triangles.size(), 1u + 1u + 8u);
  for (const glm::dvec4& v : lp.planar.casters.vertices) EXPECT_EQ(v.w, 1.0);
  EXPECT_TRUE(lp.all_volumes.triangles.empty());  // it counts no volumes
}

TEST(RenderMethods, TheViewersKeyCyclesThroughEveryInteractiveMethod) {
  // planar included (it was accepted but not cycled to); raycast never.
  std::vector<std::string> seen;
  RenderMethod m = RenderMethod::kAuto;
  do {
    seen.push_back(method_name(m));
    m = next_interactive_method(m);
  } while (m != RenderMethod::kAuto && seen.size() < 10);
  std::vector<std::string> interactive;  // the table's, in its order
  for (const RenderMethod method : all_methods())
    if (is_interactive(method)) interactive.push_back(method_name(method));
  EXPECT_EQ(seen, interactive);
  EXPECT_EQ(interactive.front(), "auto");
  EXPECT_FALSE(is_interactive(RenderMethod::kRaycast));
  EXPECT_FALSE(counts_volumes(RenderMethod::kPlanar));
  EXPECT_TRUE(counts_volumes(RenderMethod::kTriangles));
}

TEST(RenderPlan, ExplainSaysHowEachMethodShadows) {
  // Only the volume methods count volumes; the others say what they do instead.
  const Scene scene = parse_scene_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/two_spheres.scene");
  for (const auto& [method, phrase] :
       std::vector<std::pair<RenderMethod, std::string>>{{RenderMethod::kAuto, "method: auto; shadow volumes counted in a float buffer, z-pass or z-fail per light"},
                                                         {RenderMethod::kShadowMap, "method: shadowmap; no volumes: a cube map of distances from each light"},
                                                         {RenderMethod::kPlanar, "method: planar; no volumes: casters projected onto the triangles' planes"}}) {
    RenderSettings settings;
    settings.method = method;
    std::ostringstream explain;
    print_render_plan(explain, scene, make_render_plan(scene, settings));
    EXPECT_NE(explain.str().find(phrase + "\n"), std::string::npos) << explain.str();
    EXPECT_EQ(explain.str().find("counted in a float buffer") == std::string::npos,
              method == RenderMethod::kShadowMap || method == RenderMethod::kPlanar);
  }
}

TEST(RenderPlan, SaysWhichShadingTermsTheSceneUses) {
  const Scene matte = parse_scene_text("light 0 0 2\nlight 1 0 2 color 0 0 0\nsphere 0 0 0 0.3\n", "matte.scene");
  const RenderPlan plan = make_render_plan(matte, RenderSettings{});
  EXPECT_FALSE(plan.specular_used);
  EXPECT_EQ(plan.light_adds_direct, (std::vector<uint8_t>{1, 0}));
  // Specular only counts where a light with colour meets it.
  const Scene shiny = parse_scene_text("light 0 0 2\nmaterial m specular 0.5 0.5 0.5\nsphere 0 0 0 0.3 material m\n",
                                       "shiny.scene");
  EXPECT_TRUE(make_render_plan(shiny, RenderSettings{}).specular_used);
  const Scene dark = parse_scene_text("light 0 0 2 color 0 0 0\nmaterial m specular 0.5 0.5 0.5\nsphere 0 0 0 0.3 material m\n",
                                      "dark.scene");
  EXPECT_FALSE(make_render_plan(dark, RenderSettings{}).specular_used);
  std::ostringstream explain;
  print_render_plan(explain, matte, plan);
  EXPECT_NE(explain.str().find("shading: ambient + diffuse (no material has a specular term: skipped)"), std::string::npos);
  EXPECT_NE(explain.str().find("no colour: ambient only, so a frame draws neither its shadows nor its direct light"),
            std::string::npos)
      << explain.str();
}

}  // namespace
}  // namespace umbra

namespace umbra {
namespace {

TEST(Projection, PointsAtInfinityLandJustInsideTheFarPlane) {
  // Everitt and Kilgard: A = -(1 - eps), B = -(2 - eps) near, so a point at
  // infinity straight ahead has depth 1 - eps, not 1 (which rounding could clip).
  const glm::dmat4 p = infinite_perspective(45.0, 1.5, 0.05);
  EXPECT_DOUBLE_EQ(p[2][2], -(1.0 - kInfiniteFarEpsilon));
  EXPECT_DOUBLE_EQ(p[3][2], -(2.0 - kInfiniteFarEpsilon) * 0.05);
  EXPECT_EQ(p[2][3], -1.0);
  EXPECT_DOUBLE_EQ(p[1][1], 1.0 / std::tan(glm::radians(22.5)));
  EXPECT_DOUBLE_EQ(p[0][0], p[1][1] / 1.5);
  for (const glm::dvec4& at_infinity : {glm::dvec4(0, 0, -1, 0), glm::dvec4(0.3, -0.2, -1, 0)}) {
    const glm::dvec4 clip = p * at_infinity;
    EXPECT_DOUBLE_EQ(clip.z / clip.w, 1.0 - kInfiniteFarEpsilon);
  }
  // The near plane maps to depth -1.
  const glm::dvec4 near = p * glm::dvec4(0, 0, -0.05, 1);
  EXPECT_NEAR(near.z / near.w, -1.0, 1e-12);
}

}  // namespace
}  // namespace umbra
