#pragma once
// Float pictures as OpenEXR files (Kainz, Bogart and Stanczyk, "Technical
// Introduction to OpenEXR", Industrial Light & Magic, 2004): a view's depth
// and normals, which need more than 8 bits and values beyond 0 to 1.
// Written with Debian's OpenEXR library, 32-bit float channels, ZIP
// compressed (lossless), rows from the top.

#include <string>
#include <vector>

#include "image/partial_file.hpp"

namespace umbra {

// A width x height picture of `channels.size()` float channels, interleaved
// per pixel in `values` (the channels' names in EXR's convention: "Z" for
// depth, "R", "G", "B" for a vector), into `into`'s temporary file, for the
// caller to commit with the run's other outputs. Throws std::runtime_error,
// naming the path, when it cannot be written.
void write_exr_into(const std::vector<float>& values, int width, int height, const std::vector<std::string>& channels,
                    const PartialFile& into);

// A float picture read back: what write_exr_into wrote (for tests and the
// Python module's readers); throws std::runtime_error naming the path.
struct ExrPicture {
  int width = 0, height = 0;
  std::vector<std::string> channels;  // sorted by name, as EXR keeps them
  std::vector<float> values;          // interleaved per pixel in `channels`' order
};
ExrPicture read_exr(const std::string& path);

}  // namespace umbra
