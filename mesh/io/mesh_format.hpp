#pragma once
// Which mesh format a file is in: by its content first (PLY and OFF magic,
// binary STL's size, ascii STL's "solid ... facet", OBJ's statements), with
// the file name's extension as the fallback for content too broken to tell.

#include <string>
#include <string_view>

namespace umbra {

// "obj", "off", "ply" or "stl" when `bytes` (a whole file) plainly are one;
// "" when they are not, or are too broken to say.
std::string detect_mesh_format(std::string_view bytes);

// "obj", "off", "ply", "stl" for a path with one of those extensions (any
// case), or "" for any other.
std::string mesh_format_of(const std::string& path);

// What `bytes` look like, for the message when they are no mesh format:
// "empty", "binary data", "UTF-16 text", "text starting with \"...\"".
std::string describe_content(std::string_view bytes);

}  // namespace umbra
