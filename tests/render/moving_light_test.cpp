// A light that moves between frames, drawn as `umbra view` draws it: the
// view updated first, the light's volumes made while the GL draws the first
// pass, and each triangle's side of the light worked out when a lit pass
// first asks for it (SurfaceBuffers::use_light). Each frame must be the one
// a renderer made afresh for the light where it now is.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "render/headless_context.hpp"
#include "render/render_plan.hpp"
#include "render/shadow_renderer.hpp"
#include "scene/scene_parser.hpp"

namespace umbra {
namespace {

// The bundled torus, shaded smooth (so that its terminator's corners are
// coded too), over a floor, under two lights of their own colours.
Scene smooth_torus_under_two_lights() {
  return parse_scene_text(
      "light 0.5 0.9 1.8 color 0.8 0.7 0.6\nlight -1.2 0.4 1.1 color 0.3 0.4 0.6\n"
      "material floor diffuse 0.7 0.7 0.72\nmaterial copper diffuse 0.85 0.45 0.25\n"
      "triangle -1 -1 -1   1 -1 -1   1 1 -1 material floor\ntriangle -1 -1 -1   1 1 -1   -1 1 -1 material floor\n"
      "mesh meshes/torus.obj material copper smooth 40 scale 0.5 rotate 1 0.3 0 50 translate 0 0 -0.25\n",
      std::string(UMBRA_SOURCE_DIR) + "/scenes/moving_light.scene");
}

TEST(MovingLight, EachFrameDrawnAsTheViewerDrawsItIsTheFrameOfAFreshRenderer) {
  Scene scene = smooth_torus_under_two_lights();
  ASSERT_FALSE(scene.meshes[0].triangle_normals.empty()) << "the torus is not shaded smooth";
  const std::vector<MeshCaster> casters = prepare_mesh_casters(scene);
  RenderSettings settings;
  settings.width = settings.height = 96;
  HeadlessContext context(96, 96);
  RenderPlan plan = make_render_plan(scene, casters, settings);
  ShadowRenderer renderer(scene, plan, DrawSending::kWhole);  // reads `scene` as it moves
  for (int frame = 1; frame <= 4; ++frame) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    if (frame == 3)  // only the first light moves: the second's sides are kept
      scene.lights[0].position = rotated_about_z(scene.lights[0].position, 50.0);
    else
      rotate_lights_about_z(scene, 50.0);
    update_render_view(scene, plan);
    int updates = 0;
    renderer.draw(false, [&] {
      ++updates;
      update_render_lights(scene, casters, plan);
    });
    EXPECT_EQ(updates, 1);
    const Image drawn = renderer.read_image();
    const RenderPlan fresh_plan = make_render_plan(scene, settings);
    ShadowRenderer fresh(scene, fresh_plan);
    const Image expected = fresh.render_image(false);
    ASSERT_EQ(drawn.pixels.size(), expected.pixels.size());
    size_t differing = 0;
    for (size_t i = 0; i < drawn.pixels.size(); ++i) differing += drawn.pixels[i] != expected.pixels[i];
    EXPECT_EQ(differing, 0u) << "channels that differ from a fresh renderer's frame";
  }
}

}  // namespace
}  // namespace umbra
