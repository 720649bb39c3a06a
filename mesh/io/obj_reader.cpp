// Wavefront OBJ: `v x y z [w]` points and `f i j k ...` polygons whose corners
// are `v`, `v/vt`, `v//vn` or `v/vt/vn`, counted from 1, or from the end when
// negative; `usemtl` gives the faces after it a material of the `mtllib`
// files beside the OBJ (Kd, Ks, Ns). Texture coordinates, normals, groups and
// texture maps are skipped.
#include <algorithm>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <limits>
#include <map>
#include <set>

#include <glm/common.hpp>

#include "mesh/io/mapped_file.hpp"
#include "mesh/io/mesh_readers.hpp"
#include "mesh/io/text_scanner.hpp"

namespace umbra {
namespace {

// The point index (from 0) of one face corner such as "7/3/2" or "-1//4".
uint32_t corner_index(TextScanner& scanner, std::string_view corner, size_t points_so_far) {
  const std::string_view vertex = corner.substr(0, corner.find('/'));
  int64_t value = 0;
  const char* first = vertex.data();
  const char* last = vertex.data() + vertex.size();
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last || vertex.empty())
    scanner.fail("expected a vertex index (as in \"f 1 2 3\" or \"f 1/1/1 2/2/2 3/3/3\"), got " + quote_field(corner));
  if (value == 0) scanner.fail("vertex indices count from 1 (or from -1 backwards); 0 is not an index");
  const int64_t index = value > 0 ? value - 1 : int64_t(points_so_far) + value;
  if (index < 0)
    scanner.fail("relative vertex index " + std::to_string(value) + " points before the first vertex (only " +
                 std::to_string(points_so_far) + " defined so far)");
  if (index >= int64_t(std::numeric_limits<uint32_t>::max()))
    scanner.fail("vertex index " + std::to_string(value) + " is out of range");
  return uint32_t(index);
}

// How many lines start with "v " and "f ": one quick pass, so that the
// arrays are allocated once rather than grown (and copied) as they fill.
std::pair<size_t, size_t> vertex_and_face_lines(std::string_view text) {
  size_t vertices = 0, faces = 0;
  for (size_t at = 0; at + 1 < text.size();) {
    if (text[at + 1] == ' ' || text[at + 1] == '\t') vertices += text[at] == 'v', faces += text[at] == 'f';
    const void* newline = std::memchr(text.data() + at, '\n', text.size() - at);
    if (!newline) break;
    at = size_t(static_cast<const char*>(newline) - text.data()) + 1;
  }
  return {vertices, faces};
}

// The rest of the line without the blanks round it: a material's name may hold spaces.
std::string rest_as_name(const TextScanner& scanner) {
  std::string_view rest = scanner.rest_of_line();
  const size_t first = rest.find_first_not_of(" \t"), last = rest.find_last_not_of(" \t");
  return first == std::string_view::npos ? "" : std::string(rest.substr(first, last - first + 1));
}

// The materials of one .mtl file (Wavefront's material library) into `soup`,
// by name into `named`. Kd, Ks and Ns are kept; texture maps are noted once.
void read_material_library(const std::string& path, int line, PolygonSoup& soup, std::map<std::string, int>& named) {
  std::error_code exists_error;
  if (!std::filesystem::is_regular_file(path, exists_error)) {
    soup.warn(line, "material library \"" + path + "\" not found: its materials are left out");
    return;
  }
  const MappedFile file(path);
  TextScanner scanner(file.bytes(), path);
  SoupMaterial* current = nullptr;
  bool noted_maps = false;
  while (scanner.next_line()) {
    const std::string_view keyword = scanner.field();
    if (keyword == "newmtl") {
      const std::string name = rest_as_name(scanner);
      soup.materials.push_back({name});
      named[name] = int(soup.materials.size() - 1);
      current = &soup.materials.back();
    } else if (current && (keyword == "Kd" || keyword == "Ks")) {
      glm::dvec3 rgb;
      rgb.r = scanner.number("red");
      // "Kd r" alone means grey r (the format allows g and b to be left out).
      rgb.g = scanner.at_line_end() ? rgb.r : scanner.number("green");
      rgb.b = scanner.at_line_end() ? rgb.g : scanner.number("blue");
      (keyword == "Kd" ? current->diffuse : current->specular) = glm::clamp(rgb, 0.0, 1.0);
    } else if (current && keyword == "Ns") {
      current->shininess = std::max(0.0, scanner.number("shininess"));
    } else if (!noted_maps && keyword.substr(0, 4) == "map_") {
      soup.warn(line, "the materials' texture maps are ignored: faces take each material's Kd colour");
      noted_maps = true;
    }
  }
}

}  // namespace

PolygonSoup read_obj(std::string_view text, const std::string& path) {
  PolygonSoup soup;
  soup.path = path;
  soup.format = "OBJ";
  const auto [vertex_lines, face_lines] = vertex_and_face_lines(text);
  soup.points.reserve(vertex_lines);
  soup.point_lines.reserve(vertex_lines);
  soup.corners.reserve(3 * face_lines);
  soup.polygon_starts.reserve(face_lines + 1);
  soup.polygon_lines.reserve(face_lines);
  TextScanner scanner(text, path);
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::map<std::string, int> materials;  // by name
  std::set<std::string> missing;         // used but defined nowhere: said once each
  int material = -1;                     // of the faces that follow
  while (scanner.next_line()) {
    const std::string_view keyword = scanner.field();
    if (keyword == "v") {
      const glm::dvec3 p = scanner.vertex();
      soup.add_point(p, scanner.line_number());
    } else if (keyword == "mtllib") {
      for (std::string_view name = scanner.field(); !name.empty(); name = scanner.field())
        read_material_library((folder / std::string(name)).lexically_normal().string(), scanner.line_number(), soup, materials);
    } else if (keyword == "usemtl") {
      const std::string name = rest_as_name(scanner);
      const auto it = materials.find(name);
      material = it == materials.end() ? -1 : it->second;
      if (it == materials.end() && missing.insert(name).second)
        soup.warn(scanner.line_number(), "material " + quote_field(name) + " is in no material library: its faces keep the scene's material");
    } else if (keyword == "f") {
      uint32_t corners = 0;
      for (std::string_view corner = scanner.field(); !corner.empty(); corner = scanner.field()) {
        soup.corners.push_back(corner_index(scanner, corner, soup.points.size()));
        ++corners;
      }
      if (corners < 3) scanner.fail_at_line("a face needs at least 3 vertices, this one has " + std::to_string(corners));
      soup.end_polygon(scanner.line_number());
      // Per-face materials from the first face that has one (the faces before it have none).
      if (material >= 0 && soup.polygon_materials.size() + 1 < soup.polygon_count()) soup.polygon_materials.assign(soup.polygon_count() - 1, -1);
      if (material >= 0 || !soup.polygon_materials.empty()) soup.polygon_materials.push_back(material);
    }
  }
  return soup;
}

}  // namespace umbra
