#pragma once
// Reading a mesh file (OBJ, OFF, PLY or STL, chosen by the file's extension)
// into a polygon soup, exactly as written.

#include <string>
#include <string_view>

#include "mesh/polygon_soup.hpp"

namespace umbra {

// Throws InputError ("FILE: reason" or "FILE:LINE:COL: reason") when the file
// cannot be opened or is not a valid mesh of its format.
PolygonSoup read_polygon_soup(const std::string& path);

// The same from bytes already in memory; `path` names them in errors and
// chooses the format by its extension.
PolygonSoup parse_polygon_soup(std::string_view bytes, const std::string& path);

// "obj", "off", "ply", "stl" for a path with one of those extensions (any
// case), or "" for any other.
std::string mesh_format_of(const std::string& path);

}  // namespace umbra
