#pragma once
// The mesh files that `umbra check`'s arguments name, and the part of them
// one shard checks.

#include <cstddef>
#include <string>
#include <vector>

namespace umbra {

// Each argument in order: a file as given (even one that cannot be read, so
// that the check reports it), or a folder searched recursively for the files
// whose content is a mesh format or whose name has a mesh extension, in
// sorted order. Throws UsageError for a folder that cannot be searched.
std::vector<std::string> expand_mesh_paths(const std::vector<std::string>& arguments);

// Part `index` (from 0) of `count` disjoint, contiguous parts of `paths`,
// which together are all of it in order: shards' outputs, concatenated in
// shard order, are the whole run's output.
struct Shard {
  size_t index = 0, count = 1;
};
Shard parse_shard(const std::string& option, const std::string& text);  // "K/N", 0 <= K < N
std::vector<std::string> shard_of(const std::vector<std::string>& paths, const Shard& shard);

}  // namespace umbra
