// The Embree search must give exactly the brute-force answers: the same
// object, the same t bit for bit, the same shadow verdict, for every eye ray
// of a grid and every light, on every bundled scene and on hard ones.
#include "reference/ray_caster.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "scene/scene_parser.hpp"
#include "scene/camera.hpp"

namespace umbra {
namespace {

void expect_same_answers(const Scene& scene, int grid) {
  const RayCaster caster(scene, RayCaster::Search::kHierarchy);
  int hits = 0, blocked = 0;
  for (int y = 0; y < grid; ++y)
    for (int x = 0; x < grid; ++x) {
      const Ray ray = scene.camera.pixel_ray(grid, grid, x, y);
      const auto brute = nearest_hit(scene, ray);
      const auto fast = caster.nearest_hit(ray);
      ASSERT_EQ(bool(brute), bool(fast)) << scene.path << " pixel " << x << ", " << y;
      if (!brute) continue;
      ++hits;
      ASSERT_EQ(brute->object, fast->object) << scene.path << " pixel " << x << ", " << y;
      ASSERT_EQ(brute->t, fast->t);
      ASSERT_EQ(brute->normal, fast->normal);
      for (const Light& light : scene.lights) {
        const bool b = shadow_ray_blocked(scene, brute->point, brute->object, light.position);
        ASSERT_EQ(b, caster.shadow_ray_blocked(brute->point, brute->object, light.position))
            << scene.path << " pixel " << x << ", " << y;
        blocked += b;
      }
    }
  EXPECT_GT(hits, grid * grid / 10) << scene.path;
  EXPECT_GT(blocked, 0) << scene.path;
}

TEST(RayCaster, SameAnswersAsBruteForceOnEveryBundledScene) {
  for (const auto& entry : std::filesystem::directory_iterator(std::string(UMBRA_SOURCE_DIR) + "/scenes"))
    if (entry.path().extension() == ".scene") expect_same_answers(parse_scene_file(entry.path().string()), 96);
}

TEST(RayCaster, SameAnswersWhenScaledBy1e6And1eMinus6AndWithALightFarAway) {
  for (const double s : {1e6, 1e-6}) {
    Scene scene = parse_scene_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene");
    for (Sphere& sp : scene.spheres) sp.center *= s, sp.radius *= s;
    for (Triangle& t : scene.triangles) t.a *= s, t.b *= s, t.c *= s;
    for (Light& l : scene.lights) l.position *= s;
    scene.camera.eye *= s;
    scene.camera.target *= s;
    expect_same_answers(scene, 64);
  }
  Scene far = parse_scene_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/two_spheres.scene");
  far.lights[0].position = {3e5, 4e5, 1e6};
  expect_same_answers(far, 64);
}

TEST(RayCaster, AnEmptySceneHitsNothing) {
  const Scene scene = parse_scene_text("light 0 0 2\n", "empty.scene");
  const RayCaster caster(scene, RayCaster::Search::kHierarchy);
  EXPECT_FALSE(caster.nearest_hit({0, 0, 3}, {0, 0, -1}));
  EXPECT_FALSE(caster.shadow_ray_blocked({0, 0, -1}, -1, {0, 0, 2}));
}

}  // namespace
}  // namespace umbra
