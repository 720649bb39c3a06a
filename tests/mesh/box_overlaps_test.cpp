#include "mesh/check/box_overlaps.hpp"

#include <algorithm>
#include <array>
#include <limits>
#include <atomic>
#include <mutex>
#include <random>
#include <set>

#include <gtest/gtest.h>

namespace umbra {
namespace {

using PairSet = std::set<std::pair<uint32_t, uint32_t>>;

PairSet brute_force_pairs(const std::vector<FloatBox>& boxes) {
  PairSet pairs;
  for (uint32_t i = 0; i < boxes.size(); ++i)
    for (uint32_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j])) pairs.insert({i, j});
  return pairs;
}

// Every pair the search visits, each as (smaller, larger), counting repeats.
std::multiset<std::pair<uint32_t, uint32_t>> searched_pairs(const std::vector<FloatBox>& boxes) {
  std::mutex lock;
  std::multiset<std::pair<uint32_t, uint32_t>> pairs;
  const bool complete = for_each_overlapping_pair(boxes, [&](const std::pair<uint32_t, uint32_t>* found, size_t count) {
    std::lock_guard<std::mutex> guard(lock);
    for (size_t k = 0; k < count; ++k) {
      const auto [i, j] = found[k];
      EXPECT_NE(i, j);
      pairs.insert({std::min(i, j), std::max(i, j)});
    }
    return true;
  });
  EXPECT_TRUE(complete);
  return pairs;
}

FloatBox box_at(const glm::dvec3& lo, const glm::dvec3& size) { return enclosing_box(lo, lo + size, lo + size); }

TEST(BoxOverlaps, RandomBoxesOfMixedSizesGiveExactlyTheBruteForcePairsEachOnce) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> where(-10.0, 10.0), small(0.0, 0.8);
  std::vector<FloatBox> boxes;
  for (int i = 0; i < 3000; ++i) boxes.push_back(box_at({where(rng), where(rng), where(rng)}, {small(rng), small(rng), small(rng)}));
  for (int i = 0; i < 5; ++i) boxes.push_back(box_at({where(rng), -10.0, where(rng)}, {0.1, 20.0, 0.1}));  // long slivers
  boxes.push_back(box_at({-11.0, -11.0, -11.0}, {22.0, 22.0, 22.0}));  // one box round all the others
  for (int i = 0; i < 40; ++i) boxes.push_back(boxes[size_t(i)]);      // exact copies, whose centres coincide
  const PairSet expected = brute_force_pairs(boxes);
  const auto found = searched_pairs(boxes);
  EXPECT_EQ(found.size(), expected.size());  // none twice
  EXPECT_EQ(PairSet(found.begin(), found.end()), expected);
  EXPECT_GT(expected.size(), boxes.size());
}

// Boxes of triangles whose corners come from a few vertices, so that many
// overlapping pairs share one: the pairs sharing a marked vertex are left
// out, and every other overlapping pair is visited, even where its two
// triangles share vertices that are not marked.
TEST(BoxOverlaps, PairsSharingAMarkedVertexAreLeftOutAndNoOthers) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> where(-3.0, 3.0), small(0.0, 0.8);
  std::uniform_int_distribution<uint32_t> vertex(0, 29);
  std::vector<FloatBox> boxes;
  std::vector<std::array<uint32_t, 3>> corners;
  for (int i = 0; i < 2000; ++i) {
    boxes.push_back(box_at({where(rng), where(rng), where(rng)}, {small(rng), small(rng), small(rng)}));
    std::array<uint32_t, 3> c{vertex(rng), vertex(rng), vertex(rng)};
    while (c[1] == c[0]) c[1] = vertex(rng);
    while (c[2] == c[0] || c[2] == c[1]) c[2] = vertex(rng);
    corners.push_back(c);
  }
  std::vector<uint8_t> marked(30, 0);
  for (uint32_t v = 0; v < 30; v += 3) marked[v] = 1;
  const PairSet overlapping = brute_force_pairs(boxes);
  PairSet expected;
  size_t shared_unmarked = 0;  // expected pairs whose triangles share only unmarked vertices
  for (const auto& [i, j] : overlapping) {
    bool marked_shared = false, shared = false;
    for (const uint32_t v : corners[i])
      for (const uint32_t w : corners[j])
        if (v == w) shared = true, marked_shared = marked_shared || marked[v];
    if (marked_shared) continue;
    expected.insert({i, j});
    shared_unmarked += shared;
  }
  FloatBox bounds = boxes[0];
  for (const FloatBox& b : boxes)
    for (int k = 0; k < 3; ++k)
      bounds.lo[size_t(k)] = std::min(bounds.lo[size_t(k)], b.lo[size_t(k)]), bounds.hi[size_t(k)] = std::max(bounds.hi[size_t(k)], b.hi[size_t(k)]);
  std::mutex lock;
  std::multiset<std::pair<uint32_t, uint32_t>> found;
  const SharedVertexSkip skip{[&](uint32_t i) { return corners[i]; }, &marked};
  EXPECT_TRUE(for_each_overlapping_pair(
      boxes.size(), bounds, [&](uint32_t i) { return boxes[i]; },
      [&](const std::pair<uint32_t, uint32_t>* pairs, size_t count) {
        std::lock_guard<std::mutex> guard(lock);
        for (size_t k = 0; k < count; ++k) found.insert({std::min(pairs[k].first, pairs[k].second), std::max(pairs[k].first, pairs[k].second)});
        return true;
      },
      skip));
  EXPECT_EQ(found.size(), expected.size());  // none twice
  EXPECT_EQ(PairSet(found.begin(), found.end()), expected);
  // The data hold both kinds: neighbours through unmarked vertices, which are
  // visited, and hundreds through marked ones, which are not.
  EXPECT_GT(shared_unmarked, 500u);
  EXPECT_LT(expected.size(), overlapping.size() - 300);
}

TEST(BoxOverlaps, BoxesThatOnlyTouchOverlapAndBoxesApartByOneFloatDoNot) {
  // Unit cubes side by side on a grid share faces, edges and corners.
  std::vector<FloatBox> boxes;
  for (int x = 0; x < 4; ++x)
    for (int y = 0; y < 4; ++y)
      for (int z = 0; z < 4; ++z) boxes.push_back(box_at({x, y, z}, {1.0, 1.0, 1.0}));
  const auto found = searched_pairs(boxes);
  EXPECT_EQ(PairSet(found.begin(), found.end()), brute_force_pairs(boxes));
  // Each cube touches the cubes at most one step away along every axis.
  size_t touching = 0;
  for (int a = 0; a < 64; ++a)
    for (int b = a + 1; b < 64; ++b)
      touching += std::abs(a / 16 - b / 16) <= 1 && std::abs(a / 4 % 4 - b / 4 % 4) <= 1 && std::abs(a % 4 - b % 4) <= 1;
  EXPECT_EQ(found.size(), touching);

  const FloatBox left = box_at({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0});
  const FloatBox right = box_at({std::nextafter(1.0f, 2.0f), 0.0, 0.0}, {1.0, 1.0, 1.0});
  EXPECT_TRUE(searched_pairs({left, right}).empty());
}

TEST(BoxOverlaps, FloatBoxesContainTheDoublePointsTheyBound) {
  const glm::dvec3 a(0.1, -1e-30, 1.0 / 3.0), b(1e20, 0.7, -2.0 / 3.0), c(-0.3, 1e-300, 5.0);
  const FloatBox box = enclosing_box(a, b, c);
  for (const glm::dvec3& p : {a, b, c})
    for (int k = 0; k < 3; ++k) {
      EXPECT_LE(double(box.lo[size_t(k)]), p[k]);
      EXPECT_GE(double(box.hi[size_t(k)]), p[k]);
    }
}

TEST(BoxOverlaps, AVisitThatReturnsFalseStopsTheSearchAndSaysItIsIncomplete) {
  std::vector<FloatBox> boxes(5000, box_at({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}));  // every pair overlaps
  std::atomic<size_t> visits{0};
  const bool complete =
      for_each_overlapping_pair(boxes, [&](const std::pair<uint32_t, uint32_t>*, size_t count) { return (visits += count) < 2000; });
  EXPECT_FALSE(complete);
  EXPECT_LT(visits.load(), size_t(5000) * 4999 / 2 / 10);
}

TEST(BoxOverlaps, BoxesBeyondAFloatsRangeAreInfiniteAndStillPaired) {
  // Points past 3.4e38 round outward to infinite float boxes (found by fuzzing).
  const FloatBox huge = enclosing_box({-1e300, 0, 0}, {1e300, 1, 1}, {0, 0, 1e300});
  EXPECT_EQ(huge.lo[0], -std::numeric_limits<float>::infinity());
  EXPECT_EQ(huge.hi[2], std::numeric_limits<float>::infinity());
  std::vector<FloatBox> boxes = {huge, box_at({0.5, 0.5, 0.5}, {0.1, 0.1, 0.1}), box_at({5, -3, 2}, {1, 1, 1}),
                                 enclosing_box({1e39, 1e39, 1e39}, {2e39, 2e39, 2e39}, {1e39, 2e39, 1e39})};
  for (int i = 0; i < 50; ++i) boxes.push_back(box_at({i, i, i}, {0.5, 0.5, 0.5}));
  const auto found = searched_pairs(boxes);
  EXPECT_EQ(PairSet(found.begin(), found.end()), brute_force_pairs(boxes));
}

TEST(BoxOverlaps, NoneOrOneBoxHasNoPairs) {
  EXPECT_TRUE(searched_pairs({}).empty());
  EXPECT_TRUE(searched_pairs({box_at({0.0, 0.0, 0.0}, {1.0, 1.0, 1.0})}).empty());
}

}  // namespace
}  // namespace umbra
