#pragma once
// The names a folder render gives its pictures: one per input file, never
// two alike, decided for all the files before anything is drawn, so that
// no picture overwrites another and every shard names alike.

#include <string>
#include <vector>

namespace umbra {

// `names` (each file's path relative to the folder it was found in, or its
// file name; see MeshPaths) made distinct: files that share a name take as
// many of their folders' names in front as tell them apart (a/x.off and
// b/x.off, both named x.off), and a file given twice takes " (2)", " (3)".
// `paths` and `roots` are the files and the folders they were found in ("":
// named on its own), as MeshPaths holds them.
std::vector<std::string> distinct_picture_names(const std::vector<std::string>& paths, std::vector<std::string> names,
                                                const std::vector<std::string>& roots);

}  // namespace umbra
