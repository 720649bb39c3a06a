// Stanford PLY, ascii or binary (either byte order): the "vertex" element's
// x, y, z and the "face" element's "vertex_indices" (or "vertex_index") list.
// The vertices' nx, ny and nz are kept as their corners' normals. Other
// elements and properties are read past and ignored.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>

#include "mesh/io/mesh_readers.hpp"
#include "mesh/io/text_scanner.hpp"

namespace umbra {
namespace {

enum class PlyType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::kFloat32;  // the item type for a list
  bool is_list = false;
  PlyType count_type = PlyType::kUint8;
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyEncoding { kAscii, kLittleEndian, kBigEndian };

bool parse_type(std::string_view name, PlyType& type) {
  static const struct { const char* name; PlyType type; } kTypes[] = {
      {"char", PlyType::kInt8},     {"int8", PlyType::kInt8},       {"uchar", PlyType::kUint8},
      {"uint8", PlyType::kUint8},   {"short", PlyType::kInt16},     {"int16", PlyType::kInt16},
      {"ushort", PlyType::kUint16}, {"uint16", PlyType::kUint16},   {"int", PlyType::kInt32},
      {"int32", PlyType::kInt32},   {"uint", PlyType::kUint32},     {"uint32", PlyType::kUint32},
      {"float", PlyType::kFloat32}, {"float32", PlyType::kFloat32}, {"double", PlyType::kFloat64},
      {"float64", PlyType::kFloat64}};
  for (const auto& t : kTypes) {
    if (name == t.name) {
      type = t.type;
      return true;
    }
  }
  return false;
}

bool is_integer(PlyType t) { return t != PlyType::kFloat32 && t != PlyType::kFloat64; }

size_t size_of(PlyType t) {
  switch (t) {
    case PlyType::kInt8: case PlyType::kUint8: return 1;
    case PlyType::kInt16: case PlyType::kUint16: return 2;
    case PlyType::kInt32: case PlyType::kUint32: case PlyType::kFloat32: return 4;
    case PlyType::kFloat64: return 8;
  }
  return 0;
}

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::kAscii;
  std::vector<PlyElement> elements;
  size_t body_offset = 0;  // first byte after "end_header\n"
  int body_line = 0;       // lines before the body
};

// Lines the format does not define (exporters write their name, for one) are
// read past with a warning, as is "end_header" with more on its line.
PlyHeader read_header(TextScanner& scanner, std::vector<ReadWarning>& warnings) {
  PlyHeader header;
  if (!scanner.next_line() || scanner.field() != "ply") scanner.fail_at_line("not a PLY file: it must begin with \"ply\"");
  bool have_format = false;
  while (true) {
    if (!scanner.next_line()) scanner.fail_at_line("the PLY header has no \"end_header\"");
    const std::string_view keyword = scanner.field();
    if (keyword == "end_header" && scanner.at_line_end()) break;
    if (keyword == "comment" || keyword == "obj_info" || keyword.empty()) continue;
    if (keyword == "format") {
      const std::string_view encoding = scanner.field();
      if (encoding == "ascii") header.encoding = PlyEncoding::kAscii;
      else if (encoding == "binary_little_endian") header.encoding = PlyEncoding::kLittleEndian;
      else if (encoding == "binary_big_endian") header.encoding = PlyEncoding::kBigEndian;
      else scanner.fail("unknown PLY format " + quote_field(encoding) + " (ascii, binary_little_endian or binary_big_endian)");
      have_format = true;
    } else if (keyword == "element") {
      PlyElement element;
      element.name = std::string(scanner.field());
      if (element.name.empty()) scanner.fail("expected an element name");
      element.count = scanner.count("element count");
      if (element.count >= std::numeric_limits<uint32_t>::max()) scanner.fail("the element count is too large");
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) scanner.fail("a property before any element");
      PlyProperty property;
      std::string_view type = scanner.field();
      if (type == "list") {
        property.is_list = true;
        const std::string_view count_type = scanner.field();
        if (!parse_type(count_type, property.count_type) || !is_integer(property.count_type))
          scanner.fail("expected an integer type for the list's count, got " + quote_field(count_type));
        type = scanner.field();
      }
      if (!parse_type(type, property.type)) scanner.fail("unknown PLY property type " + quote_field(type));
      property.name = std::string(scanner.field());
      if (property.name.empty()) scanner.fail("expected a property name");
      header.elements.back().properties.push_back(std::move(property));
    } else {
      warnings.push_back({scanner.line_number(), "unknown PLY header line " + quote_field(keyword) + " ignored"});
    }
  }
  if (!have_format) scanner.fail_at_line("the PLY header has no \"format\" line");
  header.body_line = scanner.line_number();
  return header;
}

// Where the vertex positions and face lists are among the properties.
struct PlyLayout {
  int x = -1, y = -1, z = -1;  // property indices in the vertex element
  int colour[3] = {-1, -1, -1};  // red, green and blue, when the vertex element has all three
  int normal[3] = {-1, -1, -1};  // nx, ny and nz, likewise
  int indices = -1;            // property index of the face element's list
  bool has_colour() const { return colour[0] >= 0 && colour[1] >= 0 && colour[2] >= 0; }
  bool has_normal() const { return normal[0] >= 0 && normal[1] >= 0 && normal[2] >= 0; }
};

// A colour channel in [0, 1]: integers over their type's largest value
// (255 for uchar), floats as they are.
float colour_channel(double v, PlyType type) {
  double full = 1.0;
  switch (type) {
    case PlyType::kInt8: full = 127.0; break;
    case PlyType::kUint8: full = 255.0; break;
    case PlyType::kInt16: full = 32767.0; break;
    case PlyType::kUint16: full = 65535.0; break;
    case PlyType::kInt32: full = 2147483647.0; break;
    case PlyType::kUint32: full = 4294967295.0; break;
    case PlyType::kFloat32: case PlyType::kFloat64: break;
  }
  const double c = v / full;
  return std::isfinite(c) ? float(std::clamp(c, 0.0, 1.0)) : 0.0f;
}

PlyLayout find_layout(const PlyHeader& header, const std::string& path) {
  PlyLayout layout;
  bool have_vertex = false, have_face = false;
  for (const PlyElement& e : header.elements) {
    for (int i = 0; i < int(e.properties.size()); ++i) {
      const PlyProperty& p = e.properties[size_t(i)];
      if (e.name == "vertex" && !p.is_list) {
        if (p.name == "x") layout.x = i;
        if (p.name == "y") layout.y = i;
        if (p.name == "z") layout.z = i;
        if (p.name == "red" || p.name == "r") layout.colour[0] = i;
        if (p.name == "green" || p.name == "g") layout.colour[1] = i;
        if (p.name == "blue" || p.name == "b") layout.colour[2] = i;
        if (p.name == "nx") layout.normal[0] = i;
        if (p.name == "ny") layout.normal[1] = i;
        if (p.name == "nz") layout.normal[2] = i;
      }
      if (e.name == "face" && p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index")) {
        if (!is_integer(p.type)) throw InputError({path, 0, 0}, "the face's vertex indices must have an integer type");
        layout.indices = i;
      }
    }
    have_vertex |= e.name == "vertex";
    have_face |= e.name == "face";
  }
  if (!have_vertex || layout.x < 0 || layout.y < 0 || layout.z < 0)
    throw InputError({path, 0, 0}, "the PLY header declares no \"vertex\" element with x, y and z properties");
  if (have_face && layout.indices < 0)
    throw InputError({path, 0, 0}, "the PLY \"face\" element has no \"vertex_indices\" list");
  return layout;
}

// Reads values one at a time from a binary body, with bounds checks.
class BinaryCursor {
 public:
  BinaryCursor(std::string_view bytes, size_t offset, bool big_endian, const std::string& path)
      : bytes_(bytes), offset_(offset), big_endian_(big_endian), path_(path) {}

  double value(PlyType type, const char* what) {
    const size_t size = size_of(type);
    if (offset_ + size > bytes_.size())
      throw InputError({path_, 0, 0}, std::string("the file ends in the middle of ") + what);
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + offset_, size);
    offset_ += size;
    if (big_endian_) std::reverse(raw, raw + size);
    switch (type) {
      case PlyType::kInt8: return double(int8_t(raw[0]));
      case PlyType::kUint8: return double(raw[0]);
      case PlyType::kInt16: { int16_t v; std::memcpy(&v, raw, 2); return double(v); }
      case PlyType::kUint16: { uint16_t v; std::memcpy(&v, raw, 2); return double(v); }
      case PlyType::kInt32: { int32_t v; std::memcpy(&v, raw, 4); return double(v); }
      case PlyType::kUint32: { uint32_t v; std::memcpy(&v, raw, 4); return double(v); }
      case PlyType::kFloat32: { float v; std::memcpy(&v, raw, 4); return double(v); }
      case PlyType::kFloat64: { double v; std::memcpy(&v, raw, 8); return v; }
    }
    return 0.0;
  }

 private:
  std::string_view bytes_;
  size_t offset_;
  bool big_endian_;
  const std::string& path_;
};

// Reads values from an ascii body, which is a stream of fields across lines.
class AsciiCursor {
 public:
  explicit AsciiCursor(TextScanner& scanner) : scanner_(scanner) {}

  double value(PlyType type, const char* what) {
    while (scanner_.at_line_end()) {
      if (!scanner_.next_line())
        throw InputError({scanner_.path(), scanner_.line_number(), 0}, std::string("the file ends before ") + what);
    }
    // Any number, nan too: only the coordinates need be finite (read_body
    // says so), as for the binary encodings.
    // The scanner's messages name it after "the": "a list's length" as "list's length".
    const std::string_view article = std::string_view(what).substr(0, std::string_view(what).find(' ') + 1);
    const char* noun = what + (article == "a " || article == "an " ? article.size() : 0);
    return is_integer(type) ? double(scanner_.integer(noun)) : scanner_.any_number(noun);
  }
  int line() const { return scanner_.line_number(); }

 private:
  TextScanner& scanner_;
};

template <typename Cursor>
void read_body(Cursor& cursor, const PlyHeader& header, const PlyLayout& layout, PolygonSoup& soup,
               size_t byte_budget, const std::function<int()>& line_of, std::vector<glm::vec3>& point_normals) {
  for (const PlyElement& e : header.elements) {
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    if (e.properties.empty() && !is_vertex && !is_face) continue;  // nothing to read, however many
    if (is_vertex) soup.points.reserve(std::min<size_t>(e.count, byte_budget));
    for (uint64_t n = 0; n < e.count; ++n) {
      glm::dvec3 p(0.0);
      glm::vec3 colour(1.0f), normal(0.0f);
      int line = 0;
      for (int i = 0; i < int(e.properties.size()); ++i) {
        const PlyProperty& prop = e.properties[size_t(i)];
        if (!prop.is_list) {
          const double v = cursor.value(prop.type, is_vertex ? "a vertex" : "an element");
          if (i == 0) line = line_of();
          if (is_vertex && (i == layout.x || i == layout.y || i == layout.z)) {
            if (!std::isfinite(v))
              throw InputError({soup.path, line, 0}, "vertex " + std::to_string(n) + " has a coordinate that is not a finite number");
            (i == layout.x ? p.x : i == layout.y ? p.y : p.z) = v;
          }
          for (int c = 0; c < 3; ++c)
            if (is_vertex && i == layout.colour[c]) colour[c] = colour_channel(v, prop.type);
            else if (is_vertex && i == layout.normal[c]) normal[c] = std::isfinite(v) ? float(v) : 0.0f;
          continue;
        }
        const double count = cursor.value(prop.count_type, "a list's length");
        if (i == 0) line = line_of();
        if (count < 0 || count > double(byte_budget))
          throw InputError({soup.path, line, 0}, "a list length of " + std::to_string(int64_t(count)) + " is impossible here");
        const bool is_face_list = is_face && i == layout.indices;
        if (is_face_list && count < 3)
          throw InputError({soup.path, line, 0}, "face " + std::to_string(n) + " needs at least 3 vertices, it has " +
                                                     std::to_string(int64_t(count)));
        for (uint64_t k = 0; k < uint64_t(count); ++k) {
          const double index = cursor.value(prop.type, "a list item");
          if (!is_face_list) continue;
          if (index < 0 || index >= double(std::numeric_limits<uint32_t>::max()))
            throw InputError({soup.path, line, 0}, "face " + std::to_string(n) + " has the invalid vertex index " +
                                                       std::to_string(int64_t(index)));
          soup.corners.push_back(uint32_t(index));
        }
      }
      if (is_vertex) {
        soup.add_point(p, line);
        if (layout.has_colour()) soup.point_colors.push_back(colour);
        if (layout.has_normal()) point_normals.push_back(normal);
      }
      if (is_face) soup.end_polygon(line);
    }
  }
}

// Where the line that is "end_header" (give or take spaces) ends, at the last
// byte of its line end (\n, \r\n or a lone \r, as TextScanner reads them)
// or at the end of the bytes; npos when no line is. A comment that mentions
// end_header does not end the header.
size_t end_of_end_header_line(std::string_view bytes) {
  for (size_t start = 0; start < bytes.size();) {
    size_t end = std::min(bytes.find_first_of("\r\n", start), bytes.size());
    std::string_view line = bytes.substr(start, end - start);
    if (end + 1 < bytes.size() && bytes[end] == '\r' && bytes[end + 1] == '\n') ++end;
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
    if (line == "end_header") return end;
    start = end + 1;
  }
  return std::string_view::npos;
}

}  // namespace

PolygonSoup read_ply(std::string_view bytes, const std::string& path) {
  // The header is text whatever the body's encoding; it ends at the line "end_header".
  const size_t header_line_end = end_of_end_header_line(bytes);
  const size_t body = header_line_end == std::string_view::npos ? bytes.size()
                      : header_line_end == bytes.size()          ? std::string_view::npos
                                                                 : header_line_end;
  TextScanner header_scanner(bytes.substr(0, body == std::string_view::npos ? bytes.size() : body), path);
  PolygonSoup soup;
  soup.path = path;
  const PlyHeader header = read_header(header_scanner, soup.warnings);
  const PlyLayout layout = find_layout(header, path);

  std::vector<glm::vec3> point_normals;
  const size_t body_offset = body == std::string_view::npos ? bytes.size() : body + 1;
  const size_t byte_budget = bytes.size() - std::min(bytes.size(), body_offset);
  if (header.encoding == PlyEncoding::kAscii) {
    soup.format = "PLY (ascii)";
    TextScanner scanner(bytes, path);
    for (int i = 0; i < header.body_line; ++i) scanner.next_line();
    while (!scanner.at_line_end()) scanner.field();  // the rest of the "end_header" line
    AsciiCursor cursor(scanner);
    read_body(cursor, header, layout, soup, byte_budget, [&] { return cursor.line(); }, point_normals);
  } else {
    const bool big = header.encoding == PlyEncoding::kBigEndian;
    soup.format = big ? "PLY (binary big endian)" : "PLY (binary little endian)";
    BinaryCursor cursor(bytes, body_offset, big, path);
    read_body(cursor, header, layout, soup, byte_budget, [] { return 0; }, point_normals);
  }
  soup.set_corner_normals_of_points(point_normals);
  return soup;
}

}  // namespace umbra
