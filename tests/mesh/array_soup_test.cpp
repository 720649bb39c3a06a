// A mesh handed over as arrays (mesh/io/array_soup.hpp), every defect listed
// on request, and the repair handed back in memory: what the Python module
// calls, checked here too so that the sanitizers see it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "mesh/check/mesh_check.hpp"
#include "mesh/check/mesh_repair.hpp"
#include "mesh/input_error.hpp"
#include "mesh/io/array_soup.hpp"
#include "tests/mesh/mesh_builders.hpp"

namespace umbra {
namespace {

using namespace umbra::test;

template <typename T>
ArrayView view(const std::vector<T>& values, size_t rows, size_t columns, char kind) {
  return {values.data(), kind, sizeof(T), rows, columns, ptrdiff_t(columns * sizeof(T)), ptrdiff_t(sizeof(T))};
}

std::string error_of(const ArrayView& vertices, const ArrayView& faces) {
  try {
    soup_from_arrays(vertices, faces, "arrays");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

const std::vector<double> kTrianglePoints = {0, 0, 0, 1, 0, 0, 0, 1, 0};

TEST(ArraySoup, ReadsPointsAndFacesThroughStridesAndTypes) {
  // The points column by column (Fortran order), float32; the faces as uint16.
  const std::vector<float> columns = {0, 1, 0, 0, 0, 1, 0, 0, 0};
  const ArrayView points{columns.data(), 'f', 4, 3, 3, 4, 12};
  const std::vector<uint16_t> faces = {0, 1, 2};
  const PolygonSoup soup = soup_from_arrays(points, view(faces, 1, 3, 'u'), "arrays");
  ASSERT_EQ(soup.points.size(), 3u);
  EXPECT_EQ(soup.points[1], glm::dvec3(1, 0, 0));
  EXPECT_EQ(soup.points[2], glm::dvec3(0, 1, 0));
  EXPECT_EQ(soup.polygon_count(), 1u);
  EXPECT_EQ(std::vector<uint32_t>(soup.polygon(0), soup.polygon(0) + 3), (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_EQ(soup.format, "arrays (float32 vertices, uint16 faces)");
}

TEST(ArraySoup, QuadsArePolygonsOfFourCorners) {
  const std::vector<double> points = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  const std::vector<int64_t> quad = {0, 1, 2, 3};
  const PolygonSoup soup = soup_from_arrays(view(points, 4, 3, 'f'), view(quad, 1, 4, 'i'), "arrays");
  EXPECT_EQ(soup.polygon_count(), 1u);
  EXPECT_EQ(soup.corner_count(0), 4u);
}

TEST(ArraySoup, BadArraysAreRefusedWithTheirPlace) {
  const std::vector<int64_t> face = {0, 1, 2};
  const ArrayView faces = view(face, 1, 3, 'i');
  std::vector<double> nan_point = kTrianglePoints;
  nan_point[7] = std::nan("");
  EXPECT_EQ(error_of(view(nan_point, 3, 3, 'f'), faces),
            "arrays: vertices[2, 1] is NaN: every coordinate must be a finite number");
  std::vector<double> far = kTrianglePoints;
  far[3] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(error_of(view(far, 3, 3, 'f'), faces), "arrays: vertices[1, 0] is infinite: every coordinate must be a finite number");
  EXPECT_EQ(error_of(view(kTrianglePoints, 3, 3, 'f'), view(std::vector<int64_t>{0, 1, 3}, 1, 3, 'i')),
            "arrays: faces[0, 2] is 3, but vertices has 3 rows: a face's corners index the vertices, from 0");
  const std::vector<int32_t> negative = {0, -1, 2};
  EXPECT_EQ(error_of(view(kTrianglePoints, 3, 3, 'f'), view(negative, 1, 3, 'i')),
            "arrays: faces[0, 1] is -1, but vertices has 3 rows: a face's corners index the vertices, from 0");
  const std::vector<uint64_t> huge = {0, 1, std::numeric_limits<uint64_t>::max()};
  EXPECT_EQ(error_of(view(kTrianglePoints, 3, 3, 'f'), view(huge, 1, 3, 'u')),
            "arrays: faces[0, 2] is 18446744073709551615, but vertices has 3 rows: a face's corners index the vertices, from 0");
  EXPECT_EQ(error_of(view(kTrianglePoints, 3, 3, 'f'), view(kTrianglePoints, 1, 3, 'f')),
            "arrays: faces must hold integers (vertex indices), got float64");
  EXPECT_EQ(error_of(view(kTrianglePoints, 1, 9, 'f'), faces), "arrays: vertices must be an (n, 3) array of points, got shape (1, 9)");
  EXPECT_EQ(error_of(view(kTrianglePoints, 3, 3, 'f'), view(face, 1, 2, 'i')),
            "arrays: faces must be an (m, 3) array of vertex indices (or (m, k), k >= 3), got shape (1, 2)");
  EXPECT_EQ(error_of(view(kTrianglePoints, 3, 3, 'c'), faces), "arrays: vertices must hold numbers, got 'c' elements");
}

TEST(ArraySoup, NoFacesIsAnEmptySoupNotAnError) {
  const std::vector<int64_t> none;
  const PolygonSoup soup = soup_from_arrays(view(kTrianglePoints, 3, 3, 'f'), view(none, 0, 3, 'i'), "arrays");
  EXPECT_EQ(soup.polygon_count(), 0u);
}

TEST(CheckExamples, EveryDefectIsListedWhenAskedAndFiveOtherwise) {
  // Eight loose triangles: 24 border edges.
  std::vector<glm::dvec3> points;
  std::vector<Face> faces;
  for (uint32_t t = 0; t < 8; ++t) {
    points.insert(points.end(), {{t, 0, 0}, {t + 0.5, 0, 0}, {t, 1, 0}});
    faces.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  const PolygonSoup soup = make_soup(points, faces);
  EXPECT_EQ(check_mesh(soup).examples.border_edges.size(), MeshReport::kMaxExamples);
  CheckOptions every;
  every.max_examples = SIZE_MAX;
  const MeshReport report = check_mesh(soup, every);
  ASSERT_EQ(report.examples.border_edges.size(), 24u);
  std::set<std::pair<uint32_t, uint32_t>> edges;
  for (const auto& [a, b] : report.examples.border_edges) edges.insert(std::minmax(a.index, b.index));
  for (uint32_t t = 0; t < 8; ++t)
    for (const auto& [a, b] : {std::pair{0u, 1u}, {1u, 2u}, {0u, 2u}}) EXPECT_TRUE(edges.count({3 * t + a, 3 * t + b}));
}

TEST(RepairToTriangles, AnOpenCubeComesBackClosedWithItsEightCorners) {
  PolygonSoup open = unit_cube();
  open.corners.resize(30);  // the last two triangles (the right side) dropped
  open.polygon_starts.resize(11);
  const RepairedTriangles repaired = repair_to_triangles(open);
  EXPECT_EQ(repaired.points.size(), 8u);
  ASSERT_EQ(repaired.triangles.size(), 12u);
  std::vector<Face> faces;
  for (const auto& t : repaired.triangles) faces.push_back({t[0], t[1], t[2]});
  const MeshReport report = check_mesh(make_soup(repaired.points, faces));
  EXPECT_TRUE(report.is_closed_manifold()) << report.verdict();
  ASSERT_TRUE(report.enclosed_volume);
  EXPECT_NEAR(*report.enclosed_volume, 1.0, 1e-12);
}

}  // namespace
}  // namespace umbra
