#include "mesh/check/face_classes.hpp"

#include <algorithm>
#include <limits>

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

// Marks every face whose vertex set equals an earlier face's. Equal sets
// have the same smallest vertex, so faces are bucketed by it (a counting
// sort, in file order within a bucket) and compared only within a bucket,
// which for most vertices holds two or three faces.
void find_duplicates(const PolygonSoup& soup, size_t vertex_count, FaceClasses& faces) {
  const auto smallest = [&](uint32_t f) {
    const uint32_t* v = faces.corners.data() + soup.polygon_starts[f];
    return *std::min_element(v, v + soup.corner_count(f));
  };
  std::vector<uint32_t> bucket_start(vertex_count + 1, 0);
  for (uint32_t f = 0; f < soup.polygon_count(); ++f)
    if (!faces.repeats_vertex[f]) ++bucket_start[smallest(f) + 1];
  for (size_t v = 0; v < vertex_count; ++v) bucket_start[v + 1] += bucket_start[v];
  std::vector<uint32_t> bucketed(bucket_start[vertex_count]);
  {
    std::vector<uint32_t> fill(bucket_start.begin(), bucket_start.end() - 1);
    for (uint32_t f = 0; f < soup.polygon_count(); ++f)
      if (!faces.repeats_vertex[f]) bucketed[fill[smallest(f)]++] = f;
  }
  // Each face as its sorted vertices, for the faces of one bucket.
  std::vector<std::vector<uint32_t>> sorted;
  std::vector<uint32_t> rank;
  for (size_t v = 0; v < vertex_count; ++v) {
    const uint32_t first = bucket_start[v], end = bucket_start[v + 1];
    if (end - first < 2) continue;
    sorted.resize(end - first);
    for (uint32_t i = first; i < end; ++i) {
      const uint32_t f = bucketed[i];
      const uint32_t* c = faces.corners.data() + soup.polygon_starts[f];
      sorted[i - first].assign(c, c + soup.corner_count(f));
      std::sort(sorted[i - first].begin(), sorted[i - first].end());
    }
    // By vertices, then file order: each duplicate follows the first face
    // with its vertices (a hub vertex's bucket may hold thousands).
    rank.resize(end - first);
    for (uint32_t i = 0; i < rank.size(); ++i) rank[i] = i;
    std::sort(rank.begin(), rank.end(), [&](uint32_t x, uint32_t y) { return sorted[x] != sorted[y] ? sorted[x] < sorted[y] : x < y; });
    for (size_t k = 1; k < rank.size(); ++k) {
      if (sorted[rank[k]] != sorted[rank[k - 1]]) continue;
      const uint32_t f = bucketed[first + rank[k]], previous = bucketed[first + rank[k - 1]];
      faces.duplicate[f] = 1;
      faces.duplicate_of[f] = faces.duplicate[previous] ? faces.duplicate_of[previous] : previous;
    }
  }
}

}  // namespace

FaceClasses classify_faces(const PolygonSoup& soup, std::vector<uint32_t> corners, const std::vector<glm::dvec3>& positions) {
  const size_t face_count = soup.polygon_count();
  FaceClasses faces;
  faces.corners = std::move(corners);
  faces.repeats_vertex.assign(face_count, 0);
  faces.collinear.assign(face_count, 0);
  faces.duplicate.assign(face_count, 0);
  faces.duplicate_of.assign(face_count, kNone);
  for (uint32_t f = 0; f < face_count; ++f) {
    const uint32_t* v = faces.corners.data() + soup.polygon_starts[f];
    const uint32_t n = soup.corner_count(f);
    faces.repeats_vertex[f] = has_repeated_vertex(v, n);
    faces.collinear[f] = !faces.repeats_vertex[f] && all_collinear(positions, v, n);
  }
  find_duplicates(soup, positions.size(), faces);
  return faces;
}

}  // namespace umbra
