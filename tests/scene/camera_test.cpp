// The camera type: its pixel rays, its projection (the GL's matrices and
// Camera::project) and its frustum agree, and its pose is where it stands.

#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "scene/camera.hpp"
#include "scene/scene.hpp"

namespace umbra {
namespace {

Camera tilted_camera() {
  return Camera{{2.5, -1.5, 3.0}, {0.2, 0.1, -0.4}, {0.3, 1.0, 0.1}, 38.0};
}

// A point on a pixel's ray projects back onto that pixel, at its distance
// along the view axis; and the GL's matrices send it to the same place.
TEST(Camera, APixelsRayProjectsBackOntoThePixel) {
  for (const Camera& camera : {spec_camera(), tilted_camera()}) {
    const int width = 160, height = 90;
    const glm::dmat4 view_projection = camera.view_projection(double(width) / height, 0.05);
    for (const auto& [px, py] : {std::pair{0.0, 0.0}, {159.0, 0.0}, {0.0, 89.0}, {82.25, 13.5}, {-0.5, 89.5}}) {
      const Ray ray = camera.pixel_ray(width, height, px, py);
      EXPECT_EQ(ray.origin, camera.eye);
      EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-15);
      const glm::dvec3 point = ray.origin + 7.0 * ray.direction;
      const Projected p = camera.project(point, width, height);
      EXPECT_NEAR(p.px, px, 1e-9);
      EXPECT_NEAR(p.py, py, 1e-9);
      EXPECT_NEAR(p.depth, 7.0 * glm::dot(ray.direction, camera.axes().forward), 1e-12);
      // The GL: normalised device coordinates to pixels, row 0 at the bottom.
      const glm::dvec4 clip = view_projection * glm::dvec4(point, 1.0);
      EXPECT_NEAR((clip.x / clip.w + 1.0) / 2.0 * width - 0.5, px, 1e-9);
      EXPECT_NEAR((1.0 - clip.y / clip.w) / 2.0 * height - 0.5, py, 1e-9);
    }
  }
}

// The frustum's section at a depth is what the corner pixels' rays reach.
TEST(Camera, TheFrustumsCornersAreTheCornerPixelsRays) {
  const Camera camera = tilted_camera();
  const int width = 120, height = 80;
  const std::array<glm::dvec3, 4> corners = camera.section_corners(1.5, 2.0);
  const std::pair<double, double> pixels[4] = {{-0.5, 79.5}, {119.5, 79.5}, {119.5, -0.5}, {-0.5, -0.5}};
  for (int i = 0; i < 4; ++i) {
    const Ray ray = camera.pixel_ray(width, height, pixels[i].first, pixels[i].second);
    const glm::dvec3 reached = ray.origin + ray.direction * (2.0 / glm::dot(ray.direction, camera.axes().forward));
    EXPECT_LT(glm::length(reached - corners[size_t(i)]), 1e-12) << "corner " << i;
  }
}

// By hand, for the spec camera (eye (0, 0, 3.4) looking down -z, fovy 45):
// the point (1, 0.5, 0) is 3.4 ahead; a 200 x 100 picture's focal length is
// 50 / tan(22.5 deg) = 120.7107 pixels, so it lands at (99.5 + 35.5032,
// 49.5 - 17.7516).
TEST(Camera, ThePointOfASpecSceneLandsWhereTheLensSays) {
  const Camera camera = spec_camera();
  EXPECT_NEAR(camera.focal_length_pixels(100), 120.71067811865476, 1e-12);
  const Projected p = camera.project({1.0, 0.5, 0.0}, 200, 100);
  EXPECT_NEAR(p.depth, 3.4, 1e-15);
  EXPECT_NEAR(p.px, 99.5 + 120.71067811865476 / 3.4, 1e-12);
  EXPECT_NEAR(p.py, 49.5 - 0.5 * 120.71067811865476 / 3.4, 1e-12);
}

// The pose is the camera's frame in the world (OpenGL's camera axes: it
// looks down its -z with +y up) and undoes the view matrix.
TEST(Camera, ThePoseIsTheInverseOfTheView) {
  const Camera camera = tilted_camera();
  const glm::dmat4 pose = camera.pose();
  EXPECT_EQ(glm::dvec3(pose[3]), camera.eye);
  EXPECT_LT(glm::length(glm::dvec3(pose[2]) + glm::normalize(camera.target - camera.eye)), 1e-15);
  const glm::dmat4 identity = pose * camera.view();
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(identity[c][r], c == r ? 1.0 : 0.0, 1e-14);
}

// A window depth the GL writes is read back as the distance along the view axis.
TEST(Camera, WindowDepthReadsBackAsViewDepth) {
  const Camera camera = spec_camera();
  const glm::dmat4 projection = camera.projection(1.0, 0.05);
  for (const double depth : {0.05, 1.0, 3.4, 1e3}) {
    const glm::dvec4 clip = projection * glm::dvec4(0.0, 0.0, -depth, 1.0);
    EXPECT_NEAR(view_depth_of_window_depth(projection, 0.5 * clip.z / clip.w + 0.5), depth, 1e-9 * depth);
  }
  EXPECT_EQ(view_depth_of_window_depth(projection, 1.0), INFINITY);
}

}  // namespace
}  // namespace umbra
