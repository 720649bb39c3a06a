// How far a light's shadow volumes are extruded: past every point of the
// region where a caster's shadow can fall, or to infinity.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

#include "render/render_plan.hpp"
#include "render/volume_reach.hpp"
#include "scene/scene_parser.hpp"

namespace umbra {
namespace {

SceneBounds box(glm::dvec3 lo, glm::dvec3 hi) { return {lo, hi}; }

TEST(VolumeReach, ALightAboveTheCastersStopsTheirVolumesPastTheRegionsFloor) {
  // The caster's top corner (1, 1, 2) throws its shadow from (0, 0, 4) onto
  // the floor z = -2 at t = (4 + 2) / (4 - 2) = 3; nothing reaches farther.
  const double reach = volume_reach({0, 0, 4}, box({-1, -1, 0}, {1, 1, 2}), box({-10, -10, -2}, {10, 10, 5}));
  EXPECT_DOUBLE_EQ(reach, 3.0 * kVolumeReachMargin);
}

TEST(VolumeReach, ALightBesideTheCastersUsesTheFaceBehindThem) {
  // Beyond the casters along +x only: the face x = -10, (5 + 10) / (5 - 1).
  const double reach = volume_reach({5, 0, 0.5}, box({-1, -1, -1}, {1, 1, 1}), box({-10, -10, -10}, {10, 10, 10}));
  EXPECT_DOUBLE_EQ(reach, 15.0 / 4.0 * kVolumeReachMargin);
  // Below them, by the region's top face: (3 + 1) / (-1 + 3).
  EXPECT_DOUBLE_EQ(volume_reach({0, 0, -3}, box({-1, -1, -1}, {1, 1, 1}), box({-2, -2, -4}, {2, 2, 1})),
                   2.0 * kVolumeReachMargin);
}

TEST(VolumeReach, ALightAmongTheCastersOnEveryAxisExtrudesToInfinity) {
  EXPECT_TRUE(std::isinf(volume_reach({0, 0, 0}, box({-1, -1, -1}, {1, 1, 1}), box({-5, -5, -5}, {5, 5, 5}))));
  EXPECT_TRUE(std::isinf(volume_reach({0, 0, 0}, SceneBounds{}, box({-5, -5, -5}, {5, 5, 5}))));
}

// The property the renderer relies on: any point of the region on a ray from
// the light through a caster point P is L + t (P - L) with t below the reach.
TEST(VolumeReach, NoPointOfTheRegionInAVolumeLiesBeyondTheReach) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto point_in = [&](const SceneBounds& b) {
    return glm::dvec3(b.lo.x + u(random) * (b.hi.x - b.lo.x), b.lo.y + u(random) * (b.hi.y - b.lo.y),
                      b.lo.z + u(random) * (b.hi.z - b.lo.z));
  };
  int finite = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const SceneBounds region = box({-4, -4, -4}, {4, 4, 4});
    const glm::dvec3 a = point_in(region), b = point_in(region);
    const SceneBounds casters = box(glm::min(a, b), glm::max(a, b));
    const glm::dvec3 light = point_in(box({-6, -6, -6}, {6, 6, 6}));
    const double reach = volume_reach(light, casters, region);
    if (std::isinf(reach)) continue;
    ++finite;
    for (int k = 0; k < 20; ++k) {
      const glm::dvec3 p = point_in(casters);
      // Where the ray from the light through P leaves the region: t_exit.
      double t_exit = INFINITY;
      for (int axis = 0; axis < 3; ++axis) {
        const double d = p[axis] - light[axis];
        if (d > 0) t_exit = std::min(t_exit, (region.hi[axis] - light[axis]) / d);
        if (d < 0) t_exit = std::min(t_exit, (region.lo[axis] - light[axis]) / d);
      }
      EXPECT_LT(t_exit * kVolumeReachMargin, reach * (1 + 1e-12)) << "trial " << trial;
    }
  }
  EXPECT_GT(finite, 500);
}

TEST(VolumeReach, ExplainSaysHowFarEachLightsVolumesReach) {
  const std::string floor_and_sphere = "triangle -10 -10 0  10 -10 0  10 10 0\nsphere 0 0 1 0.5\n";
  std::ostringstream above, among;
  const Scene lit_from_above = parse_scene_text("light 0 0 4\n" + floor_and_sphere, "above.scene");
  print_render_plan(above, lit_from_above, make_render_plan(lit_from_above, RenderSettings{}));
  // From (0, 0, 4) past the sphere's top (z = 1.5) to the floor's z = 0:
  // 4 / 2.5 = 1.6, times the margin (1.76).
  std::ostringstream expected;
  expected << "volumes reach " << 1.6 * kVolumeReachMargin << " times their casters' distance from the light";
  EXPECT_NE(above.str().find(expected.str()), std::string::npos) << expected.str() << "\n" << above.str();
  // Level with the sphere and over the floor: within their box on every axis.
  const Scene lit_from_among = parse_scene_text("light 2 0 1\n" + floor_and_sphere, "among.scene");
  print_render_plan(among, lit_from_among, make_render_plan(lit_from_among, RenderSettings{}));
  EXPECT_NE(among.str().find("volumes reach to infinity: along every axis the light lies within the casters' box"),
            std::string::npos)
      << among.str();
}

}  // namespace
}  // namespace umbra
