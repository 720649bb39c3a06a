// The studio look a staged mesh gets, drawn by the GL as the ray-cast
// reference draws it: a headlight and a hemisphere worked out by hand, a
// soft tone curve, smooth shading that draws a coarse mesh as the surface it
// stands for, without a saw-tooth at the terminator, and
// texture coordinates through KHR_texture_transform.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <regex>
#include <string>

#include "image/tone_curve.hpp"
#include "reference/ray_caster.hpp"
#include "scene/scene_parser.hpp"
#include "scene/staged_scene.hpp"
#include "tests/mesh/interchange_writers.hpp"
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

// Whether every corner of pixel (x, y)'s footprint sees the mesh of `scene`
// (its first, and only): off its outline.
bool inside_the_model(const Scene& scene, const RayCaster& caster, int size, int x, int y) {
  const int first_mesh_object = int(scene.spheres.size() + scene.triangles.size());
  for (const double dx : {-0.5, 0.5})
    for (const double dy : {-0.5, 0.5}) {
      const auto hit = caster.nearest_hit(scene.camera.pixel_ray(size, size, x + dx, y + dy));
      if (!hit || hit->object < first_mesh_object) return false;
    }
  return true;
}

// How closely two pictures agree over the pixels `counted(x, y)` keeps: how
// many of them, how many within `levels` in every channel, and the most
// any channel is off.
struct Agreement {
  int pixels = 0, within = 0, worst = 0;
};
template <class Counted>
Agreement agreement(const Image& a, const Image& b, int levels, Counted counted) {
  Agreement result;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      if (!counted(x, y)) continue;
      int off = 0;
      for (int c = 0; c < 3; ++c) off = std::max(off, std::abs(int(a.at(x, y, c)) - int(b.at(x, y, c))));
      ++result.pixels;
      result.within += off <= levels;
      result.worst = std::max(result.worst, off);
    }
  return result;
}

// A coarse sphere (1,224 triangles) and a coarse cylinder (188), staged and
// shaded smooth, draw as a tessellation of the same surface 100 times finer
// draws it. Their faces' exact self-shadow begins up to half a face before
// or after the smooth surface's terminator; there the normals decide
// (terminator.hpp), so the light neither ends in a saw-tooth of lit facets
// nor fades early. Off the outlines, 99.8% of the pixels that both models
// cover are within 12 levels (the polygons' rims differ from the circles'
// by a pixel); when the terminator's faces faded instead, 0.6% of the
// sphere's were further off, by up to 17 levels. The GL draws what the
// reference draws.
TEST_F(StudioLook, CoarseSmoothMeshesDrawAsTheirFineTessellationsDo) {
  struct Surface {
    std::string name;
    PolygonSoup coarse, fine;
  };
  for (const Surface& surface : {Surface{"sphere", test::uv_sphere(18, 36), test::uv_sphere(180, 360)},
                                 Surface{"cylinder", test::cylinder(48, 1), test::cylinder(480, 19)}}) {
    SCOPED_TRACE(surface.name);
    write("coarse.obj", test::obj_text(surface.coarse));
    write("fine.obj", test::obj_text(surface.fine));
    std::string text;
    parse_scene_or_mesh_file((folder_ / "coarse.obj").string(), {}, &text);
    ASSERT_NE(text.find(" smooth 30\n"), std::string::npos) << text;
    const Scene coarse = parse(text);
    const Scene fine = parse(std::regex_replace(text, std::regex("coarse\\.obj"), "fine.obj"));
    ASSERT_GE(fine.meshes[0].triangles.size(), 100 * coarse.meshes[0].triangles.size());
    const int size = 200;
    const test::RenderedImages drawn = test::render_gl_and_ray_cast(coarse, size);
    test::expect_images_agree(coarse, drawn);
    const Image finer = test::render_gl_and_ray_cast(fine, size).gl;
    const RayCaster coarse_caster(coarse), fine_caster(fine);
    const Agreement near = agreement(drawn.gl, finer, 12, [&](int x, int y) {
      return inside_the_model(coarse, coarse_caster, size, x, y) && inside_the_model(fine, fine_caster, size, x, y);
    });
    EXPECT_GT(near.pixels, size * size / 8) << "the model should fill much of the picture";
    EXPECT_GE(near.within, 0.998 * near.pixels)
        << near.within << " of " << near.pixels << " pixels within 12 levels; the worst is off by " << near.worst;
  }
}

// The normals decide where a smooth mesh's own light ends, never another
// caster's shadow: a coarse sphere behind a wall, lit from the side, takes
// none of the light on its terminator's faces either (before the wall it
// would take some there), and draws as it does with the light off. The GL
// and the reference agree.
TEST_F(StudioLook, AShadowCastAcrossTheTerminatorStaysWhole) {
  write("sphere.obj", test::obj_text(test::uv_sphere(8, 12)));
  const std::string rest = "mesh sphere.obj smooth 60\ncamera eye 0 -3.5 0.3 target 0 0 0 up 0 0 1 fovy 40\nheadlight 0.3 0.3 0.3\n";
  const std::string wall = "triangle 2 -5 -5  2 5 -5  2 0 8\n";
  const Scene open = parse("light 3 -1 0.5 ambient 0 0 0\n" + rest);
  const Scene walled = parse("light 3 -1 0.5 ambient 0 0 0\n" + rest + wall);
  const Scene dark = parse("light 3 -1 0.5 color 0 0 0 ambient 0 0 0\n" + rest + wall);
  const int size = 120;
  const test::RenderedImages behind = test::render_gl_and_ray_cast(walled, size), unlit = test::render_gl_and_ray_cast(dark, size),
                             before = test::render_gl_and_ray_cast(open, size);
  test::expect_images_agree(walled, behind);
  test::expect_images_agree(open, before);
  const RayCaster caster(open);
  int band = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      if (!inside_the_model(open, caster, size, x, y)) continue;
      EXPECT_EQ(behind.gl.at(x, y, 0), unlit.gl.at(x, y, 0)) << x << " " << y;
      EXPECT_EQ(behind.cpu.at(x, y, 0), unlit.cpu.at(x, y, 0)) << x << " " << y;
      // A pixel in the faces' shadow that the light's normals reach.
      band += reference_mask_value(open, size, size, x, y, 0) == kMaskUnlit && before.cpu.at(x, y, 0) > unlit.cpu.at(x, y, 0) + 2;
    }
  EXPECT_GT(band, 20) << "the terminator's faces that turn from the light should take some of it without the wall";
}

// The studio's fill reaches every face the camera sees: staged and drawn
// flat, each face of a coarse sphere (faces turned every way, some to the
// floor) and of an open bowl (seen inside and out, its outside being the
// back of its faces) is lighter, over its pixels, than the darkest pixel of
// the shadow on the floor.
TEST_F(StudioLook, EveryFaceTheCameraSeesIsLighterThanTheShadowOnTheFloor) {
  write("sphere.obj", test::obj_text(test::uv_sphere(6, 10)));
  write("bowl.obj", test::obj_text(test::bowl(4, 10)));
  std::vector<std::string> files{(folder_ / "sphere.obj").string(), (folder_ / "bowl.obj").string()};
  // Two triangles, one seen from its back, which was darker than the shadow.
  const std::string real = "/usr/share/assimp/models/OBJ/multiple_spaces.obj";
  if (std::filesystem::exists(real)) files.push_back(real);
  for (const std::string& name : files) {
    SCOPED_TRACE(name);
    StagingOptions staging;
    staging.flat = true;
    const Scene scene = parse_scene_or_mesh_file(name, {}, nullptr, staging);
    const int size = 200;
    const Image picture = test::render_gl_and_ray_cast(scene, size).gl;
    const RayCaster caster(scene);
    const int first_mesh_object = int(scene.spheres.size() + scene.triangles.size());
    const auto grey = [&](int x, int y) { return (picture.at(x, y, 0) + picture.at(x, y, 1) + picture.at(x, y, 2)) / 3.0; };
    double darkest_shadow = 255.0;
    std::map<int, std::pair<double, int>> faces;  // per face seen off its edges: its pixels' summed grey, and how many
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        std::set<int> seen;
        for (const double dx : {-0.5, 0.5})
          for (const double dy : {-0.5, 0.5}) {
            const auto hit = caster.nearest_hit(scene.camera.pixel_ray(size, size, x + dx, y + dy));
            seen.insert(hit ? hit->object : -1);
          }
        if (seen.size() != 1 || *seen.begin() < 0) continue;
        const int object = *seen.begin();
        if (object >= first_mesh_object) {
          faces[object].first += grey(x, y);
          ++faces[object].second;
        } else if (reference_mask_value(scene, size, size, x, y, 0) == kMaskUnlit) {
          darkest_shadow = std::min(darkest_shadow, grey(x, y));
        }
      }
    ASSERT_LT(darkest_shadow, 255.0) << "the shadow should be in view";
    int shown = 0;
    for (const auto& [object, sum] : faces) {
      if (sum.second < 8) continue;
      ++shown;
      EXPECT_GT(sum.first / sum.second, darkest_shadow) << "face " << object - first_mesh_object << " over " << sum.second << " pixels";
    }
    EXPECT_GE(shown, name == real ? 1 : 20) << "most faces should be seen";
  }
}

// A flat face keeps its one normal, whatever its neighbours: a plate as
// CAD tools tessellate a printer's bed (its top fanned from a corner, a
// shallow bevel of small quads round it, 324 triangles), staged and shaded
// smooth, draws within 6 levels of its flat picture on 99% of its pixels.
// Weighed by their angles alone, the bevel's slivers tilted each of the
// top's corners its own way, and the fan's seams showed.
TEST_F(StudioLook, AFlatFaceKeepsItsNormalWhateverItsNeighbours) {
  write("plate.stl", test::stl_text(test::triangulated(test::bevelled_plate(20))));
  StagingOptions flat_staging;
  flat_staging.flat = true;
  const Scene smooth = parse_scene_or_mesh_file((folder_ / "plate.stl").string());
  const Scene flat = parse_scene_or_mesh_file((folder_ / "plate.stl").string(), {}, nullptr, flat_staging);
  ASSERT_FALSE(smooth.meshes[0].triangle_normals.empty());
  const int size = 200;
  const Image a = test::render_gl_and_ray_cast(smooth, size).gl, b = test::render_gl_and_ray_cast(flat, size).gl;
  const RayCaster caster(flat);
  const Agreement near = agreement(a, b, 6, [&](int x, int y) { return inside_the_model(flat, caster, size, x, y); });
  EXPECT_GT(near.pixels, size * size / 8) << "the plate should fill much of the picture";
  EXPECT_GE(near.within, 0.99 * near.pixels) << near.within << " of " << near.pixels << " pixels within 6 levels; the worst is off by "
                                             << near.worst;
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
