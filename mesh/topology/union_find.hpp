#pragma once
// Disjoint sets over 0..n-1 (union by rank, path halving), and a variant that
// also keeps each element's parity relative to its set's root: the tool for
// deciding whether faces can be flipped to agree on every shared edge.
// Ranks stay below 32 (a root of rank r holds at least 2^r elements), so a
// byte holds one: 5 bytes an element rather than 8 for sizes, which counts at
// a corner each for millions of corners (Tarjan and van Leeuwen, "Worst-case
// Analysis of Set Union Algorithms", 1984: rank and halving keep the bound).

#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

namespace umbra {

class UnionFind {
 public:
  explicit UnionFind(size_t n) : parent_(n), rank_(n, 0) { std::iota(parent_.begin(), parent_.end(), uint32_t(0)); }

  uint32_t find(uint32_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }

  void unite(uint32_t a, uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (rank_[a] < rank_[b]) std::swap(a, b);
    parent_[b] = a;
    if (rank_[a] == rank_[b]) ++rank_[a];
  }

 private:
  std::vector<uint32_t> parent_;
  std::vector<uint8_t> rank_;
};

class ParityUnionFind {
 public:
  explicit ParityUnionFind(size_t n) : parent_(n), parity_(n, 0), rank_(n, 0) {
    std::iota(parent_.begin(), parent_.end(), uint32_t(0));
  }

  // The root of x's set and x's parity relative to it.
  std::pair<uint32_t, uint8_t> find(uint32_t x) {
    uint8_t parity = 0;
    uint32_t root = x;
    while (parent_[root] != root) {
      parity ^= parity_[root];
      root = parent_[root];
    }
    // Compress: point every element on the path straight at the root.
    uint8_t remaining = parity;
    while (parent_[x] != root && x != root) {
      const uint32_t next = parent_[x];
      const uint8_t own = parity_[x];
      parent_[x] = root;
      parity_[x] = remaining;
      remaining ^= own;
      x = next;
    }
    return {root, parity};
  }

  // Records that a and b differ by `parity`; false when that contradicts what is known.
  bool unite(uint32_t a, uint32_t b, uint8_t parity) {
    auto [ra, pa] = find(a);
    auto [rb, pb] = find(b);
    if (ra == rb) return (pa ^ pb) == parity;
    if (rank_[ra] < rank_[rb]) std::swap(ra, rb);
    parent_[rb] = ra;
    parity_[rb] = pa ^ pb ^ parity;
    if (rank_[ra] == rank_[rb]) ++rank_[ra];
    return true;
  }

 private:
  std::vector<uint32_t> parent_;
  std::vector<uint8_t> parity_;  // relative to the parent
  std::vector<uint8_t> rank_;
};

}  // namespace umbra
