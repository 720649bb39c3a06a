#include "mesh/check/face_classes.hpp"

#include <algorithm>
#include <array>
#include <limits>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "mesh/check/bucket_fill.hpp"
#include "mesh/unset_vector.hpp"
#include "mesh/predicates/orientation.hpp"

namespace umbra {
namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

bool has_repeated_vertex(const uint32_t* v, uint32_t n) {
  for (uint32_t i = 0; i < n; ++i)
    for (uint32_t j = i + 1; j < n; ++j)
      if (v[i] == v[j]) return true;
  return false;
}

bool all_collinear(const std::vector<glm::dvec3>& positions, const uint32_t* v, uint32_t n) {
  for (uint32_t k = 2; k < n; ++k)
    if (!collinear(positions[v[0]], positions[v[1]], positions[v[k]])) return false;
  return true;
}

// Marks each of the bucket's `count` faces (in file order) whose vertex set
// equals an earlier one's, when they are at most 8 triangles, comparing
// their sorted corners pairwise; false, marking nothing, for any other bucket.
bool duplicate_triangles(const PolygonSoup& soup, const uint32_t* bucket, uint32_t count, FaceClasses& faces) {
  if (count > 8) return false;
  std::array<std::array<uint32_t, 3>, 8> key;
  for (uint32_t i = 0; i < count; ++i) {
    if (soup.corner_count(bucket[i]) != 3) return false;
    const uint32_t* c = faces.corners.data() + soup.polygon_starts[bucket[i]];
    key[i] = {c[0], c[1], c[2]};
    std::sort(key[i].begin(), key[i].end());
  }
  for (uint32_t i = 1; i < count; ++i)
    for (uint32_t j = 0; j < i; ++j)
      if (key[j] == key[i]) {  // the first such face is no duplicate itself
        faces.duplicate[bucket[i]] = 1;
        faces.duplicate_of[bucket[i]] = bucket[j];
        break;
      }
  return true;
}

// The same for any bucket: faces as sorted vertex lists, sorted by them and
// then by file order, so that each duplicate follows the first face with its
// vertices (a hub vertex's bucket may hold thousands).
void duplicate_polygons(const PolygonSoup& soup, const uint32_t* bucket, uint32_t count, FaceClasses& faces,
                        std::vector<std::vector<uint32_t>>& sorted, std::vector<uint32_t>& rank) {
  sorted.resize(count);
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t* c = faces.corners.data() + soup.polygon_starts[bucket[i]];
    sorted[i].assign(c, c + soup.corner_count(bucket[i]));
    std::sort(sorted[i].begin(), sorted[i].end());
  }
  rank.resize(count);
  for (uint32_t i = 0; i < count; ++i) rank[i] = i;
  std::sort(rank.begin(), rank.end(), [&](uint32_t x, uint32_t y) { return sorted[x] != sorted[y] ? sorted[x] < sorted[y] : x < y; });
  for (size_t k = 1; k < count; ++k) {
    if (sorted[rank[k]] != sorted[rank[k - 1]]) continue;
    const uint32_t f = bucket[rank[k]], previous = bucket[rank[k - 1]];
    faces.duplicate[f] = 1;
    faces.duplicate_of[f] = faces.duplicate[previous] ? faces.duplicate_of[previous] : previous;
  }
}

// Marks every face whose vertex set equals an earlier face's. Equal sets
// have the same smallest vertex, so faces are bucketed by it (a counting
// sort, in file order within a bucket) and compared only within a bucket,
// which for most vertices holds two or three faces.
void find_duplicates(const PolygonSoup& soup, size_t vertex_count, FaceClasses& faces) {
  const auto smallest = [&](uint32_t f) {
    const uint32_t* v = faces.corners.data() + soup.polygon_starts[f];
    return *std::min_element(v, v + soup.corner_count(f));
  };
  std::vector<uint32_t> bucket_start;
  UnsetVector<uint32_t> bucketed;
  fill_buckets<uint32_t>(soup.polygon_count(), vertex_count, [&](uint32_t first, uint32_t end, const auto& put) {
    for (uint32_t f = first; f < end; ++f)
      if (!faces.repeats_vertex[f]) put(smallest(f), f);
  }, bucket_start, bucketed);
  // Buckets are independent: on every core, each chunk with its own scratch.
  tbb::parallel_for(tbb::blocked_range<size_t>(0, vertex_count, 4096), [&](const tbb::blocked_range<size_t>& range) {
    std::vector<std::vector<uint32_t>> sorted;  // each face as its sorted vertices, for the faces of one bucket
    std::vector<uint32_t> rank;
    for (size_t v = range.begin(); v < range.end(); ++v) {
      const uint32_t first = bucket_start[v], end = bucket_start[v + 1];
      if (end - first < 2) continue;
      if (!duplicate_triangles(soup, bucketed.data() + first, end - first, faces))
        duplicate_polygons(soup, bucketed.data() + first, end - first, faces, sorted, rank);
    }
  });
}

}  // namespace

FaceClasses classify_file_faces(const PolygonSoup& soup, std::vector<uint32_t> corners, const std::vector<glm::dvec3>& positions) {
  const size_t face_count = soup.polygon_count();
  FaceClasses faces;
  faces.corners = std::move(corners);
  faces.repeats_vertex.assign(face_count, 0);
  faces.collinear.assign(face_count, 0);
  faces.duplicate.assign(face_count, 0);
  faces.duplicate_of.assign(face_count, kNone);
  // Exact predicates for every face: on every core.
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, uint32_t(face_count), 4096), [&](const tbb::blocked_range<uint32_t>& r) {
    for (uint32_t f = r.begin(); f < r.end(); ++f) {
      const uint32_t* v = faces.corners.data() + soup.polygon_starts[f];
      const uint32_t n = soup.corner_count(f);
      faces.repeats_vertex[f] = has_repeated_vertex(v, n);
      faces.collinear[f] = !faces.repeats_vertex[f] && all_collinear(positions, v, n);
    }
  });
  find_duplicates(soup, positions.size(), faces);
  return faces;
}

}  // namespace umbra
