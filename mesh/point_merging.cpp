#include "mesh/point_merging.hpp"

#include <cstring>

namespace umbra {
namespace {

uint64_t bits_of(double x) {
  if (x == 0.0) x = 0.0;  // -0.0 equals 0.0, so it must hash the same
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
  // An open-addressing table of distinct positions, at most half full: one
  // pass, and 4 bytes per slot rather than a sorted copy of every point.
  size_t slots = 16;
  while (slots < 2 * points.size()) slots *= 2;
  constexpr uint32_t kEmpty = ~uint32_t(0);
  std::vector<uint32_t> table(slots, kEmpty);  // position index, or kEmpty

  MergedPoints merged;
  merged.vertex_of_point.resize(points.size());
  for (uint32_t i = 0; i < points.size(); ++i) {
    const glm::dvec3& p = points[i];
    size_t slot = hash_of(p) & (slots - 1);
    while (table[slot] != kEmpty && merged.positions[table[slot]] != p) slot = (slot + 1) & (slots - 1);
    if (table[slot] == kEmpty) {
      table[slot] = uint32_t(merged.positions.size());
      merged.positions.push_back(p);
      merged.first_point.push_back(i);
    }
    merged.vertex_of_point[i] = table[slot];
  }
  return merged;
}

}  // namespace umbra
