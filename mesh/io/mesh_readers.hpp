#pragma once
// The readers behind read_polygon_soup, one per format, each over the file's
// bytes. Each checks what its format requires and throws InputError naming the
// file and, where there is one, the line.

#include <string>
#include <string_view>

#include "mesh/io/polygon_soup.hpp"

namespace umbra {

PolygonSoup read_obj(std::string_view text, const std::string& path);
PolygonSoup read_off(std::string_view text, const std::string& path);
PolygonSoup read_stl(std::string_view bytes, const std::string& path);  // ascii or binary
PolygonSoup read_ply(std::string_view bytes, const std::string& path);  // ascii or binary

// Throws a located error when a polygon refers to a point the file lacks.
void require_corners_in_range(const PolygonSoup& soup);

}  // namespace umbra
