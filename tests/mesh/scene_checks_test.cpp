#include "mesh/scene/scene_checks.hpp"

#include <gtest/gtest.h>

#include "mesh/scene/scene_parser.hpp"

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

}  // namespace
}  // namespace umbra
