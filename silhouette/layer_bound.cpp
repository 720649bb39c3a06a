#include "silhouette/layer_bound.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "mesh/unset_vector.hpp"

namespace umbra {
namespace {

// A plane z = 1 in the frame (axis, e1, e2) at the light, onto which
// directions are projected as (d . e1, d . e2) / (d . axis), with a grid of
// cells over [-range, range]^2.
struct Projection {
  glm::dvec3 axis, e1, e2;
  double range;
};

std::vector<Projection> projections_for(const glm::dvec3& centre, double radius, const glm::dvec3& light) {
  const glm::dvec3 to_centre = centre - light;
  const double distance = glm::length(to_centre);
  // A cone of up to 60 degrees round the mesh: one grid over it.
  if (distance > 0.0 && radius < distance * std::sin(M_PI / 3.0)) {
    const glm::dvec3 axis = to_centre / distance;
    const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 e1 = glm::normalize(glm::cross(axis, helper)), e2 = glm::cross(axis, e1);
    return {{axis, e1, e2, std::tan(std::asin(radius / distance))}};
  }
  std::vector<Projection> cube;  // every direction: the six faces of a cube
  for (int a = 0; a < 3; ++a)
    for (const double sign : {1.0, -1.0}) {
      glm::dvec3 axis(0.0), e1(0.0), e2(0.0);
      axis[a] = sign, e1[(a + 1) % 3] = 1.0, e2[(a + 2) % 3] = 1.0;
      cube.push_back({axis, e1, e2, 1.0});
    }
  return cube;
}

// A triangle's directions that fall in a projection's grid, as a convex
// polygon on its plane: the triangle clipped to the pyramid
// |x|, |y| <= range * z (Sutherland and Hodgman 1974), then projected. Empty
// when none fall in it; `everywhere` when the clipped triangle reaches the
// light itself, whose projection is unbounded.
struct Footprint {
  std::array<glm::dvec2, 8> corners;  // a triangle clipped by 4 planes has at most 7
  int count = 0;
  double orientation = 1.0;  // +1 counter-clockwise, -1 clockwise
  bool everywhere = false;
};

Footprint footprint(const Projection& p, const glm::dvec3 (&d)[3]) {
  std::array<glm::dvec3, 8> polygon, clipped;
  int count = 3, inside = 0;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 q(glm::dot(d[i], p.e1), glm::dot(d[i], p.e2), glm::dot(d[i], p.axis));
    polygon[size_t(i)] = q;
    inside += std::abs(q.x) < p.range * q.z && std::abs(q.y) < p.range * q.z;
  }
  if (inside < 3) {  // clip it
    for (const glm::dvec3 plane :
         {glm::dvec3(-1, 0, p.range), glm::dvec3(1, 0, p.range), glm::dvec3(0, -1, p.range), glm::dvec3(0, 1, p.range)}) {
      int kept = 0;
      for (int i = 0; i < count; ++i) {
        const glm::dvec3& a = polygon[size_t(i)];
        const glm::dvec3& b = polygon[size_t((i + 1) % count)];
        const double sa = glm::dot(plane, a), sb = glm::dot(plane, b);
        if (sa >= 0) clipped[size_t(kept++)] = a;
        if ((sa >= 0) != (sb >= 0)) clipped[size_t(kept++)] = a + (sa / (sa - sb)) * (b - a);
      }
      polygon = clipped;
      count = kept;
      if (count == 0) return {};
    }
  }
  Footprint f;
  double area = 0.0;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3& q = polygon[size_t(i)];
    if (!(q.z > 0)) {
      f.everywhere = true;
      return f;
    }
    f.corners[size_t(i)] = {q.x / q.z, q.y / q.z};
  }
  f.count = count;
  for (int i = 0; i < count; ++i) {
    const glm::dvec2& a = f.corners[size_t(i)];
    const glm::dvec2& b = f.corners[size_t((i + 1) % count)];
    area += a.x * b.y - a.y * b.x;
  }
  f.orientation = area >= 0 ? 1.0 : -1.0;
  return f;
}

// Conservatively: may the convex polygon overlap a square [x, x + w] x
// [y, y + w]? No when the whole square lies outside one of its edges, with a
// margin far above the projection's rounding (the caller has checked the
// bounding boxes). Each edge's inward normal and threshold are worked out
// once per footprint, for the many squares it is tested against.
class OverlapTest {
 public:
  OverlapTest(const Footprint& f, double margin) : count_(f.count) {
    for (int i = 0; i < f.count; ++i) {
      const glm::dvec2& a = f.corners[size_t(i)];
      const glm::dvec2& b = f.corners[size_t((i + 1) % f.count)];
      Edge& e = edges_[size_t(i)];
      e.inward = f.orientation * glm::dvec2(a.y - b.y, b.x - a.x);  // inside: inward . (q - a) >= 0
      e.least = glm::dot(e.inward, a) - margin * (std::abs(e.inward.x) + std::abs(e.inward.y));
    }
  }
  bool may_overlap(double x, double y, double w) const {
    for (int i = 0; i < count_; ++i) {
      const Edge& e = edges_[size_t(i)];
      const glm::dvec2 corner(e.inward.x > 0 ? x + w : x, e.inward.y > 0 ? y + w : y);  // the square's most inward corner
      if (glm::dot(e.inward, corner) < e.least) return false;
    }
    return true;
  }

 private:
  struct Edge {
    glm::dvec2 inward;
    double least;
  };
  std::array<Edge, 8> edges_;
  int count_;
};

// The cells [i0, i1] x [j0, j1] of an n x n grid of cells of width w from
// (x0, y0) that footprint f's bounding box touches (empty: i0 > i1).
struct CellBox {
  int i0, i1, j0, j1;  // unset until made (the boxes of millions of triangles are made on every core)
};
constexpr CellBox kNoCells{0, -1, 0, -1};

CellBox cell_box(const Footprint& f, double x0, double y0, double w, int n, double margin) {
  if (f.everywhere) return {0, n - 1, 0, n - 1};
  if (f.count == 0) return kNoCells;
  double u0 = 1e300, u1 = -1e300, v0 = 1e300, v1 = -1e300;
  for (int k = 0; k < f.count; ++k) {
    const glm::dvec2& q = f.corners[size_t(k)];
    u0 = std::min(u0, q.x), u1 = std::max(u1, q.x), v0 = std::min(v0, q.y), v1 = std::max(v1, q.y);
  }
  const auto cell = [&](double at, double from) { return int(std::floor((at - from) / w)); };
  return {std::max(0, cell(u0 - margin, x0)), std::min(n - 1, cell(u1 + margin, x0)), std::max(0, cell(v0 - margin, y0)),
          std::min(n - 1, cell(v1 + margin, y0))};
}

// Every cell of `box` that footprint f may overlap: all of them where the
// box is at most 2 x 2 cells (the overcount is small there), else those the
// footprint does not miss.
template <typename Visit>
void for_each_cell(const Footprint& f, const CellBox& box, double x0, double y0, double w, double margin, Visit visit) {
  if (f.everywhere || (box.i1 - box.i0 <= 1 && box.j1 - box.j0 <= 1)) {
    for (int j = box.j0; j <= box.j1; ++j)
      for (int i = box.i0; i <= box.i1; ++i) visit(i, j);
    return;
  }
  const OverlapTest test(f, margin);
  for (int j = box.j0; j <= box.j1; ++j)
    for (int i = box.i0; i <= box.i1; ++i)
      if (test.may_overlap(x0 + i * w, y0 + j * w, w)) visit(i, j);
}

// Cells holding more footprints than this are split, 4 x 4 at a time, while
// that lowers the count and up to 4 times (256 finer): where the light's rays
// graze the surface, many edge-on triangles' footprints pass through a cell
// although no ray crosses many of them.
constexpr size_t kSplitAbove = 64;
constexpr int kSplitDepth = 4;
constexpr size_t kAhead = 8;  // triangles fetched ahead
constexpr long kRefineTests = 64;  // footprint tests a hot cell may spend, per footprint it holds

// The most footprints `members` (indices into `all`) over any subcell of the
// square [x, x + w]^2, splitting it while that helps; as soon as a subcell
// holds more than `limit` however far it is split, that count. Each
// footprint tested against a subcell spends one of `budget`; with none left,
// a cell is not split (its count is still a bound, only a looser one).
size_t refined_count(const std::vector<Footprint>& all, const std::vector<uint32_t>& members, double x, double y, double w,
                     double margin, int depth, size_t limit, long& budget) {
  if (depth == kSplitDepth || budget <= 0) return members.size();
  budget -= long(members.size());
  std::vector<uint32_t> sub[16];
  const double s = w / 4.0;
  for (const uint32_t m : members)
    for_each_cell(all[m], cell_box(all[m], x, y, s, 4, margin), x, y, s, margin,
                  [&](int i, int j) { sub[j * 4 + i].push_back(m); });
  size_t most = 0;
  for (int k = 0; k < 16; ++k) {
    size_t count = sub[k].size();
    if (count > kSplitAbove && count < members.size())
      count = refined_count(all, sub[k], x + (k % 4) * s, y + (k / 4) * s, s, margin, depth + 1, limit, budget);
    most = std::max(most, count);
    if (most > limit) break;
  }
  return most;
}

}  // namespace

int layer_bound(const std::vector<glm::dvec3>& positions, const std::vector<std::array<uint32_t, 3>>& triangles,
                const glm::dvec3& light, int limit) {
  if (triangles.size() <= size_t(limit)) return int(triangles.size());
  glm::dvec3 lo(positions[triangles[0][0]]), hi = lo;
  for (const auto& t : triangles)
    for (const uint32_t v : t) lo = glm::min(lo, positions[v]), hi = glm::max(hi, positions[v]);
  const std::vector<Projection> projections = projections_for(0.5 * (lo + hi), 0.5 * glm::length(hi - lo), light);
  // About 2.25 cells a triangle: the grid grows with the mesh, so that
  // cells stay as fine and the work linear (8192 x 8192 cells of 16 bits is
  // 128 MiB a thread, reached only past 30M triangles).
  const int n = int(std::clamp(1.5 * std::sqrt(double(triangles.size()) / double(projections.size())), 16.0, 8192.0));
  const auto footprint_of = [&](size_t t, const Projection& p) {
    const glm::dvec3 d[3] = {positions[triangles[t][0]] - light, positions[triangles[t][1]] - light,
                             positions[triangles[t][2]] - light};
    return footprint(p, d);
  };
  int most = 0;
  for (const Projection& p : projections) {
    const double w = 2.0 * p.range / n, margin = 1e-9 * p.range;
    // Each cell's count of footprints (16 bits, stopping past the limit),
    // and each footprint's box of cells for the second pass.
    // On every core, each thread counting into its own grid, summed after.
    UnsetVector<CellBox> boxes(triangles.size());
    const uint16_t stop = uint16_t(std::min(limit + 1, 65535));
    const auto add = [stop](uint16_t& c, int more) { c = uint16_t(std::min<int>(stop, c + more)); };
    tbb::enumerable_thread_specific<std::vector<uint16_t>> counts([n] { return std::vector<uint16_t>(size_t(n) * size_t(n), 0); });
    tbb::parallel_for(tbb::blocked_range<size_t>(0, triangles.size(), 8192), [&](const tbb::blocked_range<size_t>& r) {
      std::vector<uint16_t>& local = counts.local();
      for (size_t t = r.begin(); t < r.end(); ++t) {
        if (t + kAhead < r.end())  // the corners lie anywhere: fetched a few triangles ahead
          for (const uint32_t v : triangles[t + kAhead]) __builtin_prefetch(&positions[v]);
        const Footprint f = footprint_of(t, p);
        boxes[t] = cell_box(f, -p.range, -p.range, w, n, margin);
        for_each_cell(f, boxes[t], -p.range, -p.range, w, margin,
                      [&](int i, int j) { add(local[size_t(j) * size_t(n) + size_t(i)], 1); });
      }
    });
    // The threads' grids summed into one of them.
    auto grid = counts.begin();
    std::vector<uint16_t>& count = *grid;
    for (++grid; grid != counts.end(); ++grid) {
      const std::vector<uint16_t>& local = *grid;
      tbb::parallel_for(tbb::blocked_range<size_t>(0, count.size(), 1 << 16), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t k = r.begin(); k < r.end(); ++k) add(count[k], local[k]);
      });
    }
    // Split the cells that hold many (in cell order, and a bit per cell, which
    // stays in cache where the counts do not), with the footprints whose
    // boxes touch them.
    std::vector<uint32_t> hot_cells;
    std::vector<uint64_t> hot_bits((count.size() + 63) / 64, 0);
    for (size_t k = 0; k < count.size(); ++k) {
      if (count[k] > kSplitAbove) {
        hot_cells.push_back(uint32_t(k));
        hot_bits[k / 64] |= uint64_t(1) << (k % 64);
      } else {
        most = std::max(most, int(count[k]));
      }
    }
    if (hot_cells.empty()) continue;
    const auto for_each_hot_cell = [&](const CellBox& box, auto visit) {
      for (int j = box.j0; j <= box.j1; ++j)
        for (int i = box.i0; i <= box.i1; ++i) {
          const size_t k = size_t(j) * size_t(n) + size_t(i);
          if ((hot_bits[k / 64] >> (k % 64)) & 1) visit(k);
        }
    };
    std::vector<uint8_t> touches_hot(triangles.size(), 0);
    tbb::parallel_for(tbb::blocked_range<size_t>(0, triangles.size(), 8192), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t t = r.begin(); t < r.end(); ++t) for_each_hot_cell(boxes[t], [&](size_t) { touches_hot[t] = 1; });
    });
    // Each hot cell's triangles, in triangle order; their footprints are made
    // again as each cell is refined (a hot triangle touches a cell or two),
    // which holds far less than keeping them all would.
    std::vector<std::vector<uint32_t>> hot_members(hot_cells.size());
    for (uint32_t t = 0; t < triangles.size(); ++t) {
      if (!touches_hot[t]) continue;
      for_each_hot_cell(boxes[t], [&](size_t k) {
        hot_members[size_t(std::lower_bound(hot_cells.begin(), hot_cells.end(), uint32_t(k)) - hot_cells.begin())].push_back(t);
      });
    }
    // The fullest cells first, so that a stack deeper than the limit shows
    // early; each refined on its own, on every core, spending at most
    // kRefineTests tests per footprint it holds (so the bound is the same
    // whichever thread refines which cell).
    std::vector<uint32_t> fullest(hot_cells.size());
    for (uint32_t h = 0; h < fullest.size(); ++h) fullest[h] = h;
    std::stable_sort(fullest.begin(), fullest.end(), [&](uint32_t a, uint32_t b) { return count[hot_cells[a]] > count[hot_cells[b]]; });
    std::atomic<int> deepest{most};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, fullest.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i < r.end() && deepest.load() <= limit; ++i) {
        const uint32_t h = fullest[i];
        const size_t k = hot_cells[h];
        const double x = -p.range + double(k % size_t(n)) * w, y = -p.range + double(k / size_t(n)) * w;
        const std::vector<uint32_t>& members = hot_members[h];
        std::vector<Footprint> footprints(members.size());
        std::vector<uint32_t> local(members.size());
        for (uint32_t m = 0; m < members.size(); ++m) footprints[m] = footprint_of(members[m], p), local[m] = m;
        long budget = kRefineTests * long(members.size());
        const int found = int(refined_count(footprints, local, x, y, w, margin, 0, size_t(limit), budget));
        for (int seen = deepest.load(); found > seen && !deepest.compare_exchange_weak(seen, found);) {}
      }
    });
    most = deepest.load();
    if (most > limit) return limit + 1;
  }
  return std::min(most, limit + 1);
}

std::vector<FaceRun> layer_bounded_runs(const std::vector<glm::dvec3>& positions,
                                        const std::vector<std::array<uint32_t, 3>>& triangles, const glm::dvec3& light,
                                        int limit) {
  std::vector<FaceRun> runs;
  std::vector<std::pair<uint32_t, uint32_t>> pending{{0, uint32_t(triangles.size())}};
  while (!pending.empty()) {
    const auto [first, end] = pending.back();
    pending.pop_back();
    const std::vector<std::array<uint32_t, 3>> run(triangles.begin() + first, triangles.begin() + end);
    const int bound = run.empty() ? 0 : layer_bound(positions, run, light, limit);
    if (bound <= limit) {
      runs.push_back({first, end, bound});
      continue;
    }
    const uint32_t middle = first + (end - first) / 2;
    pending.push_back({middle, end});  // popped after the first half: runs come out in order
    pending.push_back({first, middle});
  }
  return runs;
}

}  // namespace umbra
