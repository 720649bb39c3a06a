// Wavefront OBJ: `v x y z [w]` points and `f i j k ...` polygons whose corners
// are `v`, `v/vt`, `v//vn` or `v/vt/vn`, counted from 1, or from the end when
// negative. Texture coordinates, normals, groups and materials are skipped:
// a check needs only positions and faces.
#include <charconv>
#include <cstring>
#include <limits>

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
  while (scanner.next_line()) {
    const std::string_view keyword = scanner.field();
    if (keyword == "v") {
      const glm::dvec3 p = scanner.vertex();
      soup.add_point(p, scanner.line_number());
    } else if (keyword == "f") {
      uint32_t corners = 0;
      for (std::string_view corner = scanner.field(); !corner.empty(); corner = scanner.field()) {
        soup.corners.push_back(corner_index(scanner, corner, soup.points.size()));
        ++corners;
      }
      if (corners < 3) scanner.fail_at_line("a face needs at least 3 vertices, this one has " + std::to_string(corners));
      soup.end_polygon(scanner.line_number());
    }
  }
  return soup;
}

}  // namespace umbra
