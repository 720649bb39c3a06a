#include "silhouette/sphere_volume.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "silhouette/volume_topology.hpp"
#include "volume_test_util.hpp"

namespace umbra {
namespace {

void expect_near(const glm::dvec3& actual, const glm::dvec3& expected, double tolerance = 1e-12) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

TEST(TangentCircle, OnTheAxis) {
  // LC = 5, R = 3: PL = (25 - 9) / 5 = 3.2, r = sqrt(25 - 9 - 3.2^2) = 2.4.
  const TangentCircle c = tangent_circle({0, 0, 0}, 3.0, {0, 0, 5});
  expect_near(c.center, {0, 0, 1.8});
  EXPECT_NEAR(c.radius, 2.4, 1e-12);
  // LC = (0, 0, -5): x and y tie for smallest, so [0, -z, y] = (0, 5, 0).
  expect_near(c.u, {0, 2.4, 0});
  expect_near(c.v, {-2.4, 0, 0});  // u x LC = (-12, 0, 0), scaled to r
}

TEST(TangentCircle, OffAxis) {
  // LC = (0, -3, -4), |LC| = 5, R = 3: P = L + 3.2 * (0, -0.6, -0.8).
  const glm::dvec3 center(1, 1, 1), light(1, 4, 5);
  const TangentCircle c = tangent_circle(center, 3.0, light);
  expect_near(c.center, {1, 4 - 1.92, 5 - 2.56});
  EXPECT_NEAR(c.radius, 2.4, 1e-12);
  expect_near(c.u, {0, 1.92, -1.44});  // skips x: [0, -z, y] = (0, 4, -3), scaled to 2.4
}

TEST(TangentCircle, PerpendicularSkipsTheSmallestCoordinate) {
  const glm::dvec3 light(0, 0, 0);
  EXPECT_EQ(tangent_circle({5, 0.1, 2}, 1.0, light).u.y, 0.0);  // y smallest: [-z, 0, x]
  EXPECT_EQ(tangent_circle({0.1, 5, 2}, 1.0, light).u.x, 0.0);  // x smallest: [0, -z, y]
  EXPECT_EQ(tangent_circle({2, 5, 0.1}, 1.0, light).u.z, 0.0);  // z smallest: [-y, x, 0]
}

TEST(TangentCircle, RejectsALightInsideOrOnTheSphere) {
  EXPECT_THROW(tangent_circle({0, 0, 0}, 1.0, {0, 0, 0.5}), std::invalid_argument);
  EXPECT_THROW(tangent_circle({0, 0, 0}, 1.0, {0, 0, 1}), std::invalid_argument);
}

TEST(SphereVolume, PolygonVerticesAreTangencyPoints) {
  const glm::dvec3 center(0.1, -0.2, 0.3), light(0.6, 0.8, 1.6);
  const double radius = 0.35;
  const ShadowVolume v = sphere_volume(center, radius, light, 64);
  for (int k = 0; k < 64; ++k) {
    const glm::dvec3 q(v.vertices[size_t(k)]);
    EXPECT_NEAR(glm::length(q - center), radius, 1e-12);
    EXPECT_NEAR(glm::dot(q - center, q - light), 0.0, 1e-12);  // the ray from L touches the sphere at Q
  }
}

TEST(SphereVolume, LightCapFacesTheLightAndEveryFaceOutward) {
  const glm::dvec3 center(0, 0, -0.3), light(0.6, 0.8, 1.6);
  const ShadowVolume v = sphere_volume(center, 0.35, light, 16);
  EXPECT_EQ(v.side_quads, 16);
  EXPECT_EQ(v.light_cap_triangles, 16);  // fans round the cap's centre
  EXPECT_EQ(v.dark_cap_triangles, 16);
  for (int i = 0; i < v.light_cap_triangles; ++i)
    EXPECT_GT(glm::dot(test::face_normal(v, v.triangles[size_t(i)]), light - center), 0.0);
  // A point inside the volume (behind the sphere on the axis) is on the inner
  // side of every side quad's plane.
  const glm::dvec3 inside = center + 2.0 * (center - light);
  for (size_t i = size_t(v.light_cap_triangles + v.dark_cap_triangles); i < v.triangles.size(); i += 2) {
    const auto& t = v.triangles[i];
    const glm::dvec3 b(v.vertices[t[0]]), a(v.vertices[t[1]]);
    const glm::dvec3 normal = glm::cross(a - b, glm::dvec3(v.vertices[t[2]]));
    EXPECT_LT(glm::dot(normal, inside - b), 0.0);
  }
}

TEST(SphereVolume, CapsAtInfinityStayWellConditionedWhenTheLightAlmostTouchesTheSphere) {
  // A light 1e-9 R outside the sphere: the cone is 4e-5 rad short of a half
  // space, so its directions at infinity lie almost in one plane. Every
  // triangle of the cap at infinity must still span a solid corner (the
  // determinant of its unit directions), or float clipping loses it; a fan
  // from one rim vertex would give determinants near 4e-5.
  const glm::dvec3 center(0.1, -0.1, -0.3), axis = glm::normalize(glm::dvec3(0.3, 0.4, 0.866));
  const double radius = 0.4;
  const ShadowVolume v = sphere_volume(center, radius, center + axis * (radius * (1.0 + 1e-9)), 64);
  EXPECT_TRUE(is_closed_and_consistently_oriented(v));
  int far_triangles = 0;
  for (const auto& t : v.triangles) {
    if (v.vertices[t[0]].w != 0.0 || v.vertices[t[1]].w != 0.0 || v.vertices[t[2]].w != 0.0) continue;
    ++far_triangles;
    glm::dvec3 d[3];
    for (int i = 0; i < 3; ++i) d[i] = glm::normalize(glm::dvec3(v.vertices[t[size_t(i)]]));
    EXPECT_GT(std::abs(glm::dot(glm::cross(d[0], d[1]), d[2])), 0.05);
  }
  EXPECT_EQ(far_triangles, 64);  // the dark cap: a fan round the cone's axis
}

TEST(SphereVolume, IsClosedForManyLightsAndSegmentCounts) {
  for (int n : {3, 4, 7, 64, 1000})
    for (double angle = 0.0; angle < 360.0; angle += 30.0) {
      const double a = angle * M_PI / 180.0;
      const glm::dvec3 light(1.5 * std::cos(a), 1.5 * std::sin(a), 1.2 + angle / 360.0);
      EXPECT_TRUE(is_closed_and_consistently_oriented(sphere_volume({0.1, 0.2, -0.3}, 0.4, light, n)))
          << "n = " << n << ", angle = " << angle;
    }
}

TEST(SphereVolume, StableWhenTheLightIsFar) {
  // r = R sqrt(LC^2 - R^2) / LC tends to R; the textbook sqrt(LC^2 - R^2 - PL^2)
  // would cancel to garbage at LC = 1e8.
  const TangentCircle c = tangent_circle({0, 0, 0}, 0.5, {0, 0, 1e8});
  EXPECT_NEAR(c.radius, 0.5, 1e-15);
  EXPECT_NEAR(c.center.z, 0.5 * 0.5 / 1e8, 1e-15);
}

}  // namespace
}  // namespace umbra
