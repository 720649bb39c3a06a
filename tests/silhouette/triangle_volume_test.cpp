#include "silhouette/triangle_volume.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "silhouette/volume_topology.hpp"
#include "volume_test_util.hpp"

namespace umbra {
namespace {

const glm::dvec3 kA(0, 0, 0), kB(1, 0, 0), kC(0, 1, 0);
const glm::dvec3 kLight(0.2, 0.3, 2.0);

TEST(TriangleVolume, HasThreeSideQuadsAndTwoCaps) {
  const auto v = triangle_volume(kA, kB, kC, kLight);
  ASSERT_TRUE(v);
  EXPECT_EQ(v->side_quads, 3);
  EXPECT_EQ(v->light_cap_triangles, 1);
  EXPECT_EQ(v->dark_cap_triangles, 1);
  EXPECT_EQ(v->triangles.size(), 8u);
  // The primed vertices are the unprimed ones pushed to infinity away from the light.
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(v->vertices[i].w, 1.0);
    EXPECT_EQ(v->vertices[i + 3], glm::dvec4(glm::dvec3(v->vertices[i]) - kLight, 0.0));
  }
}

TEST(TriangleVolume, IsTheSameWhateverTheVertexOrder) {
  std::array<glm::dvec3, 3> p{kA, kB, kC};
  const auto reference = test::oriented_faces(*triangle_volume(kA, kB, kC, kLight));
  std::sort(p.begin(), p.end(), [](auto& x, auto& y) { return std::tie(x.x, x.y, x.z) < std::tie(y.x, y.y, y.z); });
  int orders = 0;
  do {
    EXPECT_EQ(test::oriented_faces(*triangle_volume(p[0], p[1], p[2], kLight)), reference);
    ++orders;
  } while (std::next_permutation(p.begin(), p.end(),
                                 [](auto& x, auto& y) { return std::tie(x.x, x.y, x.z) < std::tie(y.x, y.y, y.z); }));
  EXPECT_EQ(orders, 6);
}

TEST(TriangleVolume, QuadOrientationFollowsTheTripleProduct) {
  // Light below instead of above: (AB x AC) . AL changes sign, so the same
  // vertex order must give the opposite winding of the light cap.
  const auto above = triangle_volume(kA, kB, kC, {0.2, 0.3, 2.0});
  const auto below = triangle_volume(kA, kB, kC, {0.2, 0.3, -2.0});
  EXPECT_GT(test::face_normal(*above, above->triangles[0]).z, 0.0);  // light cap faces the light
  EXPECT_LT(test::face_normal(*below, below->triangles[0]).z, 0.0);
}

TEST(TriangleVolume, LightCapFacesTheLightAndSideQuadsFaceOutward) {
  const auto v = triangle_volume(kA, kC, kB, kLight);  // listed clockwise seen from the light
  const glm::dvec3 centroid = (kA + kB + kC) / 3.0;
  EXPECT_GT(glm::dot(test::face_normal(*v, v->triangles[0]), kLight - kA), 0.0);
  // Each side quad's plane passes through the light; its outward normal points
  // away from the triangle's interior.
  for (size_t i = 2; i < v->triangles.size(); i += 2) {
    const auto& t = v->triangles[i];
    const glm::dvec3 a(v->vertices[t[0]]), b(v->vertices[t[1]]);
    const glm::dvec3 normal = glm::cross(b - a, glm::dvec3(v->vertices[t[2]]));  // third vertex is a direction
    EXPECT_LT(glm::dot(normal, centroid - a), 0.0);
    EXPECT_NEAR(glm::dot(normal, kLight - a), 0.0, 1e-12);
  }
}

TEST(TriangleVolume, IsClosedAndConsistentlyOriented) {
  for (const glm::dvec3& light : {glm::dvec3(0.2, 0.3, 2), glm::dvec3(5, -4, -1), glm::dvec3(0.3, 0.3, 1e-3)})
    EXPECT_TRUE(is_closed_and_consistently_oriented(*triangle_volume(kA, kB, kC, light)));
}

TEST(TriangleVolume, NoneWhenTheLightIsInTheTrianglesPlane) {
  EXPECT_FALSE(triangle_volume(kA, kB, kC, {3, 4, 0}));
  EXPECT_FALSE(triangle_volume(kA, kB, kC, {0.25, 0.25, 0}));  // even inside the triangle
}

TEST(TriangleVolume, NoneForCollinearOrRepeatedVertices) {
  EXPECT_FALSE(triangle_volume(kA, kB, {2, 0, 0}, kLight));
  EXPECT_FALSE(triangle_volume(kA, kA, kC, kLight));
}

TEST(VolumeTopology, DetectsAMissingOrFlippedFace) {
  ShadowVolume v = *triangle_volume(kA, kB, kC, kLight);
  ShadowVolume missing = v;
  missing.triangles.pop_back();
  EXPECT_FALSE(is_closed_and_consistently_oriented(missing));
  ShadowVolume flipped = v;
  std::swap(flipped.triangles[0][1], flipped.triangles[0][2]);
  EXPECT_FALSE(is_closed_and_consistently_oriented(flipped));
}

}  // namespace
}  // namespace umbra
