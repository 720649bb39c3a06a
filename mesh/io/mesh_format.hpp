#pragma once
// Which mesh format a file is in: by its content first (PLY, OFF and GLB
// magic, a zip with a .model part for 3MF, binary STL's size, ascii STL's
// "solid ... facet", glTF's JSON "asset", OBJ's statements), with
// the file name's extension as the fallback for content too broken to tell.

#include <string>
#include <string_view>

namespace umbra {

// "obj", "off", "ply", "stl", "gltf" (JSON or GLB) or "3mf" when `bytes` (a
// whole file) plainly are one;
// "" when they are not, or are too broken to say.
std::string detect_mesh_format(std::string_view bytes);

// The same for the file at `path`, read by memory mapping; "" too when it
// cannot be read (whoever reads it next says why).
std::string detect_mesh_format_of_file(const std::string& path);

// "obj", "off", "ply", "stl", "3mf" for a path with one of those extensions
// (any case), "gltf" for .gltf and .glb, or "" for any other.
std::string mesh_format_of(const std::string& path);

// What `bytes` are when they are plainly some other format (UTF-16 text, a zip
// archive with no 3D model part, a JPEG or PNG image, a PDF), or "".
std::string other_known_format(std::string_view bytes);

// The same for the file at `path`; "" too when it cannot be read.
std::string other_known_format_of_file(const std::string& path);

// What `bytes` look like, for the message when they are no mesh format:
// "empty", "binary data", "UTF-16 text", "text starting with \"...\"".
std::string describe_content(std::string_view bytes);

}  // namespace umbra
