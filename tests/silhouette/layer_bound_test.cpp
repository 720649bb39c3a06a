// layer_bound: never less than the number of triangles a ray from the light
// crosses, and small where few layers lie over one another.
#include <gtest/gtest.h>

#include <random>

#include <glm/geometric.hpp>

#include "silhouette/layer_bound.hpp"

namespace umbra {
namespace {

using Triangles = std::vector<std::array<uint32_t, 3>>;

// How many triangles the ray from `light` along `direction` crosses
// (Moeller and Trumbore 1997), doubles; grazing hits count too.
int crossings(const std::vector<glm::dvec3>& p, const Triangles& triangles, const glm::dvec3& light,
              const glm::dvec3& direction) {
  int count = 0;
  for (const auto& t : triangles) {
    const glm::dvec3 e1 = p[t[1]] - p[t[0]], e2 = p[t[2]] - p[t[0]], h = glm::cross(direction, e2);
    const double det = glm::dot(e1, h);
    if (std::abs(det) < 1e-300) continue;
    const glm::dvec3 s = light - p[t[0]];
    const double u = glm::dot(s, h) / det;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(direction, q) / det, along = glm::dot(e2, q) / det;
    count += u >= -1e-12 && v >= -1e-12 && u + v <= 1 + 1e-12 && along > 0;
  }
  return count;
}

// `layers` squares of side `size` in planes z = -k * gap, centred under the light.
void stacked_squares(int layers, double size, double gap, std::vector<glm::dvec3>& p, Triangles& t) {
  for (int k = 0; k < layers; ++k) {
    const uint32_t first = uint32_t(p.size());
    const double z = -k * gap;
    p.insert(p.end(), {{-size, -size, z}, {size, -size, z}, {size, size, z}, {-size, size, z}});
    t.push_back({first, first + 1, first + 2});
    t.push_back({first, first + 2, first + 3});
  }
}

TEST(LayerBound, NoRayFromTheLightCrossesMoreTrianglesThanTheBound) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 30; ++trial) {
    std::vector<glm::dvec3> p;
    Triangles t;
    for (int i = 0; i < 40; ++i) p.push_back({0.5 * unit(rng), 0.5 * unit(rng), 0.5 * unit(rng)});
    for (int i = 0; i < 60; ++i) t.push_back({uint32_t(rng() % 40), uint32_t(rng() % 40), uint32_t(rng() % 40)});
    // Lights far (one grid) and close or inside (the cube).
    const glm::dvec3 light = trial % 2 ? glm::dvec3(unit(rng), unit(rng), 3.0) : 0.3 * glm::dvec3(unit(rng), unit(rng), unit(rng));
    const int bound = layer_bound(p, t, light, 20);  // below the 60 triangles, so the grid runs
    int most = 0;
    for (int k = 0; k < 4000; ++k) {
      const glm::dvec3 towards = 0.5 * glm::dvec3(unit(rng), unit(rng), unit(rng));
      most = std::max(most, crossings(p, t, light, towards - light));
    }
    EXPECT_GE(bound, std::min(most, 21)) << "trial " << trial;  // 21: more than the limit
    EXPECT_GT(most, 0);
  }
}

TEST(LayerBound, RefinedCellsStillBoundEveryRayOnRandomInputs) {
  // Thousands of thin triangles, most of them nearly edge-on to the light
  // (so that cells full of footprints are split), in clusters over wide
  // sheets: the bound,
  // refined, is still no less than the crossings of any ray, whether the
  // ray aims at random or at a triangle's centre or corners, where the
  // layers stack deepest.
  std::mt19937 rng(29);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 6; ++trial) {
    const glm::dvec3 light = trial % 3 == 2 ? glm::dvec3(0.1, -0.2, 0.05) : glm::dvec3(unit(rng), unit(rng), 4.0 + trial);
    std::vector<glm::dvec3> p;
    Triangles t;
    for (int cluster = 0; cluster < 6; ++cluster) {
      const glm::dvec3 centre = 0.6 * glm::dvec3(unit(rng), unit(rng), unit(rng));
      for (int i = 0; i < 400; ++i) {
        const glm::dvec3 a = centre + 0.15 * glm::dvec3(unit(rng), unit(rng), unit(rng));
        const glm::dvec3 towards_light = glm::normalize(light - a);
        const glm::dvec3 across = glm::normalize(glm::cross(towards_light, glm::dvec3(unit(rng), unit(rng), unit(rng))));
        // Edge-on: two corners along the ray from the light, the third a hair across it (or a fair way, one in five).
        const double width = i % 5 ? 1e-4 : 0.05;
        const uint32_t first = uint32_t(p.size());
        p.insert(p.end(), {a, a + 0.2 * towards_light, a + 0.1 * towards_light + width * across});
        t.push_back({first, first + 1, first + 2});
      }
    }
    // And 20 wide sheets below them all, which every downward ray crosses.
    for (int k = 0; k < 20; ++k) {
      const uint32_t first = uint32_t(p.size());
      const double z = -1.0 - 0.05 * k;
      p.insert(p.end(), {{-3, -3, z}, {3, -3, z}, {0, 3, z}});
      t.push_back({first, first + 1, first + 2});
    }
    const int bound = layer_bound(p, t, light, 255);
    int most = 0;
    const auto aim = [&](const glm::dvec3& target) { most = std::max(most, crossings(p, t, light, target - light)); };
    for (const auto& tri : t) {
      aim((p[tri[0]] + p[tri[1]] + p[tri[2]]) / 3.0);
      aim(p[tri[2]]);
    }
    for (int k = 0; k < 2000; ++k) aim(0.8 * glm::dvec3(unit(rng), unit(rng), unit(rng)));
    EXPECT_GE(bound, std::min(most, 256)) << "trial " << trial;
    EXPECT_GT(most, 20) << "trial " << trial;  // the sheets and some of the thin ones
    EXPECT_LE(bound, 255) << "trial " << trial;  // a bound, refined, not "more than the limit"
  }
}

TEST(LayerBound, ManyTrianglesSideBySideAreFewLayers) {
  // A 100 x 100 grid of squares (20,000 triangles) under the light: any ray
  // crosses at most 2 (at a shared edge), and a cell of the bound's grid
  // holds only the few triangles round it.
  std::vector<glm::dvec3> p;
  Triangles t;
  for (int i = 0; i <= 100; ++i)
    for (int j = 0; j <= 100; ++j) p.push_back({-1.0 + 0.02 * i, -1.0 + 0.02 * j, -1.0});
  for (uint32_t i = 0; i < 100; ++i)
    for (uint32_t j = 0; j < 100; ++j) {
      const uint32_t a = i * 101 + j;
      t.push_back({a, a + 101, a + 102});
      t.push_back({a, a + 102, a + 1});
    }
  const int bound = layer_bound(p, t, {0.1, 0.2, 2.0}, 255);
  EXPECT_GE(bound, 2);
  EXPECT_LE(bound, 12);
}

TEST(LayerBound, SaysMoreThanTheLimitForTooManyStackedLayers) {
  std::vector<glm::dvec3> p;
  Triangles t;
  stacked_squares(300, 0.5, 0.001, p, t);
  EXPECT_EQ(layer_bound(p, t, {0.0, 0.0, 2.0}, 255), 256);
  // Below the limit, the stack's depth (and not much more).
  std::vector<glm::dvec3> q;
  Triangles u;
  stacked_squares(100, 0.5, 0.001, q, u);
  const int bound = layer_bound(q, u, {0.0, 0.0, 2.0}, 255);
  EXPECT_GE(bound, 100);
  EXPECT_LE(bound, 200);  // a ray near a diagonal crosses both triangles of a square
}

TEST(LayerBound, ALightInsideAClosedBoxSeesOneLayerEachWay) {
  // The box [-1, 1]^3 of 12 triangles repeated 30 times over (360
  // triangles, so the grid runs), lit from inside: every ray crosses 30
  // layers, or 60 through an edge shared by two triangles. The grid has 16
  // cells a side per cube face, so a cell where three of the box's faces
  // meet in the light's view holds all three faces' triangles: at most
  // 3 x 2 x 30 = 180.
  std::vector<glm::dvec3> p{{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  const Triangles box{{0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                      {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  Triangles t;
  for (int k = 0; k < 30; ++k) t.insert(t.end(), box.begin(), box.end());
  const int bound = layer_bound(p, t, {0.1, -0.2, 0.3}, 255);
  EXPECT_GE(bound, 60);
  EXPECT_LE(bound, 180);
}

}  // namespace
}  // namespace umbra
