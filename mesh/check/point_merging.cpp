#include "mesh/check/point_merging.hpp"

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
  // Slots are random accesses into a table far larger than the caches: the
  // next block's are computed and prefetched while this block is inserted.
  constexpr size_t kBlock = 16;
  size_t slot_of[2][kBlock];
  const auto hash_block = [&](size_t first, size_t (&out)[kBlock]) {
    for (size_t k = 0; k < kBlock && first + k < points.size(); ++k) {
      out[k] = hash_of(points[first + k]) & (slots - 1);
      __builtin_prefetch(&table[out[k]]);
    }
  };
  hash_block(0, slot_of[0]);
  for (size_t first = 0, b = 0; first < points.size(); first += kBlock, b ^= 1) {
    if (first + kBlock < points.size()) hash_block(first + kBlock, slot_of[b ^ 1]);
    for (size_t k = 0; k < kBlock && first + k < points.size(); ++k) {
      const uint32_t i = uint32_t(first + k);
      const glm::dvec3& p = points[i];
      size_t slot = slot_of[b][k];
      while (table[slot] != kEmpty && merged.positions[table[slot]] != p) slot = (slot + 1) & (slots - 1);
      if (table[slot] == kEmpty) {
        table[slot] = uint32_t(merged.positions.size());
        merged.positions.push_back(p);
        merged.first_point.push_back(i);
      }
      merged.vertex_of_point[i] = table[slot];
    }
  }
  return merged;
}

}  // namespace umbra
