#include "mesh/mesh_file.hpp"

#include <filesystem>

#include "mesh/input_error.hpp"
#include "mesh/mapped_file.hpp"
#include "mesh/mesh_readers.hpp"

namespace umbra {

std::string mesh_format_of(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".obj" || ext == ".off" || ext == ".ply" || ext == ".stl") return ext.substr(1);
  return "";
}

PolygonSoup parse_polygon_soup(std::string_view bytes, const std::string& path) {
  const std::string format = mesh_format_of(path);
  PolygonSoup soup;
  if (format == "obj") soup = read_obj(bytes, path);
  else if (format == "off") soup = read_off(bytes, path);
  else if (format == "ply") soup = read_ply(bytes, path);
  else if (format == "stl") soup = read_stl(bytes, path);
  else throw InputError({path, 0, 0}, "unknown mesh format: the file name must end in .obj, .off, .ply or .stl");
  require_corners_in_range(soup);
  return soup;
}

PolygonSoup read_polygon_soup(const std::string& path) {
  if (mesh_format_of(path).empty())
    throw InputError({path, 0, 0}, "unknown mesh format: the file name must end in .obj, .off, .ply or .stl");
  const MappedFile file(path);
  return parse_polygon_soup(file.bytes(), path);
}

void require_corners_in_range(const PolygonSoup& soup) {
  const size_t point_count = soup.points.size();
  for (size_t p = 0; p < soup.polygon_count(); ++p) {
    const uint32_t* corners = soup.polygon(p);
    for (uint32_t k = 0; k < soup.corner_count(p); ++k) {
      if (corners[k] >= point_count)
        throw InputError({soup.path, soup.polygon_line(p), 0},
                         "face " + std::to_string(p) + " refers to vertex " + std::to_string(corners[k]) +
                             " (counting from 0), but the file has " + std::to_string(point_count) + " vertices");
    }
  }
}

}  // namespace umbra
