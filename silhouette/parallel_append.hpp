#pragma once
// A volume's indices made on every core, in the order one loop makes them:
// each item (a face, an edge) adds a number of indices known beforehand. The
// items are cut into blocks; each block counts its indices, the counts'
// running sum gives each block its place, and each block writes there. The
// buffer and the picture are the same as a serial loop's, byte for byte.

#include <algorithm>
#include <cstddef>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "silhouette/volume_indices.hpp"

namespace umbra {

// Items per block: enough work to pay for a task, few enough blocks that
// every core gets several.
constexpr size_t kAppendBlock = 16384;
// Faces per task when each face is classified against the light.
constexpr size_t kClassifyBlock = 8192;

// For each item i in [0, n): `size(i)` indices, written by `write(i, out)`
// at `out`, appended to `volume` in item order. Returns the indices added.
template <typename Size, typename Write>
size_t append_in_order(MeshVolumeIndices& volume, size_t n, const Size& size, const Write& write) {
  const size_t blocks = (n + kAppendBlock - 1) / kAppendBlock;
  std::vector<size_t> start(blocks + 1, 0);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, blocks, 1), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t b = r.begin(); b < r.end(); ++b) {
      size_t total = 0;
      for (size_t i = b * kAppendBlock; i < std::min(n, (b + 1) * kAppendBlock); ++i) total += size(i);
      start[b + 1] = total;
    }
  });
  for (size_t b = 0; b < blocks; ++b) start[b + 1] += start[b];
  uint32_t* const first = volume.append(start[blocks]);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, blocks, 1), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t b = r.begin(); b < r.end(); ++b) {
      uint32_t* out = first + start[b];
      for (size_t i = b * kAppendBlock; i < std::min(n, (b + 1) * kAppendBlock); ++i) {
        const size_t s = size(i);
        if (s == 0) continue;
        write(i, out);
        out += s;
      }
    }
  });
  return start[blocks];
}

}  // namespace umbra
