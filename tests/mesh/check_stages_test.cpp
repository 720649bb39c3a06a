// The mesh check's stages, each called on its own with values made by hand:
// what a face is, how edges group, components, fans and loops, and flips.
#include <gtest/gtest.h>

#include <map>
#include <numeric>
#include <random>

#include <tbb/task_arena.h>

#include "mesh/check/bucket_fill.hpp"
#include "mesh/check/components.hpp"
#include "mesh/check/edge_groups.hpp"
#include "mesh/check/face_classes.hpp"
#include "mesh/check/face_flips.hpp"
#include "mesh/check/point_merging.hpp"
#include "mesh/check/solid_orientation.hpp"
#include "tests/mesh/mesh_builders.hpp"

namespace umbra {
namespace {

using namespace umbra::test;

FaceClasses classes_of(const PolygonSoup& soup) { return classify_file_faces(soup, soup.corners, soup.points); }

TEST(CheckStages, ClassifyFacesFindsRepeatsCollinearCornersAndCopiesInAnyRotation) {
  // 0: a triangle; 1: it rotated and reversed; 2: a repeated corner; 3: three points on a line.
  const PolygonSoup soup = make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}}, {{0, 1, 2}, {2, 1, 0}, {0, 1, 1}, {0, 1, 3}});
  const FaceClasses faces = classes_of(soup);
  EXPECT_EQ(faces.duplicate, (std::vector<uint8_t>{0, 1, 0, 0}));
  EXPECT_EQ(faces.duplicate_of[1], 0u);
  EXPECT_EQ(faces.repeats_vertex, (std::vector<uint8_t>{0, 0, 1, 0}));
  EXPECT_EQ(faces.collinear, (std::vector<uint8_t>{0, 0, 0, 1}));
  EXPECT_TRUE(faces.in_topology(0));
  EXPECT_FALSE(faces.in_topology(1));
  EXPECT_FALSE(faces.in_topology(2));
  EXPECT_TRUE(faces.in_topology(3));  // collinear faces stay: a closed mesh needs them
}

TEST(CheckStages, GroupEdgesCountsEachEdgesFacesAndWhichRunTheSameWay) {
  // Three triangles on the edge 0-1 (non-manifold), and a fourth wound against its neighbour across 1-2.
  const PolygonSoup soup =
      make_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {1, 1, 1}},
                {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {1, 2, 5}});
  const FaceClasses faces = classes_of(soup);
  EdgeGroups groups = group_edges(soup, faces, soup.points.size());
  ASSERT_FALSE(groups.edges.empty());
  EXPECT_EQ(groups.edges[0].a, 0u);
  EXPECT_EQ(groups.edges[0].b, 1u);
  EXPECT_EQ(groups.edges[0].uses, 3u);
  EXPECT_EQ(groups.on_non_manifold_edge[0] + groups.on_non_manifold_edge[1], 2);
  // Faces 0 and 3 both run 1 -> 2: one inconsistent edge, named by the earlier face.
  EXPECT_EQ(groups.inconsistent_edge_faces, std::vector<uint32_t>{0});
  size_t border = 0;
  for (const EdgeRun& e : groups.edges) border += e.uses == 1;
  // 0-1 (three faces), 1-2 (two), and seven border edges: 0-2, 0-3, 1-3, 0-4, 1-4, 1-5, 2-5.
  EXPECT_EQ(groups.edges.size(), 9u);
  EXPECT_EQ(border, 7u);
}

TEST(CheckStages, ComponentsFansAndLoopsOfTwoBowlsTouchingAtAVertex) {
  // Two open pyramids (4 side faces each, no base) whose apexes are the same vertex.
  const PolygonSoup soup = make_soup(
      {{0, 0, 0}, {1, 1, 1}, {-1, 1, 1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, -1}, {1, -1, -1}},
      {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}, {0, 6, 5}, {0, 7, 6}, {0, 8, 7}, {0, 5, 8}});
  const FaceClasses faces = classes_of(soup);
  EdgeGroups groups = group_edges(soup, faces, soup.points.size());
  const ComponentLabels labels = label_components(faces, groups);
  ASSERT_EQ(labels.reports.size(), 2u);  // faces that touch only at a vertex are separate components
  EXPECT_EQ(labels.of_face, (std::vector<uint32_t>{0, 0, 0, 0, 1, 1, 1, 1}));
  EXPECT_EQ(labels.reports[0].faces, 4u);
  EXPECT_EQ(labels.reports[0].border_edges, 4u);
  const ComponentVertices fans = find_vertex_fans(soup, faces, groups, labels, soup.points.size());
  EXPECT_EQ(fans.non_manifold_vertices, std::vector<uint32_t>{0});  // the shared apex: two fans
  EXPECT_EQ(fans.vertices, (std::vector<size_t>{5, 5}));            // the apex counts in both
  EXPECT_EQ(fans.pinched_vertices, (std::vector<size_t>{0, 0}));     // but each component holds one fan of it
  EXPECT_EQ(fans.topology_vertices, 9u);
  const BorderLoops loops = count_border_loops(groups, labels, soup.points.size());
  EXPECT_EQ(loops.loops, 2u);
  EXPECT_EQ(loops.per_component, (std::vector<size_t>{1, 1}));
}

// Border loops are counted per component, as the cycles of its border
// edges (edges - vertices + pieces of its border graph): loops that touch at
// a vertex stay two, and one component's loop never takes another's.
TEST(CheckStages, BorderLoopsThatTouchAtAVertexAreCountedPerComponent) {
  // Two triangles sharing one vertex: two components, a loop each.
  const PolygonSoup bow_tie = make_soup({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}}, {{0, 1, 2}, {0, 3, 4}});
  {
    const FaceClasses faces = classes_of(bow_tie);
    EdgeGroups groups = group_edges(bow_tie, faces, bow_tie.points.size());
    const ComponentLabels labels = label_components(faces, groups);
    const BorderLoops loops = count_border_loops(groups, labels, bow_tie.points.size());
    EXPECT_EQ(loops.loops, 2u);
    EXPECT_EQ(loops.per_component, (std::vector<size_t>{1, 1}));
  }
  // A 4 x 4 grid of quads without quads (1, 1) and (2, 2), whose holes touch
  // at grid vertex (2, 2): one component, its outer loop and two holes.
  std::vector<glm::dvec3> points;
  for (int y = 0; y <= 4; ++y)
    for (int x = 0; x <= 4; ++x) points.emplace_back(x, y, 0);
  std::vector<Face> quads;
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 4; ++x)
      if (!(x == y && (x == 1 || x == 2))) quads.push_back({5 * y + x, 5 * y + x + 1, 5 * (y + 1) + x + 1, 5 * (y + 1) + x});
  const PolygonSoup grid = make_soup(points, quads);
  const FaceClasses faces = classes_of(grid);
  EdgeGroups groups = group_edges(grid, faces, grid.points.size());
  const ComponentLabels labels = label_components(faces, groups);
  ASSERT_EQ(labels.reports.size(), 1u);
  const BorderLoops loops = count_border_loops(groups, labels, grid.points.size());
  EXPECT_EQ(loops.loops, 3u);
  EXPECT_EQ(loops.per_component, (std::vector<size_t>{3}));
}

TEST(CheckStages, FacesToFlipAreTheSmallerParityClassAndTurnTheirTriangles) {
  const PolygonSoup soup = reversed(unit_cube(), {3, 8});
  const FaceClasses faces = classes_of(soup);
  EdgeGroups groups = group_edges(soup, faces, soup.points.size());
  const ComponentLabels labels = label_components(faces, groups);
  const std::vector<uint8_t> flip = faces_to_flip(faces, groups.flips, labels.of_face, labels.conflict);
  std::vector<uint8_t> expected(12, 0);
  expected[3] = expected[8] = 1;
  EXPECT_EQ(flip, expected);
  FaceTriangles triangles = triangulate_faces(soup, faces, soup.points);
  ASSERT_EQ(triangles.triangles.size(), 12u);
  const auto before = triangles.triangles[3];
  turn_flipped(triangles, flip);
  EXPECT_EQ(triangles.triangles[3], (std::array<uint32_t, 3>{before[0], before[2], before[1]}));
  EXPECT_EQ(triangles.triangles[0], triangulate_faces(soup, faces, soup.points).triangles[0]);
}

TEST(CheckStages, BucketsFillAsOneCoreWouldHoweverManyShareTheWork) {
  // Item i puts i into buckets hash(i) % 97 and (i / 3) % 97, the second only
  // for odd i.
  const size_t items = 20000, buckets = 97;
  const auto for_each_item = [](uint32_t first, uint32_t end, const auto& put) {
    for (uint32_t i = first; i < end; ++i) {
      put((i * 2654435761u) % buckets, i);
      if (i % 2) put((i / 3) % buckets, i);
    }
  };
  std::vector<std::vector<uint32_t>> expected(buckets);
  for (uint32_t i = 0; i < items; ++i) {
    expected[(i * 2654435761u) % buckets].push_back(i);
    if (i % 2) expected[(i / 3) % buckets].push_back(i);
  }
  for (const int threads : {1, 2, 3, 7}) {
    std::vector<uint32_t> start, values;
    tbb::task_arena(threads).execute([&] { fill_buckets<uint32_t>(items, buckets, for_each_item, start, values); });
    ASSERT_EQ(start.size(), buckets + 1);
    for (size_t b = 0; b < buckets; ++b)
      EXPECT_EQ(std::vector<uint32_t>(values.begin() + start[b], values.begin() + start[b + 1]), expected[b])
          << "bucket " << b << " with " << threads << " threads";
  }
}

TEST(CheckStages, MergedPointsAreNumberedByFirstAppearanceHoweverManyShareTheWork) {
  // 300,000 points (many parts) drawn from 40,000 positions, with -0 and +0
  // as one coordinate; checked against a map from position to first point.
  std::mt19937 random(7);
  std::vector<glm::dvec3> positions(40000);
  for (glm::dvec3& p : positions) p = glm::dvec3(double(random() % 50), double(random() % 50), double(random() % 50) / 7.0);
  positions[1] = {0.0, 1.0, 2.0};
  std::vector<glm::dvec3> points(300000);
  for (glm::dvec3& p : points) p = positions[random() % positions.size()];
  points[5] = {-0.0, 1.0, 2.0};
  points[9] = {0.0, 1.0, 2.0};
  const auto less = [](const glm::dvec3& a, const glm::dvec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  };
  std::map<glm::dvec3, uint32_t, decltype(less)> vertex_of(less);
  MergedPoints expected;
  for (uint32_t i = 0; i < points.size(); ++i) {
    const auto [it, added] = vertex_of.emplace(points[i], uint32_t(expected.positions.size()));
    if (added) {
      expected.positions.push_back(points[i]);
      expected.first_point.push_back(i);
    }
    expected.vertex_of_point.push_back(it->second);
  }
  EXPECT_EQ(expected.vertex_of_point[5], expected.vertex_of_point[9]);
  for (const int threads : {1, 2, 5}) {
    MergedPoints merged;
    tbb::task_arena(threads).execute([&] { merged = merge_coincident_points(points); });
    EXPECT_EQ(merged.positions, expected.positions) << threads << " threads";
    EXPECT_EQ(merged.first_point, expected.first_point) << threads << " threads";
    EXPECT_EQ(merged.vertex_of_point, expected.vertex_of_point) << threads << " threads";
  }
  EXPECT_TRUE(merge_coincident_points({}).positions.empty());
}

// --merge-tolerance: a point joins a kept one within the tolerance, across
// the cells' walls and on either side of 0; kept points never move, so
// merges do not chain along a line of points closer than the tolerance.
TEST(CheckStages, NearbyPointsMergeWithinTheToleranceWithoutChaining) {
  const std::vector<glm::dvec3> points{{0, 0, 0},       {0.8, 0, 0},  {1.6, 0, 0},   {2.4, 0, 0},
                                       {0.99, 5, 0},    {1.01, 5, 0}, {-0.01, 7, 0}, {0.01, 7, 0},
                                       {0, 9, 1.00001}};
  const MergedPoints merged = merge_nearby_points(points, 1.0);
  // 0.8 joins 0; 1.6 is 1.6 from 0, kept; 2.4 joins 1.6.
  EXPECT_EQ(merged.vertex_of_point, (std::vector<uint32_t>{0, 0, 1, 1, 2, 2, 3, 3, 4}));
  EXPECT_EQ(merged.first_point, (std::vector<uint32_t>{0, 2, 4, 6, 8}));
  EXPECT_EQ(merged.positions[1], glm::dvec3(1.6, 0, 0));
  // At a tolerance below every gap, each point is its own.
  EXPECT_EQ(merge_nearby_points(points, 1e-3).positions.size(), points.size());
  // Equal points merge at any tolerance.
  EXPECT_EQ(merge_nearby_points({{1e9, -3, 2}, {1e9, -3, 2}}, 1e-12).positions.size(), 1u);
}

TEST(CheckStages, ShellsReadTurnedRoundFaceAsIfTurned) {
  // The hollow cube's two shells (12 triangles each) face the right way;
  // read with every triangle of a shell turned round, that shell faces the
  // wrong way, whether the triangles are turned or only read so.
  const PolygonSoup hollow = hollow_cube();
  std::vector<std::array<uint32_t, 3>> triangles;
  for (size_t f = 0; f < hollow.polygon_count(); ++f) triangles.push_back({hollow.polygon(f)[0], hollow.polygon(f)[1], hollow.polygon(f)[2]});
  std::vector<uint32_t> component_of(24, 0);
  std::fill(component_of.begin() + 12, component_of.end(), 1);
  const std::vector<uint8_t> closed{1, 1}, untangled{0, 0};
  const auto facing = [&](const std::vector<std::array<uint32_t, 3>>& t, const std::vector<uint8_t>* reversed = nullptr) {
    return facing_of_closed_components(hollow.points, t, component_of, 2, closed, untangled, reversed).facing;
  };
  EXPECT_EQ(facing(triangles), (std::vector<Facing>{Facing::kRight, Facing::kRight}));
  for (const size_t shell : {0, 1}) {
    std::vector<uint8_t> reversed(24, 0);
    std::fill(reversed.begin() + std::ptrdiff_t(12 * shell), reversed.begin() + std::ptrdiff_t(12 * shell + 12), 1);
    std::vector<std::array<uint32_t, 3>> turned = triangles;
    for (size_t t = 0; t < 24; ++t)
      if (reversed[t]) std::swap(turned[t][1], turned[t][2]);
    std::vector<Facing> expected{Facing::kRight, Facing::kRight};
    expected[shell] = Facing::kWrong;
    EXPECT_EQ(facing(turned), expected) << "shell " << shell;
    EXPECT_EQ(facing(triangles, &reversed), expected) << "shell " << shell;
  }
}

TEST(CheckStages, ThousandsOfShellsAreNestedByTheirBoxes) {
  // A box [0, 100]^3 facing out; 1500 small tetrahedra inside it, which
  // bound its cavities and so should face in, one of them facing out; 1500
  // more outside it, facing out, one of them facing in.
  PolygonSoup soup = box_triangles(glm::dvec3(0.0), glm::dvec3(100.0));
  std::vector<Facing> expected{Facing::kRight};
  for (int k = 0; k < 3000; ++k) {
    const bool inside = k < 1500;
    const glm::dvec3 at(1.0 + (k % 1500) % 40 * 2.4, 1.0 + (k % 1500) / 40 * 2.4, inside ? 50.0 : 150.0);
    const bool odd_one = k == 700 || k == 2300;
    const bool facing_in = inside != odd_one;
    soup = combine(soup, facing_in ? all_reversed(tetrahedron(at)) : tetrahedron(at));
    expected.push_back(odd_one ? Facing::kWrong : Facing::kRight);
  }
  std::vector<std::array<uint32_t, 3>> triangles;
  std::vector<uint32_t> component_of;
  for (size_t f = 0; f < soup.polygon_count(); ++f) {
    triangles.push_back({soup.polygon(f)[0], soup.polygon(f)[1], soup.polygon(f)[2]});
    component_of.push_back(f < 12 ? 0 : uint32_t(1 + (f - 12) / 4));
  }
  const std::vector<uint8_t> closed(3001, 1), untangled(3001, 0);
  EXPECT_EQ(facing_of_closed_components(soup.points, triangles, component_of, 3001, closed, untangled).facing, expected);
  // A tangled outer box leaves every shell it holds undecided, not the ones outside it.
  std::vector<uint8_t> box_tangled(3001, 0);
  box_tangled[0] = 1;
  const std::vector<Facing> facing =
      facing_of_closed_components(soup.points, triangles, component_of, 3001, closed, box_tangled).facing;
  for (size_t c = 0; c < 3001; ++c) EXPECT_EQ(facing[c] == Facing::kUndecided, c <= 1500) << c;
}

}  // namespace
}  // namespace umbra
