#include "mesh/io/mesh_file.hpp"

#include <stdexcept>

#include "mesh/input_error.hpp"
#include "mesh/io/mapped_file.hpp"
#include "mesh/io/mesh_format.hpp"
#include "mesh/io/mesh_readers.hpp"

namespace umbra {

namespace {

// A UTF-8 byte-order mark, as some Windows tools write before OBJ, OFF or
// STL text, is no part of the content (columns are counted after it).
std::string_view without_byte_order_mark(std::string_view bytes) {
  if (bytes.substr(0, 3) == "\xef\xbb\xbf") bytes.remove_prefix(3);
  return bytes;
}

}  // namespace

std::string mesh_reader_of(std::string_view bytes, const std::string& path) {
  bytes = without_byte_order_mark(bytes);
  // The content decides; the extension only names the reader whose located
  // errors best explain a file too broken for its content to say: one of
  // umbra's own (a library's says only that it cannot read it, and a STEP
  // file without STEP's header, such as a SystemTap script named .stp, is
  // no STEP file).
  const std::string format = detect_mesh_format(bytes, path);
  const MeshFormat* named = mesh_format_by_id(mesh_format_of(path));
  // Not OBJ, though: any text would read as an OBJ without faces.
  // Nor for what is plainly some other format.
  if (format.empty() && named && named->fuzzed && named->id != "obj" && other_known_format(bytes).empty()) return std::string(named->id);
  return format;
}

PolygonSoup parse_polygon_soup(std::string_view bytes, const std::string& path, const ReadOptions& maps) {
  bytes = without_byte_order_mark(bytes);
  if (const std::string blank = blank_content(bytes); !blank.empty()) throw InputError({path, 0, 0}, blank, InputProblem::kEmpty);
  const MeshFormat* reader = mesh_format_by_id(mesh_reader_of(bytes, path));
  if (!reader)
    throw InputError({path, 0, 0}, "not a mesh file (" + mesh_format_names() + "): " + describe_content(bytes),
                     InputProblem::kUnsupportedFormat);
  PolygonSoup soup = reader->read(bytes, path, maps);
  if (soup.format.empty()) soup.format = reader->name;  // a reader names a variant ("STL (binary)") or leaves it to its row
  require_corners_in_range(soup);
  if (!soup.polygon_materials.empty() && soup.polygon_materials.size() != soup.polygon_count())
    throw std::logic_error("a reader gave " + std::to_string(soup.polygon_materials.size()) + " face materials for " +
                           std::to_string(soup.polygon_count()) + " faces");
  return soup;
}

PolygonSoup read_polygon_soup(const std::string& path, const ReadOptions& maps) {
  const MappedFile file(path);
  // A file cut short while it was read reads as zeros past its new end:
  // whatever that made of it, say what happened instead.
  const auto changed = [&] { return InputError({path, 0, 0}, "the file was cut short while it was read: read it again once it is written"); };
  PolygonSoup soup;
  try {
    soup = parse_polygon_soup(file.bytes(), path, maps);
  } catch (const InputError&) {
    if (file.cut_short()) throw changed();
    throw;
  }
  if (file.cut_short()) throw changed();
  return soup;
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
