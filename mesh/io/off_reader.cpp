// Object File Format: a header line "OFF" (or COFF, NOFF, CNOFF, STOFF...),
// then "V F E" counts, V points "x y z [colour...]" and F polygons
// "n i1 ... in [colour...]" with indices from 0. '#' starts a comment.
#include <algorithm>
#include <limits>

#include "mesh/io/mesh_readers.hpp"
#include "mesh/io/text_scanner.hpp"

namespace umbra {
namespace {

// Moves to the next line that has a field, skipping blank and comment lines.
bool next_content_line(TextScanner& scanner) {
  while (scanner.next_line()) {
    if (scanner.at_line_end()) continue;
    if (scanner.rest_of_line().front() == '#') continue;
    return true;
  }
  return false;
}

void require_line(TextScanner& scanner, bool found, const std::string& what) {
  if (!found) throw InputError({scanner.path(), scanner.line_number(), 0}, "the file ends before " + what);
}

}  // namespace

PolygonSoup read_off(std::string_view text, const std::string& path) {
  PolygonSoup soup;
  soup.path = path;
  soup.format = "OFF";
  TextScanner scanner(text, path);
  require_line(scanner, next_content_line(scanner), "the OFF header");
  const std::string_view header = scanner.field();
  const bool known_header = header.size() >= 3 && header.substr(header.size() - 3) == "OFF" &&
                            header.find_first_not_of("CNST") == header.size() - 3;
  if (!known_header) scanner.fail("expected the header \"OFF\", got " + quote_field(header));
  // The counts may follow the header on its line.
  const bool counts_on_header_line = !scanner.at_line_end() && scanner.rest_of_line().front() != '#';
  if (counts_on_header_line && scanner.rest_of_line().substr(0, 6) == "BINARY")
    scanner.fail("binary OFF is not supported; write the mesh as text OFF, OBJ, PLY or STL");
  if (!counts_on_header_line) require_line(scanner, next_content_line(scanner), "the vertex and face counts");
  // Each point and face takes at least two bytes, so larger counts are lies
  // (and must not make us reserve gigabytes).
  const uint64_t most = std::min<uint64_t>(text.size() / 2, std::numeric_limits<uint32_t>::max() - 1);
  const auto count = [&](const char* what) {
    const uint64_t n = scanner.count(what);
    if (n > most)
      scanner.fail(std::string("the ") + what + " " + std::to_string(n) + " is more than a file of " +
                   std::to_string(text.size()) + " bytes can hold");
    return n;
  };
  const uint64_t point_count = count("vertex count");
  const uint64_t face_count = count("face count");
  soup.points.reserve(point_count);
  soup.point_lines.reserve(point_count);
  soup.polygon_lines.reserve(face_count);
  soup.polygon_starts.reserve(face_count + 1);

  for (uint64_t i = 0; i < point_count; ++i) {
    require_line(scanner, next_content_line(scanner), "vertex " + std::to_string(i) + " of " + std::to_string(point_count));
    const glm::dvec3 p = scanner.vertex();
    soup.add_point(p, scanner.line_number());
  }
  for (uint64_t f = 0; f < face_count; ++f) {
    require_line(scanner, next_content_line(scanner), "face " + std::to_string(f) + " of " + std::to_string(face_count));
    const uint64_t corners = count("face's vertex count");
    if (corners < 3) scanner.fail("a face needs at least 3 vertices, this one has " + std::to_string(corners));
    for (uint64_t k = 0; k < corners; ++k) {
      if (scanner.at_line_end())
        scanner.fail("the face has " + std::to_string(k) + " vertex indices, its count says " + std::to_string(corners));
      const uint64_t index = scanner.count("vertex index");
      if (index >= point_count)
        scanner.fail("vertex index " + std::to_string(index) + " is out of range: the file has " +
                     std::to_string(point_count) + " vertices, counted from 0");
      soup.corners.push_back(uint32_t(index));
    }
    soup.end_polygon(scanner.line_number());
  }
  return soup;
}

}  // namespace umbra
