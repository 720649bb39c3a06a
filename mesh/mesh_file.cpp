#include "mesh/mesh_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "mesh/input_error.hpp"
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
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError({path, 0, 0}, "is a folder, not a mesh file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError({path, 0, 0}, std::string("cannot open: ") + std::strerror(errno));
  // One read into one buffer: a mesh file can be hundreds of megabytes.
  std::string bytes;
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw InputError({path, 0, 0}, "cannot read the file");
  bytes.resize(size_t(size));
  in.seekg(0);
  if (!in.read(bytes.data(), size)) throw InputError({path, 0, 0}, "cannot read the file");
  return parse_polygon_soup(bytes, path);
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
