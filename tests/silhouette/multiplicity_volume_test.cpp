// The edge-multiplicity volume of arbitrary triangle soups: its stencil count
// at a point is the number of the soup's triangles between the point and the
// light, exactly what per-triangle volumes count.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

#include <tbb/task_arena.h>

#include <glm/geometric.hpp>

#include "mesh/topology/silhouette_components.hpp"
#include "mesh/topology/edge_table.hpp"
#include "silhouette/mesh_caster.hpp"
#include "silhouette/mesh_volume.hpp"
#include "silhouette/multiplicity_volume.hpp"
#include "silhouette/parallel_append.hpp"
#include "silhouette/volume_topology.hpp"
#include "volume_test_util.hpp"

namespace umbra {
namespace {

using Triangles = std::vector<std::array<uint32_t, 3>>;

struct Soup {
  std::vector<glm::dvec3> positions;
  Triangles triangles;
};

// `count` triangles over a pool of `pool` random points in [-0.5, 0.5]^3:
// with so few points they share edges in every way (borders, three and more
// faces on an edge, both windings), cross each other, and repeat.
Soup random_soup(std::mt19937& rng, int pool, int count) {
  std::uniform_real_distribution<double> coordinate(-0.5, 0.5);
  std::uniform_int_distribution<uint32_t> vertex(0, uint32_t(pool - 1));
  Soup s;
  for (int i = 0; i < pool; ++i) s.positions.push_back({coordinate(rng), coordinate(rng), coordinate(rng)});
  while (int(s.triangles.size()) < count) {
    const std::array<uint32_t, 3> t{vertex(rng), vertex(rng), vertex(rng)};
    if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) s.triangles.push_back(t);
  }
  return s;
}

MultiplicityAdjacency all_faces(const Soup& s) {
  return build_multiplicity_adjacency(s.positions, s.triangles, build_edge_table(s.triangles, s.positions.size()),
                                      std::vector<uint8_t>(s.triangles.size(), 1));
}

// The solid angle triangle abc subtends at the origin, signed: positive when
// abc turns counter-clockwise seen from the origin's far side (Van Oosterom
// and Strackee 1983).
double solid_angle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
  const double numerator = glm::dot(a, glm::cross(b, c));
  const double denominator = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
  return 2.0 * std::atan2(numerator, denominator);
}

// How many times the volume winds round `q` (its stencil count there), with
// every vertex at infinity drawn `far` beyond its finite point: a closed
// surface either way, the same count for points nearer than that.
double winding_number(const ShadowVolume& v, const glm::dvec3& light, const glm::dvec3& q, double far) {
  const auto point = [&](uint32_t i) {
    const glm::dvec4& p = v.vertices[i];
    if (p.w == 1.0) return glm::dvec3(p);
    const glm::dvec3 d(p);  // P - L
    return light + d + far * glm::normalize(d);
  };
  double sum = 0.0;
  for (const auto& t : v.triangles) sum += solid_angle(point(t[0]) - q, point(t[1]) - q, point(t[2]) - q);
  return sum / (4.0 * M_PI);
}

// The number of triangles the segment from q to the light crosses, or -1
// when it passes too close to an edge or end for doubles to be sure.
int crossings(const Soup& s, const glm::dvec3& q, const glm::dvec3& light) {
  const glm::dvec3 d = light - q;
  int count = 0;
  for (const auto& t : s.triangles) {
    const glm::dvec3 a = s.positions[t[0]], e1 = s.positions[t[1]] - a, e2 = s.positions[t[2]] - a;
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    const double scale = glm::length(d) * glm::length(e1) * glm::length(e2);
    if (std::abs(det) < 1e-9 * scale) {  // parallel: crosses only if within the plane, never counted
      if (std::abs(glm::dot(glm::cross(e1, e2), q - a)) < 1e-9 * glm::length(glm::cross(e1, e2))) return -1;
      continue;
    }
    const glm::dvec3 r = q - a;
    const double u = glm::dot(r, p) / det;
    const glm::dvec3 qv = glm::cross(r, e1);
    const double v = glm::dot(d, qv) / det, w = glm::dot(e2, qv) / det;
    const double margin = 1e-7;
    const bool inside = u > 0 && v > 0 && u + v < 1 && w > 0 && w < 1;
    const bool near = std::abs(u) < margin || std::abs(v) < margin || std::abs(1 - u - v) < margin ||
                      std::abs(w) < margin || std::abs(1 - w) < margin;
    if (near && (u > -margin && v > -margin && u + v < 1 + margin && w > -margin && w < 1 + margin)) return -1;
    count += inside;
  }
  return count;
}

TEST(MultiplicityVolume, CountsAtSamplePointsEqualTheTrianglesCrossedOnTheWayToTheLight) {
  std::mt19937 rng(20261124);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int compared = 0, shadowed = 0, deep = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Soup s = random_soup(rng, 9, 14);
    const glm::dvec3 light(2.0 * unit(rng), 2.0 * unit(rng), 2.0 + unit(rng));
    const ShadowVolume v = multiplicity_shadow_volume(s.positions, all_faces(s), light);
    ASSERT_TRUE(has_no_boundary(v)) << "trial " << trial;
    for (int k = 0; k < 60; ++k) {
      // Points round and behind the soup as seen from the light.
      const glm::dvec3 q = 0.7 * glm::dvec3(unit(rng), unit(rng), unit(rng)) - (0.3 + 0.5 * (unit(rng) + 1.0)) * glm::normalize(light);
      const int expected = crossings(s, q, light);
      if (expected < 0) continue;
      const double w = winding_number(v, light, q, 1e4);
      ASSERT_NEAR(w, expected, 1e-6) << "trial " << trial << ", point " << k;
      ++compared;
      shadowed += expected > 0;
      deep += expected > 2;
    }
  }
  // The test means something only if many points are behind several layers.
  EXPECT_GT(compared, 2000);
  EXPECT_GT(shadowed, 500);
  EXPECT_GT(deep, 50);
}

// The volume as a signed chain: each cap triangle by its sorted points, +1 or
// -1 by its orientation, and each side quad by its finite edge, +1 or -1 by
// the edge's direction. A quad and its reverse are split along different
// diagonals, so this is where they cancel.
using Point = std::array<double, 4>;
std::map<std::vector<Point>, int> chain(const ShadowVolume& v) {
  std::map<std::vector<Point>, int> c;
  const auto at = [&](uint32_t i) {
    const glm::dvec4& p = v.vertices[i];
    return Point{p.x, p.y, p.z, p.w};
  };
  for (const auto& t : v.triangles) {
    const std::array<Point, 3> p{at(t[0]), at(t[1]), at(t[2])};
    const int finite = int(p[0][3] == 1.0) + int(p[1][3] == 1.0) + int(p[2][3] == 1.0);
    if (finite == 0 || finite == 3) {  // a cap: sorting is a rotation (+1) or a swap of two (-1)
      std::vector<Point> key(p.begin(), p.end());
      std::sort(key.begin(), key.end());
      const size_t first = size_t(std::find(p.begin(), p.end(), key[0]) - p.begin());
      c[key] += p[(first + 1) % 3] == key[1] ? 1 : -1;
    } else if (finite == 2) {  // a quad's half (v, u, u'): its edge runs u -> v
      size_t i = 0;
      while (p[i][3] != 1.0 || p[(i + 1) % 3][3] != 1.0) ++i;
      const Point v_point = p[i], u_point = p[(i + 1) % 3];
      c[{std::min(u_point, v_point), std::max(u_point, v_point)}] += u_point < v_point ? 1 : -1;
    }  // a quad's other half, (v, u', v'), adds nothing new
  }
  for (auto it = c.begin(); it != c.end();) it = it->second == 0 ? c.erase(it) : std::next(it);
  return c;
}

TEST(MultiplicityVolume, IsThePerTriangleVolumesWithEverySharedQuadCancelled) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 30; ++trial) {
    const Soup s = random_soup(rng, 7, 12);
    const glm::dvec3 light(unit(rng), unit(rng), 2.5);
    const ShadowVolume multiplicity = multiplicity_shadow_volume(s.positions, all_faces(s), light);
    const ShadowVolume per_triangle = per_triangle_volume(s.positions, s.triangles, light);
    EXPECT_EQ(chain(multiplicity), chain(per_triangle)) << "trial " << trial;
    // And it is smaller: only the quads that do not cancel are drawn.
    EXPECT_LE(multiplicity.side_quads, per_triangle.side_quads);
  }
}

TEST(MultiplicityVolume, OfAnySubsetOfFacesIsThatSubsetsPerTriangleVolumes) {
  // Any faces, edges shared with faces left out included: what a mesh cast
  // in runs of its faces (each a volume of its own) relies on.
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Soup s = random_soup(rng, 7, 14);
    std::vector<uint8_t> in(s.triangles.size());
    Triangles subset;
    for (size_t t = 0; t < s.triangles.size(); ++t)
      if ((in[t] = rng() % 2)) subset.push_back(s.triangles[t]);
    const glm::dvec3 light(unit(rng), unit(rng), 2.5);
    const ShadowVolume part = multiplicity_shadow_volume(
        s.positions, build_multiplicity_adjacency(s.positions, s.triangles, build_edge_table(s.triangles, s.positions.size()), in),
        light);
    EXPECT_TRUE(part.triangles.empty() || has_no_boundary(part)) << "trial " << trial;
    EXPECT_EQ(chain(part), chain(per_triangle_volume(s.positions, subset, light))) << "trial " << trial;
  }
}

// A soup of many blocks of faces and edges: its volume is the same, index
// for index, on one thread and on several, and counts what per-triangle
// volumes count (checked above on small soups).
TEST(MultiplicityVolume, MadeOnEveryCoreTheSameWhateverTheThreads) {
  std::mt19937 rng(7);
  const Soup soup = random_soup(rng, 4000, 60000);
  const EdgeTable edges = build_edge_table(soup.triangles, soup.positions.size());
  const MultiplicityAdjacency mesh =
      build_multiplicity_adjacency(soup.positions, soup.triangles, edges, std::vector<uint8_t>(soup.triangles.size(), 1));
  ASSERT_GT(mesh.pair_uses.size() + mesh.other_vertices.size(), 2 * kAppendBlock);
  const glm::dvec3 light(0.3, 2.1, 1.7);
  const auto volume_on = [&](int threads) {
    MeshVolumeIndices volume;
    tbb::task_arena(threads).execute([&] {
      std::vector<int8_t> side;
      classify_light_sides(soup.positions, mesh, light, side);
      append_multiplicity_caps(mesh, side, uint32_t(soup.positions.size()), volume);
      append_multiplicity_quads(mesh, side, uint32_t(soup.positions.size()), volume);
    });
    return std::vector<uint32_t>(volume.buffer.begin(), volume.buffer.begin() + volume.count);
  };
  const std::vector<uint32_t> one = volume_on(1);
  EXPECT_EQ(volume_on(2), one);
  EXPECT_EQ(volume_on(5), one);
}

TEST(MultiplicityVolume, AFaceWhosePlaneHoldsTheLightCastsNothing) {
  // The triangle lies in the plane z = 0, and so does the light.
  const Soup s{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}};
  const ShadowVolume v = multiplicity_shadow_volume(s.positions, all_faces(s), {3, 4, 0});
  EXPECT_TRUE(v.triangles.empty());
  // A degenerate one casts nothing either, from anywhere.
  const Soup line{{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, {{0, 1, 2}}};
  EXPECT_TRUE(multiplicity_shadow_volume(line.positions, all_faces(line), {0.3, 0.2, 5}).triangles.empty());
}

TEST(MultiplicityVolume, AClosedCubeLitFromAboveCountsBothOfItsLayers) {
  // The unit cube lit from straight above its centre: only the top faces the
  // light; the bottom and the four sides (the light is between each side's
  // plane and the opposite side) face away. Oriented toward the light, the
  // top keeps its winding and every other face is reversed. The top's 4
  // edges then have both faces running the same way (m = 2, drawn twice);
  // every other edge joins two reversed faces, which still run opposite ways
  // (m = 0). So 8 quads, and a light cap on each of the 12 faces: a point
  // below the cube is behind 2 layers, as per-triangle volumes count it.
  const std::vector<glm::dvec3> p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const Triangles t{{0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                    {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  const Soup cube{p, t};
  const ShadowVolume v = multiplicity_shadow_volume(cube.positions, all_faces(cube), {0.5, 0.5, 3.0});
  EXPECT_EQ(v.light_cap_triangles, 12);
  EXPECT_EQ(v.side_quads, 8);
}

}  // namespace
}  // namespace umbra
