// Normals for smooth shading where a file gives none, against values worked
// out by hand: a cube's corners, a fold either side of the crease angle, a
// flat face against a bevel's slivers, and a degenerate triangle.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "mesh/topology/crease_normals.hpp"
#include "tests/mesh/mesh_builders.hpp"

namespace umbra {
namespace {

std::vector<std::array<uint32_t, 3>> triangles_of(const PolygonSoup& soup) {
  std::vector<std::array<uint32_t, 3>> triangles;
  for (size_t p = 0; p < soup.polygon_count(); ++p) triangles.push_back({soup.polygon(p)[0], soup.polygon(p)[1], soup.polygon(p)[2]});
  return triangles;
}

void expect_near(const glm::vec3& got, const glm::dvec3& want) {
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1e-6) << "component " << k;
}

// Faces at right angles keep their own normals under a 30-degree crease;
// over 90 degrees, each corner's is the mean of its three faces', each face
// weighted by its angle there (90 degrees, however it is cut into
// triangles) and by its flat face's area (the same for all six), so along
// the cube's diagonal. Weighting by triangle count would tilt it: a face's
// two triangles meet some corners twice and others once.
TEST(CreaseNormals, ACubesCornersKeepTheirFacesBelowARightAngleAndBlendAlongItsDiagonalAbove) {
  const PolygonSoup cube = test::unit_cube();
  const auto triangles = triangles_of(cube);
  const auto sharp = crease_normals(cube.points, triangles, 30.0);
  const auto smooth = crease_normals(cube.points, triangles, 100.0);
  for (size_t t = 0; t < triangles.size(); ++t) {
    const auto& [a, b, c] = triangles[t];
    const glm::dvec3 face = glm::normalize(glm::cross(cube.points[b] - cube.points[a], cube.points[c] - cube.points[a]));
    for (size_t k = 0; k < 3; ++k) {
      SCOPED_TRACE(testing::Message() << "triangle " << t << " corner " << k);
      expect_near(sharp[t][k], face);
      const glm::dvec3 p = cube.points[triangles[t][k]];
      expect_near(smooth[t][k], glm::normalize(p - glm::dvec3(0.5)));  // outward along the diagonal
    }
  }
}

// A fold of two triangles along the x axis, the second turned by `fold`
// degrees: below the crease angle the corners on the fold share the mean
// normal, turned half way; above it, each keeps its own.
TEST(CreaseNormals, AFoldIsSmoothBelowTheCreaseAngleAndSharpAbove) {
  const double fold = 40.0, r = fold * 3.141592653589793 / 180.0;
  const std::vector<glm::dvec3> points = {{0, 0, 0}, {1, 0, 0}, {0.5, -1, 0}, {0.5, std::cos(r), std::sin(r)}};
  const std::vector<std::array<uint32_t, 3>> triangles = {{0, 2, 1}, {0, 1, 3}};  // both wound to face +z at fold 0
  const glm::dvec3 first(0, 0, 1), second(0, -std::sin(r), std::cos(r));
  const auto smooth = crease_normals(points, triangles, fold + 1.0);
  // On the fold, both triangles' angles at points 0 and 1 are equal (isosceles), so the mean is half way.
  for (const glm::vec3& on_fold : {smooth[0][0], smooth[0][2], smooth[1][0], smooth[1][1]})
    expect_near(on_fold, glm::normalize(first + second));
  // Off the fold, each triangle's own.
  expect_near(smooth[0][1], first);
  expect_near(smooth[1][2], second);
  const auto sharp = crease_normals(points, triangles, fold - 1.0);
  for (size_t k = 0; k < 3; ++k) expect_near(sharp[0][k], first), expect_near(sharp[1][k], second);
}

// A flat face keeps nearly its own normal where a shallow bevel of small
// triangles meets it, however it is cut: a 10 x 10 square, fanned from
// either of two corners, with a bevel 1 wide falling at 10 degrees along
// one side, cut into 20 triangles. At each point of that side, both meet
// at the same angle (90 degrees at its ends, 180 between), so the normal is
// their faces' normals weighted by their faces' areas alone: 100 against
// 10 / cos 10. Weighted by angle alone it would be half way, 5 degrees off.
TEST(CreaseNormals, AFlatFaceOutweighsTheSliversOfABevelHoweverItIsCut) {
  const double slope = 10.0 * 3.141592653589793 / 180.0;
  std::vector<glm::dvec3> points;
  for (int k = 0; k <= 10; ++k) points.push_back({k, 0, 0});                             // 0..10: the side
  for (int k = 0; k <= 10; ++k) points.push_back({k, -1, -std::tan(slope)});             // 11..21: the bevel's foot
  points.push_back({0, 10, 0}), points.push_back({10, 10, 0});                          // 22, 23: the far corners
  const glm::dvec3 bevel(0, -std::sin(slope), std::cos(slope));
  const glm::dvec3 want = glm::normalize(100.0 * glm::dvec3(0, 0, 1) + 10.0 / std::cos(slope) * bevel);
  for (const uint32_t apex : {22u, 23u}) {
    SCOPED_TRACE(testing::Message() << "fanned from point " << apex);
    std::vector<std::array<uint32_t, 3>> triangles;
    for (uint32_t k = 0; k < 10; ++k) triangles.push_back({apex, k, k + 1});
    triangles.push_back(apex == 22 ? std::array<uint32_t, 3>{22, 10, 23} : std::array<uint32_t, 3>{23, 22, 0});
    const size_t top = triangles.size();
    for (uint32_t k = 0; k < 10; ++k) {
      triangles.push_back({k, 11 + k, 12 + k});
      triangles.push_back({k, 12 + k, k + 1});
    }
    const auto normals = crease_normals(points, triangles, 30.0);
    for (size_t t = 0; t < triangles.size(); ++t)
      for (size_t c = 0; c < 3; ++c) {
        if (triangles[t][c] > 10) continue;  // off the side: its own face's (or the fan's mean, at the apex)
        SCOPED_TRACE(testing::Message() << "triangle " << t << (t < top ? " (top)" : " (bevel)") << " at point " << triangles[t][c]);
        expect_near(normals[t][c], want);
      }
  }
}

// A degenerate triangle has no normal to give: its corners are drawn flat
// (0, 0, 0), and it adds nothing to its neighbours'.
TEST(CreaseNormals, ADegenerateTriangleIsDrawnFlatAndTiltsNoNeighbour) {
  const std::vector<glm::dvec3> points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
  const std::vector<std::array<uint32_t, 3>> triangles = {{0, 1, 2}, {0, 1, 3}};  // the second lies on the x axis
  const auto normals = crease_normals(points, triangles, 180.0);
  for (size_t k = 0; k < 3; ++k) {
    expect_near(normals[0][k], glm::dvec3(0, 0, 1));
    EXPECT_EQ(normals[1][k], glm::vec3(0.0f));
  }
}

}  // namespace
}  // namespace umbra
