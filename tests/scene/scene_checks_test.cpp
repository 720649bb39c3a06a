#include "scene/scene_checks.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "scene/scene_parser.hpp"

namespace umbra {
namespace {

std::string check_error(const std::string& text) {
  try {
    require_lights_off_casters(parse_scene_text(text, "t.scene"));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(LightsOutsideSpheres, InsideOnAndOutside) {
  const std::string inside = "t.scene:3:1: light 2 (line 2) is inside or on this sphere, which then has no shadow "
                             "volume; move the light outside the sphere";
  EXPECT_EQ(check_error("light 0 0 5\nlight 0 0 1.1\nsphere 0 0 1 0.5\n"), inside);
  EXPECT_EQ(check_error("light 0 0 5\nlight 0 0 1.5\nsphere 0 0 1 0.5\n"), inside);  // on the surface
  EXPECT_EQ(check_error("light 0 0 5\nlight 0 0 1.5000001\nsphere 0 0 1 0.5\n"), "");
}

TEST(LightsOutsideSpheres, OverflowIsAnErrorNotAWrongAnswer) {
  EXPECT_EQ(check_error("light 0 0 2\nsphere 1e300 0 0 1e299\n"),
            "t.scene:2:1: the distance from light 1 (line 1) to this sphere overflows double precision; "
            "scale the scene down");
}

// Hand-computed: the triangle (0,0,0) (2,0,0) (0,2,0) seen from above its
// inside, beyond its long edge, beyond a corner; a sphere from outside and
// from inside.
TEST(NearestSurfaceDistance, TrianglesAndSpheresByHand) {
  const Scene triangle = parse_scene_text("light 0 0 5\ntriangle 0 0 0  2 0 0  0 2 0\n", "t.scene");
  EXPECT_DOUBLE_EQ(nearest_surface_distance(triangle, {0.5, 0.5, 3}), 3.0);
  EXPECT_DOUBLE_EQ(nearest_surface_distance(triangle, {2, 2, 0}), std::sqrt(2.0));   // to (1, 1, 0)
  EXPECT_DOUBLE_EQ(nearest_surface_distance(triangle, {-3, -4, 0}), 5.0);            // to the corner (0, 0, 0)
  EXPECT_DOUBLE_EQ(nearest_surface_distance(triangle, {1, -1, 1}), std::sqrt(2.0));  // to (1, 0, 0)
  const Scene sphere = parse_scene_text("light 0 0 5\nsphere 1 0 0 0.5\n", "s.scene");
  EXPECT_DOUBLE_EQ(nearest_surface_distance(sphere, {4, 0, 0}), 2.5);
  EXPECT_DOUBLE_EQ(nearest_surface_distance(sphere, {1.2, 0, 0}), 0.3);
  EXPECT_EQ(nearest_surface_distance(parse_scene_text("light 0 0 5\n", "e.scene"), {0, 0, 0}),
            std::numeric_limits<double>::infinity());
}


}  // namespace
}  // namespace umbra
