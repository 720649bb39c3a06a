#pragma once
// Reading a mesh file (OBJ, OFF, PLY, STL, glTF or 3MF, told by its content; see
// mesh_format.hpp) into a polygon soup, exactly as written.

#include <string>
#include <string_view>

#include "mesh/io/mesh_format.hpp"
#include "mesh/io/polygon_soup.hpp"

namespace umbra {

// Throws InputError ("FILE: reason" or "FILE:LINE:COL: reason") when the file
// cannot be opened or is not a valid mesh of its format.
PolygonSoup read_polygon_soup(const std::string& path, const ReadOptions& maps = {});

// The same from bytes already in memory; `path` names them in errors, and
// its extension chooses the reader when the content is too broken to tell.
PolygonSoup parse_polygon_soup(std::string_view bytes, const std::string& path, const ReadOptions& maps = {});
// The id of the format whose reader parse_polygon_soup gives these bytes
// ("obj", ...); empty when it reads them as no mesh.
std::string mesh_reader_of(std::string_view bytes, const std::string& path);

}  // namespace umbra
