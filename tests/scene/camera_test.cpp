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

Camera orthographic_camera() {
  Camera c = tilted_camera();
  c.ortho_height = 2.5;
  return c;
}

// A point on a pixel's ray projects back onto that pixel, at its distance
// along the view axis; and the GL's matrices send it to the same place.
TEST(Camera, APixelsRayProjectsBackOntoThePixel) {
  for (const Camera& camera : {spec_camera(), tilted_camera(), orthographic_camera()}) {
    const int width = 160, height = 90;
    const glm::dmat4 view_projection = camera.view_projection(double(width) / height, camera.orthographic() ? 0.0 : 0.05, 50.0);
    for (const auto& [px, py] : {std::pair{0.0, 0.0}, {159.0, 0.0}, {0.0, 89.0}, {82.25, 13.5}, {-0.5, 89.5}}) {
      const Ray ray = camera.pixel_ray(width, height, px, py);
      // A perspective's rays start at the eye; an orthographic one's on its eye's plane, along its axis.
      if (camera.orthographic()) {
        EXPECT_NEAR(glm::dot(ray.origin - camera.eye, camera.axes().forward), 0.0, 1e-15);
        EXPECT_LT(glm::length(ray.direction - camera.axes().forward), 1e-15);
      } else {
        EXPECT_EQ(ray.origin, camera.eye);
      }
      EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-15);
      const glm::dvec3 point = ray.origin + 7.0 * ray.direction;
      const Projected p = camera.project(point, width, height);
      EXPECT_NEAR(p.px, px, 1e-9);
      EXPECT_NEAR(p.py, py, 1e-9);
      EXPECT_NEAR(p.depth, 7.0 * glm::dot(ray.direction, camera.axes().forward), 1e-12);
      // The GL's rays from the window's coordinates (row 0 at the bottom): the same line.
      const WindowRays window = window_rays(view_projection, camera.eye, width, height);
      const glm::dvec3 at(px + 0.5, height - py - 0.5, 1.0);
      const glm::dvec3 start = window.origins * at, along = glm::normalize(window.directions * at);
      EXPECT_LT(glm::length(along - ray.direction), 1e-12);
      EXPECT_LT(glm::length(glm::cross(start - ray.origin, ray.direction)), 1e-12);
      // The GL: normalised device coordinates to pixels, row 0 at the bottom.
      const glm::dvec4 clip = view_projection * glm::dvec4(point, 1.0);
      EXPECT_NEAR((clip.x / clip.w + 1.0) / 2.0 * width - 0.5, px, 1e-9);
      EXPECT_NEAR((1.0 - clip.y / clip.w) / 2.0 * height - 0.5, py, 1e-9);
    }
  }
}

// The frustum's section at a depth is what the corner pixels' rays reach.
TEST(Camera, TheFrustumsCornersAreTheCornerPixelsRays) {
  for (const Camera& camera : {tilted_camera(), orthographic_camera()}) {
    const int width = 120, height = 80;
    const std::array<glm::dvec3, 4> corners = camera.section_corners(1.5, 2.0);
    const std::pair<double, double> pixels[4] = {{-0.5, 79.5}, {119.5, 79.5}, {119.5, -0.5}, {-0.5, -0.5}};
    for (int i = 0; i < 4; ++i) {
      const Ray ray = camera.pixel_ray(width, height, pixels[i].first, pixels[i].second);
      const double depth_of_origin = glm::dot(ray.origin - camera.eye, camera.axes().forward);
      const glm::dvec3 reached = ray.origin + ray.direction * ((2.0 - depth_of_origin) / glm::dot(ray.direction, camera.axes().forward));
      EXPECT_LT(glm::length(reached - corners[size_t(i)]), 1e-12) << "corner " << i;
    }
  }
}

// By hand, for an orthographic camera at (0, 0, 5) looking down -z, +y up,
// 4 high: a 200 x 100 picture shows 8 x 4, 25 pixels a unit, so (1, 0.5, 0)
// lands at (99.5 + 25, 49.5 - 12.5), 5 ahead; and the window depth its
// projection writes reads back as that.
TEST(Camera, AnOrthographicCamerasPointLandsWhereItsHeightSays) {
  Camera camera{{0.0, 0.0, 5.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}};
  camera.ortho_height = 4.0;
  EXPECT_TRUE(camera.orthographic());
  EXPECT_EQ(camera.focal_length_pixels(100), 25.0);
  const Projected p = camera.project({1.0, 0.5, 0.0}, 200, 100);
  EXPECT_NEAR(p.px, 124.5, 1e-12);
  EXPECT_NEAR(p.py, 37.0, 1e-12);
  EXPECT_NEAR(p.depth, 5.0, 1e-15);
  const glm::dmat4 projection = camera.projection(2.0, 0.0, 20.0);
  const glm::dvec4 clip = projection * glm::dvec4(0.0, 0.0, -5.0, 1.0);
  EXPECT_EQ(clip.w, 1.0);
  EXPECT_NEAR(view_depth_of_window_depth(projection, 0.5 * clip.z + 0.5), 5.0, 1e-12);
  EXPECT_NEAR(view_depth_of_window_depth(projection, 1.0), 20.0, 1e-12);
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
