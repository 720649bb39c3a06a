#include "mesh/check/simple_stars.hpp"

#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "mesh/check/bucket_fill.hpp"
#include "mesh/unset_vector.hpp"
#include "mesh/check/coordinate_projection.hpp"

namespace umbra {
namespace {

using Point = CoordinateProjection::Point;

constexpr size_t kMaxStar = 32;  // larger stars are rare; they keep their pair tests
constexpr size_t kAhead = 4;     // vertices

Point point_of(const glm::dvec3& p) { return Point(p.x, p.y, p.z); }

// The triangles round a vertex, as the pairs of their other corners (a[i],
// b[i]), walked as one closed fan: ring[0..count) are the other corners in
// order round it, triangle k of the walk joining ring[k] and ring[k + 1]
// (ring[count] being ring[0]). False unless every corner is in exactly two of
// the triangles and the walk passes through all of them before it closes.
bool walk_closed_fan(const std::array<uint32_t, kMaxStar>& a, const std::array<uint32_t, kMaxStar>& b, size_t count,
                     std::array<uint32_t, kMaxStar + 1>& ring) {
  ring[0] = a[0], ring[1] = b[0];
  size_t current = 0;
  for (size_t k = 1; k <= count; ++k) {
    const uint32_t corner = ring[k];
    size_t next = 0, others = 0;
    for (size_t j = 0; j < count; ++j) {
      if (j != current && (a[j] == corner || b[j] == corner)) ++others, next = j;
    }
    if (others != 1) return false;  // a border edge, or an edge of three or more triangles
    if (next == 0) return k == count;  // closed: through all of them, or too soon
    if (k == count) return false;
    ring[k + 1] = a[next] == corner ? b[next] : a[next];
    current = next;
  }
  return false;
}

// Does the fan's projection turn once round v, each triangle turning the
// same way? Each projected triangle turns by less than half a turn, so the
// directions from v to the ring enter the upper half-plane (angles in
// (0, pi], decided exactly by comparing coordinates) once per turn.
bool projects_once_round(const glm::dvec3& v, const std::vector<glm::dvec3>& positions,
                         const std::array<uint32_t, kMaxStar + 1>& ring, size_t count) {
  glm::dvec3 normal(0.0);  // the axis to drop need not be exact: the tests below are
  for (size_t k = 0; k < count; ++k)
    normal += glm::cross(positions[ring[k]] - v, positions[ring[(k + 1) % count]] - v);
  const CoordinateProjection projection(CoordinateProjection::Kernel::Vector_3(normal.x, normal.y, normal.z));
  const auto upper = [&](const glm::dvec3& p) {
    return p[projection.v] > v[projection.v] || (p[projection.v] == v[projection.v] && p[projection.u] < v[projection.u]);
  };
  const Point centre = point_of(v);
  CGAL::Orientation turn = CGAL::COLLINEAR;
  size_t entries = 0;
  for (size_t k = 0; k < count; ++k) {
    const glm::dvec3& from = positions[ring[k]];
    const glm::dvec3& to = positions[ring[(k + 1) % count]];
    const CGAL::Orientation this_turn = projection.orientation(centre, point_of(from), point_of(to));
    if (this_turn == CGAL::COLLINEAR || (k > 0 && this_turn != turn)) return false;
    turn = this_turn;
    if (!upper(from) && upper(to)) ++entries;
  }
  // Clockwise, this counts exits, which round a closed ring are as many.
  return entries == 1;
}

}  // namespace

std::vector<uint8_t> find_simple_stars(const std::vector<glm::dvec3>& positions,
                                       const std::vector<std::array<uint32_t, 3>>& triangles,
                                       const std::vector<uint32_t>& tested) {
  // The triangles round each vertex, as offsets into one array.
  const size_t vertex_count = positions.size();
  std::vector<uint32_t> star_begin;
  UnsetVector<uint32_t> star;
  fill_buckets<uint32_t>(tested.size(), vertex_count, [&](uint32_t first, uint32_t end, const auto& put) {
    for (uint32_t k = first; k < end; ++k)
      for (const uint32_t c : triangles[tested[k]]) put(c, tested[k]);
  }, star_begin, star);

  std::vector<uint8_t> simple(vertex_count, 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, vertex_count, 4096), [&](const tbb::blocked_range<size_t>& range) {
    std::array<uint32_t, kMaxStar> a, b;
    std::array<uint32_t, kMaxStar + 1> ring;
    for (size_t v = range.begin(); v < range.end(); ++v) {
      // A star's triangles, and then their corners, lie all over the arrays:
      // fetched a few vertices ahead, the corners once the triangles are in.
      if (v + 2 * kAhead < range.end())
        for (uint32_t i = star_begin[v + 2 * kAhead]; i < star_begin[v + 2 * kAhead + 1]; ++i) __builtin_prefetch(&triangles[star[i]]);
      if (v + kAhead < range.end())
        for (uint32_t i = star_begin[v + kAhead]; i < star_begin[v + kAhead + 1]; ++i)
          for (const uint32_t c : triangles[star[i]]) __builtin_prefetch(&positions[c]);
      const size_t count = star_begin[v + 1] - star_begin[v];
      if (count < 3 || count > kMaxStar) continue;
      for (size_t i = 0; i < count; ++i) {
        const std::array<uint32_t, 3>& tri = triangles[star[star_begin[v] + i]];
        const int k = tri[0] == v ? 0 : tri[1] == v ? 1 : 2;
        a[i] = tri[size_t((k + 1) % 3)];
        b[i] = tri[size_t((k + 2) % 3)];
      }
      simple[v] = walk_closed_fan(a, b, count, ring) && projects_once_round(positions[v], positions, ring, count);
    }
  });
  return simple;
}

}  // namespace umbra
