// The studio look a staged mesh gets, drawn by the GL as the ray-cast
// reference draws it: a headlight and a hemisphere worked out by hand, a
// soft tone curve, smooth shading without a saw-tooth at the terminator, and
// texture coordinates through KHR_texture_transform.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>

#include "image/tone_curve.hpp"
#include "scene/scene_parser.hpp"
#include "scene/staged_scene.hpp"
#include "tests/mesh/mesh_builders.hpp"
#include "tests/render/image_agreement.hpp"
#include "tests/scratch_folder.hpp"

namespace umbra {
namespace {

class StudioLook : public test::ScratchFolder {
 protected:
  Scene parse(const std::string& text) const { return parse_scene_text(text, (folder_ / "s.scene").string()); }
};

// The curve is the line up to its knee (0.8), then rolls off smoothly, and
// never reaches white: 0.98 takes 1.26 of light.
TEST(ToneCurve, SoftIsTheLineToItsKneeThenNeverReachesWhite) {
  for (const double v : {0.0, 0.3, 0.8}) EXPECT_EQ(toned(v, ToneCurve::kSoft), v);
  EXPECT_EQ(toned(1.7, ToneCurve::kClip), 1.7);  // clipped when rounded, as a spec scene is
  EXPECT_NEAR(toned(0.8 + 1e-7, ToneCurve::kSoft), 0.8 + 1e-7, 1e-12);  // slope 1 at the knee
  EXPECT_NEAR(toned(0.8 + 0.2 * std::log(10.0), ToneCurve::kSoft), 0.98, 1e-12);
  double previous = 0.8;
  for (double v = 0.85; v < 7.0; v += 0.05) {  // past 7, 1 - e^-31 rounds to 1
    EXPECT_GT(toned(v, ToneCurve::kSoft), previous);
    EXPECT_LT(toned(v, ToneCurve::kSoft), 1.0);
    previous = toned(v, ToneCurve::kSoft);
  }
}

// A quad facing the camera head-on, lit by nothing but the fill: the
// hemisphere's sky (the quad faces up) times the ambient colour, and the
// headlight by n . v (1 at the centre) times the diffuse colour. The key
// light is behind the quad: it lights nothing the camera sees.
TEST_F(StudioLook, TheFillIsWhatItIsWorkedOutToBe) {
  const std::string quad = "light 0 0 -3 ambient 0 0 0\nmaterial m ambient 0.5 0.5 0.5 diffuse 0.8 0.4 0.2\n"
                           "triangle -1 -1 0  1 -1 0  1 1 0 material m\ntriangle -1 -1 0  1 1 0  -1 1 0 material m\n"
                           "camera eye 0 0 3 target 0 0 0 up 0 1 0 fovy 30\n";
  const Scene dim = parse(quad + "headlight 0.25 0.25 0.25\nhemisphere sky 0.4 0.4 0.4 ground 0.9 0.9 0.9\n");
  const test::RenderedImages r = test::render_gl_and_ray_cast(dim, 41);
  // 0.5 * 0.4 + (0.8, 0.4, 0.2) * 0.25 = (0.4, 0.3, 0.25): 102, 77, 64.
  for (const Image* image : {&r.gl, &r.cpu}) {
    EXPECT_EQ(image->at(20, 20, 0), 102);
    EXPECT_EQ(image->at(20, 20, 1), 77);
    EXPECT_EQ(image->at(20, 20, 2), 64);
  }
  test::expect_images_agree(dim, r);
  // Turned away from `up`, the ground's instead: 0.5 * 0.9 + 0.2 = 0.65 of red.
  const Scene below = parse(quad + "headlight 0.25 0.25 0.25\nhemisphere sky 0.4 0.4 0.4 ground 0.9 0.9 0.9 up 0 0 -1\n");
  EXPECT_EQ(test::render_gl_and_ray_cast(below, 41).gl.at(20, 20, 0), channel_byte(0.65));
  // Too bright for white: clipped, or rolled off by the soft curve, as the reference does it.
  const std::string bright = quad + "headlight 1 1 1\nhemisphere sky 1 1 1\n";  // red 0.5 + 0.8 = 1.3
  EXPECT_EQ(test::render_gl_and_ray_cast(parse(bright), 41).gl.at(20, 20, 0), 255);
  const Scene soft = parse(bright + "tone soft\n");
  const test::RenderedImages toned_images = test::render_gl_and_ray_cast(soft, 41);
  EXPECT_EQ(toned_images.gl.at(20, 20, 0), channel_byte(toned(1.3, ToneCurve::kSoft)));
  EXPECT_LT(toned_images.gl.at(20, 20, 0), 255);  // rolled off short of white
  test::expect_images_agree(soft, toned_images);
}

// A coarse sphere (8 rings of 12 segments) shaded smooth, lit from the
// side: at the shadow volume's exact edge, the last lit pixels take almost
// none of the key light, so the lit side fades into the shadow instead of
// ending in a saw-tooth of bright facets. Without the terminator's dimming,
// their shading normals would still take up to a quarter of it there. The
// GL draws what the reference draws.
TEST_F(StudioLook, ASmoothCoarseSphereFadesIntoItsShadowWithoutASawTooth) {
  write("sphere.obj", test::obj_text(test::uv_sphere(8, 12)));
  const std::string text = "mesh sphere.obj smooth 60\ncamera eye 0 -3.5 0.3 target 0 0 0 up 0 0 1 fovy 40\n";
  const Scene lit = parse("light 3 -1 0.5 ambient 0 0 0\n" + text);
  ASSERT_EQ(lit.meshes[0].triangle_normals.size(), lit.meshes[0].triangles.size());
  const int size = 120;
  const test::RenderedImages r = test::render_gl_and_ray_cast(lit, size);
  test::expect_images_agree(lit, r);
  const Image& key = r.cpu;  // the key light alone: nothing else lights the scene
  int brightest = 0, edge_pixels = 0, worst = 0;
  for (int y = 1; y + 1 < size; ++y)
    for (int x = 1; x + 1 < size; ++x) {
      brightest = std::max<int>(brightest, key.at(x, y, 0));
      if (reference_mask_value(lit, size, size, x, y, 0) != kMaskLit) continue;
      bool beside_shadow = false;
      for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}})
        beside_shadow = beside_shadow || reference_mask_value(lit, size, size, x + dx, y + dy, 0) == kMaskUnlit;
      if (!beside_shadow) continue;
      ++edge_pixels;
      worst = std::max<int>(worst, key.at(x, y, 0));
    }
  EXPECT_GT(edge_pixels, 40) << "the terminator should cross the sphere";
  EXPECT_LT(worst, brightest / 10) << "a lit pixel beside the shadow takes " << worst << " of " << brightest;
}

// Across a sharp edge nothing fades: a cube shaded `smooth 30` keeps its
// faces' own normals (they meet at 90 degrees), and draws as the flat cube
// does, to a level, though each of its corners has faces on both sides of
// the light.
TEST_F(StudioLook, ACubeShadedSmoothDrawsAsItsFlatSelf) {
  write("cube.obj", test::obj_text(test::unit_cube()));
  const std::string rest = "camera eye 2.5 -3 2.2 target 0.5 0.5 0.5 up 0 0 1 fovy 40\nheadlight 0.3 0.3 0.3\n";
  const Scene smooth = parse("light -1 -2 4 ambient 0.1 0.1 0.1\nmesh cube.obj smooth 30\n" + rest);
  const Scene flat = parse("light -1 -2 4 ambient 0.1 0.1 0.1\nmesh cube.obj\n" + rest);
  const test::RenderedImages a = test::render_gl_and_ray_cast(smooth, 80), b = test::render_gl_and_ray_cast(flat, 80);
  int lit = 0;
  for (size_t i = 0; i < a.gl.pixels.size(); ++i) {
    EXPECT_LE(std::abs(int(a.gl.pixels[i]) - int(b.gl.pixels[i])), 1) << i;
    EXPECT_LE(std::abs(int(a.cpu.pixels[i]) - int(b.cpu.pixels[i])), 1) << i;
    lit += a.gl.pixels[i] > 150;
  }
  EXPECT_GT(lit, 300) << "the cube's lit faces should be bright";
}

// A torus shaded smooth under the staged studio look (the key light, the
// headlight, the hemisphere, the soft curve): away from edges, the GL and
// the reference agree, its own shadow falling across it included.
TEST_F(StudioLook, ASmoothTorusUnderTheStudioLightsDrawsAsTheReferenceDoes) {
  write("torus.obj", test::obj_text(test::quad_torus(16, 8)));
  std::string text;
  const Scene scene = parse_scene_or_mesh_file((folder_ / "torus.obj").string(), {}, &text);
  EXPECT_NE(text.find(" smooth 30\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nheadlight "), std::string::npos) << text;
  EXPECT_NE(text.find("\ntone soft\n"), std::string::npos) << text;
  test::expect_images_agree(scene, test::render_gl_and_ray_cast(scene, 100));
}

// KHR_texture_transform's sample model, each quad's texture offset, turned
// and scaled: the GL samples it where the reference does.
TEST_F(StudioLook, TextureTransformsDrawAsTheReferenceDoes) {
  const std::string path = "/usr/share/assimp/models/glTF2/textureTransform/TextureTransformTest.gltf";
  if (!std::filesystem::exists(path)) GTEST_SKIP() << "needs Debian's assimp-testmodels (build.sh installs it)";
  const Scene scene = parse_scene_or_mesh_file(path);
  EXPECT_TRUE(std::none_of(scene.warnings.begin(), scene.warnings.end(),
                           [](const Warning& w) { return w.message.find("texture") != std::string::npos; }));
  test::expect_images_agree(scene, test::render_gl_and_ray_cast(scene, 120));
}

}  // namespace
}  // namespace umbra
