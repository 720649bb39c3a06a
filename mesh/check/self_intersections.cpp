#include "mesh/check/self_intersections.hpp"

#include <algorithm>
#include <cmath>
#include <chrono>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#include <glm/common.hpp>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "mesh/check/box_overlaps.hpp"
#include "mesh/check/coordinate_projection.hpp"
#include "mesh/check/simple_stars.hpp"

namespace umbra {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

using Projection = CoordinateProjection;

// Two triangles sharing the edge pq, with third corners a and b, meet only
// along it when a and b lie strictly on opposite sides of pq in a projection
// where a's triangle has area: if they are coplanar, they lie so in their
// plane; if not, they meet only along pq anyway.
bool apart_across_edge(const Point& p, const Point& q, const Point& a, const Point& b) {
  const Projection projection(p, q, a);
  const CGAL::Orientation side_a = projection.orientation(p, q, a);
  return side_a != CGAL::COLLINEAR && projection.orientation(p, q, b) == -side_a;
}

// Two triangles (v, a1, b1) and (v, a2, b2) sharing the vertex v meet only
// at v when, in a projection where both have area, the angular sectors they
// span at v are disjoint: a point x != v in both would project into both
// sectors, and the projection is one-to-one on the first triangle's plane.
bool apart_at_vertex(const Point& v, Point a1, Point b1, Point a2, Point b2) {
  const Projection projection(v, a1, b1);
  const CGAL::Orientation turn1 = projection.orientation(v, a1, b1), turn2 = projection.orientation(v, a2, b2);
  if (turn1 == CGAL::COLLINEAR || turn2 == CGAL::COLLINEAR) return false;
  if (turn1 == CGAL::CLOCKWISE) std::swap(a1, b1);  // each sector counterclockwise from a to b
  if (turn2 == CGAL::CLOCKWISE) std::swap(a2, b2);
  // Each under half a turn wide: disjoint when the second starts strictly
  // past the first's end and ends strictly before its start.
  return projection.orientation(v, b1, a2) == CGAL::LEFT_TURN && projection.orientation(v, b2, a1) == CGAL::LEFT_TURN;
}

// Do two triangles intersect anywhere but in the vertices they share? The
// cases follow CGAL's own self-intersection test (PMP::self_intersections):
// with a shared edge they intersect only when coplanar and on the same side
// of it; with a shared vertex, when the edge opposite it in one triangle
// meets the other triangle.
bool triangles_intersect(const std::array<Point, 3>& a, const std::array<uint32_t, 3>& ia,
                         const std::array<Point, 3>& b, const std::array<uint32_t, 3>& ib) {
  int shared_in_a[3] = {-1, -1, -1};  // for each corner of a, the matching corner of b
  int shared = 0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      if (ia[size_t(i)] == ib[size_t(j)]) {
        shared_in_a[i] = j;
        ++shared;
      }
    }
  }
  if (shared == 0) return CGAL::do_intersect(Kernel::Triangle_3(a[0], a[1], a[2]), Kernel::Triangle_3(b[0], b[1], b[2]));
  if (shared >= 3) return false;  // the same triangle: a duplicate face, reported as such
  if (shared == 2) {
    int a_free = 0;
    while (shared_in_a[a_free] >= 0) ++a_free;
    int b_free = 0;
    while (b_free == shared_in_a[0] || b_free == shared_in_a[1] || b_free == shared_in_a[2]) ++b_free;
    const Point& p = a[size_t((a_free + 1) % 3)];
    const Point& q = a[size_t((a_free + 2) % 3)];
    if (apart_across_edge(p, q, a[size_t(a_free)], b[size_t(b_free)])) return false;  // most pairs, without a 3D predicate
    return CGAL::orientation(p, q, a[size_t(a_free)], b[size_t(b_free)]) == CGAL::COPLANAR &&
           CGAL::coplanar_orientation(p, q, a[size_t(a_free)], b[size_t(b_free)]) == CGAL::POSITIVE;
  }
  int a_vertex = 0;
  while (shared_in_a[a_vertex] < 0) ++a_vertex;
  const int b_vertex = shared_in_a[a_vertex];
  const Kernel::Segment_3 a_opposite(a[size_t((a_vertex + 1) % 3)], a[size_t((a_vertex + 2) % 3)]);
  const Kernel::Segment_3 b_opposite(b[size_t((b_vertex + 1) % 3)], b[size_t((b_vertex + 2) % 3)]);
  // When one triangle's opposite edge lies strictly on one side of the
  // other's plane, that triangle meets the plane only at the shared vertex,
  // which the other's opposite edge does not hold, so neither test below can
  // find anything.
  const auto strictly_on_one_side = [](const std::array<Point, 3>& t, const Kernel::Segment_3& edge) {
    const CGAL::Orientation side = CGAL::orientation(t[0], t[1], t[2], edge.source());
    return side != CGAL::COPLANAR && CGAL::orientation(t[0], t[1], t[2], edge.target()) == side;
  };
  // Neighbours round a vertex, curved or flat: their sectors, in 2D.
  if (apart_at_vertex(a[size_t(a_vertex)], a_opposite.source(), a_opposite.target(), b_opposite.source(), b_opposite.target()))
    return false;
  if (strictly_on_one_side(a, b_opposite) || strictly_on_one_side(b, a_opposite)) return false;
  return CGAL::do_intersect(a_opposite, Kernel::Triangle_3(b[0], b[1], b[2])) ||
         CGAL::do_intersect(b_opposite, Kernel::Triangle_3(a[0], a[1], a[2]));
}

}  // namespace

SelfIntersections find_self_intersections(const std::vector<glm::dvec3>& positions,
                                          const std::vector<std::array<uint32_t, 3>>& triangles,
                                          const std::vector<uint32_t>& triangle_face, double time_limit_seconds,
                                          size_t max_examples) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  // A limit beyond what the clock can count from now (about 292 years of
  // nanoseconds, less the time since boot) is no limit: converted, it would
  // wrap round to a deadline already past.
  const double seconds_left = std::chrono::duration<double>(Clock::time_point::max() - start).count();
  const Clock::time_point deadline =
      time_limit_seconds >= 0.5 * seconds_left
          ? Clock::time_point::max()
          : start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(time_limit_seconds));

  const auto point = [&positions](uint32_t v) { return Point(positions[v].x, positions[v].y, positions[v].z); };
  // A triangle with collinear corners has no plane: the exact tests are
  // undefined for it (the check reports its face as degenerate instead).
  std::vector<uint8_t> has_plane(triangles.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, triangles.size(), 4096), [&](const tbb::blocked_range<size_t>& range) {
    for (size_t t = range.begin(); t < range.end(); ++t)
      has_plane[t] = !CGAL::collinear(point(triangles[t][0]), point(triangles[t][1]), point(triangles[t][2]));
  });
  std::vector<uint32_t> triangle_of_box;
  triangle_of_box.reserve(triangles.size());
  for (uint32_t t = 0; t < triangles.size(); ++t)
    if (has_plane[t]) triangle_of_box.push_back(t);
  std::vector<uint8_t>().swap(has_plane);
  SelfIntersections result;
  // Pairs sharing a vertex whose star is simple meet only where they share.
  const std::vector<uint8_t> simple = find_simple_stars(positions, triangles, triangle_of_box);
  const auto box_of = [&](uint32_t i) {
    const auto& tri = triangles[triangle_of_box[i]];
    return enclosing_box(positions[tri[0]], positions[tri[1]], positions[tri[2]]);
  };
  glm::dvec3 lo = positions.empty() ? glm::dvec3(0.0) : positions[0], hi = lo;
  for (const glm::dvec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const SharedVertexSkip skip{[&](uint32_t i) { return triangles[triangle_of_box[i]]; }, &simple};

  struct WorkerState {
    std::vector<std::pair<uint32_t, uint32_t>> face_pairs;
    size_t calls = 0;
  };
  tbb::enumerable_thread_specific<WorkerState> workers;
  const auto test = [&](const std::pair<uint32_t, uint32_t>* pairs, size_t count) {
    WorkerState& state = workers.local();
    if ((state.calls += count) >= 1024) {
      state.calls = 0;
      if (Clock::now() > deadline) return false;
    }
    for (size_t k = 0; k < count; ++k) {
      const uint32_t s = triangle_of_box[pairs[k].first], t = triangle_of_box[pairs[k].second];
      const uint32_t fs = triangle_face[s], ft = triangle_face[t];
      if (fs == ft) continue;
      const auto& is = triangles[s];
      const auto& it = triangles[t];
      if (triangles_intersect({point(is[0]), point(is[1]), point(is[2])}, is, {point(it[0]), point(it[1]), point(it[2])}, it))
        state.face_pairs.emplace_back(std::min(fs, ft), std::max(fs, ft));
    }
    return true;
  };

  result.complete = for_each_overlapping_pair(triangle_of_box.size(), enclosing_box(lo, hi, hi), box_of, test, skip);
  std::vector<std::pair<uint32_t, uint32_t>> face_pairs;
  for (const WorkerState& state : workers) face_pairs.insert(face_pairs.end(), state.face_pairs.begin(), state.face_pairs.end());
  std::sort(face_pairs.begin(), face_pairs.end());
  face_pairs.erase(std::unique(face_pairs.begin(), face_pairs.end()), face_pairs.end());
  result.face_pairs = face_pairs.size();
  result.examples.assign(face_pairs.begin(), face_pairs.begin() + std::ptrdiff_t(std::min(max_examples, face_pairs.size())));
  result.pairs = std::move(face_pairs);
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return result;
}

}  // namespace umbra
