#pragma once
// A counting sort on every core: items 0..n-1 each put values into buckets,
// and the buckets come out as one core taking the items in order would fill
// them. Each core takes a run of items, counts what it puts in each bucket,
// then fills its own share of each bucket, after the shares of the runs
// before it: two passes over the items, and a count per bucket per run.

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace umbra {

// for_each_item(first, end, put) calls put(bucket, value) for what items
// [first, end) put, in item order; it is called twice per run (once to
// count, once to fill), and must put the same both times. Fills `values`
// and `start` (bucket b is values[start[b], start[b + 1])); `values` may be
// an UnsetVector, every element being written.
template <typename Value, typename ForEachItem, typename Values>
void fill_buckets(size_t item_count, size_t bucket_count, const ForEachItem& for_each_item, std::vector<uint32_t>& start,
                  Values& values) {
  const size_t runs = std::clamp<size_t>(size_t(tbb::this_task_arena::max_concurrency()), 1, 8);
  const auto run_start = [&](size_t r) { return uint32_t(item_count * r / runs); };
  std::vector<std::vector<uint32_t>> cursor(runs);
  tbb::parallel_for(size_t(0), runs, [&](size_t r) {
    cursor[r].assign(bucket_count, 0);
    for_each_item(run_start(r), run_start(r + 1), [&](size_t bucket, const Value&) { ++cursor[r][bucket]; });
  });
  start.assign(bucket_count + 1, 0);
  for (size_t b = 0; b < bucket_count; ++b) {
    uint32_t filled = start[b];
    for (std::vector<uint32_t>& run_cursor : cursor) filled += std::exchange(run_cursor[b], filled);
    start[b + 1] = filled;
  }
  values.resize(start[bucket_count]);
  tbb::parallel_for(size_t(0), runs, [&](size_t r) {
    for_each_item(run_start(r), run_start(r + 1), [&](size_t bucket, const Value& value) { values[cursor[r][bucket]++] = value; });
  });
}

}  // namespace umbra
