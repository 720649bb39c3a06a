#include "reference/ray_cast.hpp"

#include <utility>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "scene/scene_parser.hpp"
#include "scene/camera.hpp"

namespace umbra {
namespace {

const Scene kScene = parse_scene_text(
    "light 0 0 2\n"
    "sphere 0 0 0 0.5\n"
    "triangle -1 -1 -1  1 -1 -1  1 1 -1\n",
    "t.scene");

TEST(RayCast, EyeRayHitsTheSphereAtTheHandComputedPoint) {
  const auto hit = nearest_hit(kScene, {0, 0, 3.4}, {0, 0, -1});
  ASSERT_TRUE(hit);
  EXPECT_DOUBLE_EQ(hit->t, 2.9);
  EXPECT_EQ(hit->object, 0);
  EXPECT_EQ(hit->normal, glm::dvec3(0, 0, 1));
}

TEST(RayCast, ShadowRaysAgainstTheSphere) {
  // (0, 0, -1) looks straight up at the light through the sphere.
  EXPECT_TRUE(shadow_ray_blocked(kScene, {0, 0, -1}, 1, kScene.lights[0].position));
  // From (0.9, 0, -1) the segment to the light passes 0.5747 from the centre.
  EXPECT_FALSE(shadow_ray_blocked(kScene, {0.9, 0, -1}, 1, kScene.lights[0].position));
  // From (0.5, 0, -1) it passes 0.4781 from the centre: blocked.
  EXPECT_TRUE(shadow_ray_blocked(kScene, {0.5, 0, -1}, 1, kScene.lights[0].position));
}

TEST(RayCast, AnOccluderBeyondTheLightDoesNotShadow) {
  EXPECT_FALSE(shadow_ray_blocked(kScene, {0, 0, 1}, -1, {0, 0, 2}));  // sphere is behind the point
}

TEST(RayCast, APointOnASharedEdgeIsNotShadowedByItsNeighbour) {
  // The floor of colored_lights.scene: two triangles sharing the diagonal
  // x = y. From a rounded point on it, the neighbour was hit at t ~ 1e-16,
  // which made the reference call a lit floor pixel shadowed.
  const Scene floor = parse_scene_text(
      "light -0.8 0.6 1.8\n"
      "triangle -1 -1 -1   1 -1 -1   1 1 -1\n"
      "triangle -1 -1 -1   1 1 -1   -1 1 -1\n",
      "floor.scene");
  const glm::dvec3 eye = floor.camera.eye;
  int blocked = 0;
  for (int k = 1; k < 2000; ++k) {  // eye rays aimed along the diagonal, hitting it as rounded
    const double x = -1.0 + k / 1000.0;
    const auto hit = nearest_hit(floor, eye, glm::normalize(glm::dvec3(x, x, -1.0) - eye));
    ASSERT_TRUE(hit);
    blocked += shadow_ray_blocked(floor, hit->point, hit->object, floor.lights[0].position);
  }
  EXPECT_EQ(blocked, 0);
}

TEST(RayCast, PixelRaysOfTheSpecCamera) {
  const Camera camera = spec_camera();
  const glm::dvec3 centre = camera.pixel_ray(101, 101, 50, 50).direction;
  EXPECT_NEAR(centre.x, 0.0, 1e-15);
  EXPECT_NEAR(centre.y, 0.0, 1e-15);
  EXPECT_NEAR(centre.z, -1.0, 1e-15);
  // The top edge of the image is fovy / 2 = 22.5 degrees above the axis.
  const glm::dvec3 top = camera.pixel_ray(101, 100, 50, -0.5).direction;
  EXPECT_NEAR(std::atan2(top.y, -top.z), M_PI / 8, 1e-12);
}

// What the GL's sphere shader traces from gl_FragCoord: the same rays as
// the reference's, from the matrices the GL draws with.
TEST(RayCast, WindowRaysAreThePixelRays) {
  Camera tilted = spec_camera();
  tilted.eye = glm::dvec3(2.5, -1.5, 3.0);
  tilted.target = glm::dvec3(0.2, 0.1, -0.4);
  tilted.up = glm::dvec3(0.3, 1.0, 0.1);
  for (const Camera& camera : {spec_camera(), tilted}) {
    const int width = 160, height = 120;
    const glm::dmat3 rays = window_rays(camera.view_projection(double(width) / height, 0.05), camera.eye, width, height).directions;
    for (const auto& [px, py] : {std::pair{0, 0}, {159, 0}, {0, 119}, {82, 84}, {159, 119}, {80, 60}}) {
      const glm::dvec3 window = glm::normalize(rays * glm::dvec3(px + 0.5, height - py - 0.5, 1.0));
      const glm::dvec3 pixel = camera.pixel_ray(width, height, px, py).direction;
      EXPECT_LT(glm::length(window - pixel), 1e-12) << "pixel (" << px << ", " << py << ")";
    }
  }
  // The spec camera looks down -z with y up: the window's centre is the axis,
  // its right edge tan(fovy / 2) * aspect to the side.
  const glm::dmat3 spec = window_rays(spec_camera().view_projection(4.0 / 3.0, 0.05), spec_camera().eye, 160, 120).directions;
  const glm::dvec3 axis = spec * glm::dvec3(80.0, 60.0, 1.0), edge = spec * glm::dvec3(160.0, 60.0, 1.0);
  EXPECT_NEAR(axis.x / -axis.z, 0.0, 1e-14);  // the inverse matrix, rounded
  EXPECT_NEAR(axis.y / -axis.z, 0.0, 1e-14);
  EXPECT_NEAR(edge.x / -edge.z, std::tan(M_PI / 8) * 4.0 / 3.0, 1e-14);
  EXPECT_NEAR(edge.y / -edge.z, 0.0, 1e-14);
}

TEST(RayCast, MaskValuesForHandPickedPixels) {
  // 101 x 101, pixel (50, 50) is the axis: it sees the sphere's top, facing the light.
  EXPECT_EQ(reference_mask_value(kScene, 101, 101, 50, 50, 0), kMaskLit);
  EXPECT_EQ(reference_mask_value(kScene, 101, 101, 0, 0, 0), kMaskNoSurface);  // corner: past the floor
}

}  // namespace
}  // namespace umbra
