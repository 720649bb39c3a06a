// Which vertices' stars the self-intersection search may skip: only those
// whose triangles provably meet one another only where they share.
#include "mesh/check/simple_stars.hpp"

#include <cmath>
#include <numeric>

#include <gtest/gtest.h>

#include "mesh/check/self_intersections.hpp"

namespace umbra {
namespace {

using Triangle = std::array<uint32_t, 3>;

struct Star {
  std::vector<glm::dvec3> positions;  // the centre is vertex 0
  std::vector<Triangle> triangles;

  std::vector<uint32_t> all() const {
    std::vector<uint32_t> tested(triangles.size());
    std::iota(tested.begin(), tested.end(), 0u);
    return tested;
  }
  bool centre_simple() const { return find_simple_stars(positions, triangles, all())[0] == 1; }
  size_t crossing_pairs() const {
    std::vector<uint32_t> face(triangles.size());
    std::iota(face.begin(), face.end(), 0u);
    return find_self_intersections(positions, triangles, face, 10.0, 10).face_pairs;
  }
};

// A closed fan round the origin through ring points at the given angles (in
// turns) and heights, each triangle wound counterclockwise seen from +z.
Star fan(const std::vector<double>& turns, const std::vector<double>& heights) {
  Star star;
  star.positions.push_back(glm::dvec3(0.0));
  for (size_t k = 0; k < turns.size(); ++k)
    star.positions.push_back({std::cos(2 * M_PI * turns[k]), std::sin(2 * M_PI * turns[k]), heights[k]});
  const uint32_t n = uint32_t(turns.size());
  for (uint32_t k = 0; k < n; ++k) star.triangles.push_back({0, 1 + k, 1 + (k + 1) % n});
  return star;
}
Star flat_hexagon() { return fan({0, 1 / 6., 2 / 6., 3 / 6., 4 / 6., 5 / 6.}, {0, 0, 0, 0, 0, 0}); }

TEST(SimpleStars, AFlatFanIsSimpleAndItsRimIsNot) {
  const Star star = flat_hexagon();
  const std::vector<uint8_t> simple = find_simple_stars(star.positions, star.triangles, star.all());
  EXPECT_EQ(simple[0], 1);
  for (size_t v = 1; v < simple.size(); ++v) EXPECT_EQ(simple[v], 0) << v;  // on the border
}

TEST(SimpleStars, ConesSaddlesAndSteepFansAreSimple) {
  EXPECT_TRUE(fan({0, 1 / 5., 2 / 5., 3 / 5., 4 / 5.}, {-1, -1, -1, -1, -1}).centre_simple());  // a cone's apex
  EXPECT_TRUE(fan({0, 1 / 6., 2 / 6., 3 / 6., 4 / 6., 5 / 6.}, {1, -1, 1, -1, 1, -1}).centre_simple());  // a monkey saddle
  // Nearly vertical: the fan is seen along x, where it still turns once.
  Star wall = flat_hexagon();
  for (glm::dvec3& p : wall.positions) p = {1e-3 * p.x, p.y, p.x};
  EXPECT_TRUE(wall.centre_simple());
}

TEST(SimpleStars, WindingDoesNotMatterOnlyTheShape) {
  Star star = flat_hexagon();
  std::swap(star.triangles[2][1], star.triangles[2][2]);  // one triangle written the other way round
  std::swap(star.triangles[4][0], star.triangles[4][1]);
  EXPECT_TRUE(star.centre_simple());
}

TEST(SimpleStars, AFanThatFoldsOverItselfIsNotSimpleAndItsOverlapsAreFound) {
  // The third ring point pulled back past the fourth: two triangles turn
  // clockwise and overlap their neighbours in the plane.
  const Star folded = fan({0, 1 / 6., 0.45, 0.40, 4 / 6., 5 / 6.}, {0, 0, 0, 0, 0, 0});
  EXPECT_FALSE(folded.centre_simple());
  EXPECT_GT(folded.crossing_pairs(), 0u);
  EXPECT_EQ(flat_hexagon().crossing_pairs(), 0u);
}

TEST(SimpleStars, AFanThatGoesRoundTwiceIsNotSimple) {
  // Twelve sixths of a turn, climbing: seen along z it covers the plane twice.
  std::vector<double> turns, heights;
  for (int k = 0; k < 12; ++k) turns.push_back(k / 6.0), heights.push_back(k < 6 ? 0.1 * k : 0.1 * (12 - k));
  EXPECT_FALSE(fan(turns, heights).centre_simple());
}

TEST(SimpleStars, StarsThatAreNotOneClosedFanAreNotSimple) {
  Star open = flat_hexagon();
  open.triangles.pop_back();
  EXPECT_FALSE(open.centre_simple());  // a border vertex

  Star fin = flat_hexagon();
  fin.positions.push_back({0.5, 0.0, 1.0});
  fin.triangles.push_back({0, 1, 7});  // a third triangle on the edge from the centre to ring point 1
  EXPECT_FALSE(fin.centre_simple());

  Star bowtie = flat_hexagon();  // two fans meeting at the centre: a non-manifold vertex
  const Star upper = fan({0, 1 / 3., 2 / 3.}, {1, 1, 1});
  for (size_t k = 1; k < upper.positions.size(); ++k) bowtie.positions.push_back(upper.positions[k] + glm::dvec3(0, 0, 1));
  for (const Triangle& t : upper.triangles) bowtie.triangles.push_back({0, t[1] + 6, t[2] + 6});
  EXPECT_FALSE(bowtie.centre_simple());

  // A triangle left out of the search (as one with collinear corners is) opens the fan.
  const Star star = flat_hexagon();
  EXPECT_EQ(find_simple_stars(star.positions, star.triangles, {0, 1, 2, 3, 4})[0], 0);
}

}  // namespace
}  // namespace umbra
