#pragma once
// The mesh files that `umbra check`'s arguments name, and the part of them
// one shard checks.

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace umbra {

// Each argument in order: a file as given (even one that cannot be read, so
// that the check reports it), or a folder searched recursively for the files
// whose content is a mesh format or whose name has a mesh extension, in
// sorted order. A file in a folder that has a mesh's name but is plainly
// something else (a JPEG, a PDF, UTF-16 text, a zip without a model) is
// passed over, with what it is. Links are followed, each folder searched
// once however many links lead to it; a link to nothing, and a second way
// into a folder, are passed over too. Throws UsageError for a folder that
// cannot be searched.
struct MeshPaths {
  std::vector<std::string> meshes;
  // Per mesh, its path relative to the folder argument it was found in, or
  // its file name when it was an argument itself: where a folder's picture goes.
  std::vector<std::string> names;
  // Per mesh, the folder argument it was found in, or "" when it was an
  // argument itself: the folder its texture maps may be read from.
  std::vector<std::string> roots;
  // (path, what it is): "a JPEG image, not a mesh", "a link to nothing (x.obj)"
  std::vector<std::pair<std::string, std::string>> passed_over;
  // A folder's regular files in no format umbra reads, by content or by
  // name (a texture map, a README, a 3DS model), sorted: counted by
  // extension in one line, and each given a JSON record where asked.
  std::vector<std::string> unsupported;
};
// "passed over 3 files in no format umbra reads: 2 .3ds, 1 .png" (the
// commonest extensions first, a file without one as "no extension").
std::string unsupported_summary(const std::vector<std::string>& unsupported);
// What a JSON record says of one of them: "no format umbra reads (OBJ, ...)".
std::string unsupported_reason();
MeshPaths expand_mesh_paths(const std::vector<std::string>& arguments);
// The same for a command that needs some: where none is found (or a path
// cannot be searched), "umbra COMMAND: why" on stderr and none.
std::optional<MeshPaths> found_mesh_paths(const std::vector<std::string>& arguments, const std::string& command);

// Part `index` (from 0) of `count` disjoint, contiguous parts of `paths`,
// which together are all of it in order: shards' outputs, concatenated in
// shard order, are the whole run's output.
struct Shard {
  size_t index = 0, count = 1;
};
Shard parse_shard(const std::string& option, const std::string& text);  // "K/N", 0 <= K < N
std::vector<std::string> shard_of(const std::vector<std::string>& paths, const Shard& shard);

}  // namespace umbra
