#include "mesh/check/point_merging.hpp"

#include "mesh/check/bucket_fill.hpp"
#include "mesh/unset_vector.hpp"

#include <algorithm>
#include <cstring>
#include <unordered_map>

#include <glm/geometric.hpp>
#include <glm/common.hpp>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

namespace umbra {
namespace {

uint64_t bits_of(double x) {
  x += 0.0;  // -0.0 equals 0.0, so it must hash the same: -0.0 + 0.0 is 0.0
  uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return bits;
}

uint64_t hash_of(const glm::dvec3& p) {
  uint64_t h = bits_of(p.x) * 0x9E3779B97F4A7C15ull;
  h = (h ^ (h >> 29) ^ bits_of(p.y)) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 32) ^ bits_of(p.z)) * 0x94D049BB133111EBull;
  return h ^ (h >> 31);
}

}  // namespace

MergedPoints merge_coincident_points(const std::vector<glm::dvec3>& points) {
  // Equal points hash alike, so the points are first split by their hash's
  // top bits into parts of a few thousand, each listing its points in file
  // order. Each part is then merged on its own, on every core, with an
  // open-addressing table at most half full that stays in cache: a point's
  // first point is the first one of its part with its position.
  const size_t n = points.size();
  int part_bits = 0;
  while ((size_t(1) << part_bits) * 4096 < n && part_bits < 16) ++part_bits;
  const size_t parts = size_t(1) << part_bits;
  std::vector<uint16_t> part_of(n);  // hashed once here, for both passes of the split
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) part_of[i] = part_bits == 0 ? 0 : uint16_t(hash_of(points[i]) >> (64 - part_bits));
  });
  std::vector<uint32_t> part_start;
  UnsetVector<uint32_t> in_parts;
  fill_buckets<uint32_t>(n, parts, [&](uint32_t first, uint32_t end, const auto& put) {
    for (uint32_t i = first; i < end; ++i) put(part_of[i], i);
  }, part_start, in_parts);
  std::vector<uint16_t>().swap(part_of);

  MergedPoints merged;
  std::vector<uint32_t>& first_of = merged.vertex_of_point;  // a point's first point, until renumbered below
  first_of.resize(n);
  constexpr uint32_t kEmpty = ~uint32_t(0);
  constexpr uint32_t kAhead = 16;
  tbb::enumerable_thread_specific<std::vector<uint32_t>> tables;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, parts, 1), [&](const tbb::blocked_range<size_t>& r) {
    std::vector<uint32_t>& table = tables.local();
    for (size_t part = r.begin(); part < r.end(); ++part) {
      size_t slots = 16;
      while (slots < 2 * size_t(part_start[part + 1] - part_start[part])) slots *= 2;
      table.assign(slots, kEmpty);
      for (uint32_t k = part_start[part]; k < part_start[part + 1]; ++k) {
        // A part's points lie all over the file: fetched a few ahead.
        if (k + kAhead < part_start[part + 1]) __builtin_prefetch(&points[in_parts[k + kAhead]]);
        const uint32_t i = in_parts[k];
        const glm::dvec3& p = points[i];
        size_t slot = hash_of(p) & (slots - 1);
        while (table[slot] != kEmpty && points[table[slot]] != p) slot = (slot + 1) & (slots - 1);
        if (table[slot] == kEmpty) table[slot] = i;
        first_of[i] = table[slot];
      }
    }
  });
  UnsetVector<uint32_t>().swap(in_parts);
  // The first points numbered in file order, then every point renumbered.
  for (uint32_t i = 0; i < n; ++i)
    if (first_of[i] == i) merged.first_point.push_back(i);
  merged.positions.resize(merged.first_point.size());
  UnsetVector<uint32_t> vertex_of_first(n);  // read only at first points
  tbb::parallel_for(tbb::blocked_range<size_t>(0, merged.first_point.size(), 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t v = r.begin(); v < r.end(); ++v) {
      merged.positions[v] = points[merged.first_point[v]];
      vertex_of_first[merged.first_point[v]] = uint32_t(v);
    }
  });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, 4096), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i < r.end(); ++i) first_of[i] = vertex_of_first[first_of[i]];
  });
  return merged;
}

MergedPoints merge_nearby_points(const std::vector<glm::dvec3>& points, double tolerance) {
  MergedPoints merged;
  merged.vertex_of_point.resize(points.size());
  std::unordered_map<uint64_t, std::vector<uint32_t>> kept_in_cell;  // cell -> its kept points' positions
  const auto cell_of = [&](const glm::dvec3& p) { return glm::floor(p / tolerance); };
  const auto key_of = [](const glm::dvec3& cell) {
    return hash_of(cell);  // equal cells hash alike; a collision only adds points to look at
  };
  for (uint32_t i = 0; i < points.size(); ++i) {
    const glm::dvec3& p = points[i];
    const glm::dvec3 cell = cell_of(p);
    uint32_t joined = ~uint32_t(0);
    for (int dz = -1; dz <= 1 && joined == ~uint32_t(0); ++dz)
      for (int dy = -1; dy <= 1 && joined == ~uint32_t(0); ++dy)
        for (int dx = -1; dx <= 1 && joined == ~uint32_t(0); ++dx) {
          const auto found = kept_in_cell.find(key_of(cell + glm::dvec3(dx, dy, dz)));
          if (found == kept_in_cell.end()) continue;
          for (const uint32_t k : found->second)
            if (glm::distance(merged.positions[k], p) <= tolerance) {
              joined = k;
              break;
            }
        }
    if (joined == ~uint32_t(0)) {
      joined = uint32_t(merged.positions.size());
      merged.positions.push_back(p);
      merged.first_point.push_back(i);
      kept_in_cell[key_of(cell)].push_back(joined);
    }
    merged.vertex_of_point[i] = joined;
  }
  return merged;
}

}  // namespace umbra
