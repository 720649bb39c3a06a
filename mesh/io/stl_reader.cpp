// STL, binary (80-byte header, triangle count, 50 bytes per triangle) or
// ascii ("solid ... facet normal ... outer loop / vertex x y z / endloop ...").
// STL repeats each point in every triangle that uses it; the check merges
// points that coincide.
#include <atomic>
#include <cmath>
#include <cstring>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "mesh/io/mesh_readers.hpp"
#include "mesh/io/text_scanner.hpp"

namespace umbra {
namespace {

constexpr size_t kBinaryHeaderBytes = 84;
constexpr size_t kBinaryTriangleBytes = 50;
// Some exporters write a few bytes after the last triangle (padding, a colour
// block); fewer than this many are read past with a warning.
constexpr size_t kMaxTrailingBytes = 1024;

float little_endian_float(const char* bytes) {
  uint32_t bits = 0;
  for (int i = 3; i >= 0; --i) bits = (bits << 8) | static_cast<unsigned char>(bytes[i]);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

uint32_t little_endian_u32(const char* bytes) {
  uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = (value << 8) | static_cast<unsigned char>(bytes[i]);
  return value;
}

PolygonSoup read_binary_stl(std::string_view bytes, const std::string& path, uint32_t triangle_count) {
  PolygonSoup soup;
  soup.path = path;
  soup.format = "STL (binary)";
  if (size_t(triangle_count) * 3 > UINT32_MAX)  // corners are numbered in 32 bits
    throw InputError({path, 0, 0}, "too large to read: " + std::to_string(triangle_count) + " triangles (at most 1431655765)");
  soup.points.resize(size_t(triangle_count) * 3);
  soup.corners.resize(size_t(triangle_count) * 3);
  soup.polygon_starts.resize(size_t(triangle_count) + 1);
  // Records have a fixed size: each is read at its place, on every core; the
  // first triangle with a coordinate that is not finite is the one named.
  std::atomic<uint32_t> first_bad{triangle_count};
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, triangle_count, 16384), [&](const tbb::blocked_range<uint32_t>& r) {
    for (uint32_t t = r.begin(); t < r.end(); ++t) {
      const char* record = bytes.data() + kBinaryHeaderBytes + size_t(t) * kBinaryTriangleBytes;
      for (uint32_t k = 0; k < 3; ++k) {
        const char* xyz = record + 12 + 12 * k;  // after the facet normal
        const glm::dvec3 p(little_endian_float(xyz), little_endian_float(xyz + 4), little_endian_float(xyz + 8));
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
          uint32_t seen = first_bad.load();
          while (t < seen && !first_bad.compare_exchange_weak(seen, t)) {}
        }
        soup.points[3 * size_t(t) + k] = p;
        soup.corners[3 * size_t(t) + k] = 3 * t + k;
      }
      soup.polygon_starts[size_t(t) + 1] = 3 * (t + 1);
    }
  });
  if (first_bad < triangle_count)
    throw InputError({path, 0, 0}, "triangle " + std::to_string(first_bad.load()) + " has a vertex coordinate that is not a finite number");
  return soup;
}

PolygonSoup read_ascii_stl(std::string_view text, const std::string& path) {
  PolygonSoup soup;
  soup.path = path;
  soup.format = "STL (ascii)";
  TextScanner scanner(text, path);
  bool in_loop = false;
  uint32_t loop_corners = 0;
  while (scanner.next_line()) {
    const std::string_view keyword = scanner.field();
    if (keyword.empty() || is_word(keyword, "solid") || is_word(keyword, "endsolid") || is_word(keyword, "facet") ||
        is_word(keyword, "endfacet")) {
      continue;
    } else if (is_word(keyword, "outer")) {
      if (in_loop) scanner.fail("\"outer loop\" inside a loop: the previous loop has no \"endloop\"");
      in_loop = true;
      loop_corners = 0;
    } else if (is_word(keyword, "vertex")) {
      if (!in_loop) scanner.fail("\"vertex\" outside an \"outer loop\" ... \"endloop\" block");
      const glm::dvec3 p = scanner.vertex();
      soup.corners.push_back(uint32_t(soup.points.size()));
      soup.add_point(p, scanner.line_number());
      ++loop_corners;
    } else if (is_word(keyword, "endloop")) {
      if (!in_loop) scanner.fail("\"endloop\" without \"outer loop\"");
      if (loop_corners < 3)
        scanner.fail("a facet needs at least 3 vertices, this one has " + std::to_string(loop_corners));
      soup.end_polygon(scanner.line_number());
      in_loop = false;
    } else {
      scanner.fail("expected an ascii STL keyword (solid, facet, outer loop, vertex, endloop, endfacet, endsolid), got " +
                   quote_field(keyword));
    }
  }
  if (in_loop) throw InputError({path, scanner.line_number(), 0}, "the file ends inside a facet (no \"endloop\")");
  return soup;
}

}  // namespace

size_t most_binary_stl_bytes(std::string_view head) {
  return kBinaryHeaderBytes + size_t(little_endian_u32(head.data() + 80)) * kBinaryTriangleBytes + kMaxTrailingBytes - 1;
}

size_t binary_stl_trailing_bytes(std::string_view bytes) {
  if (bytes.size() < kBinaryHeaderBytes) return 0;
  const uint32_t count = little_endian_u32(bytes.data() + 80);
  const size_t needed = kBinaryHeaderBytes + size_t(count) * kBinaryTriangleBytes;
  if (needed == kBinaryHeaderBytes || bytes.size() <= needed || bytes.size() - needed >= kMaxTrailingBytes) return 0;
  // A size that only roughly fits is weak evidence (any binary file's bytes
  // 80-83 may count about as many records as follow): the records must look
  // like STL's too, every number finite and every facet normal of length 0
  // (unset) or about 1.
  for (uint32_t t = 0; t < count; ++t) {
    const char* record = bytes.data() + kBinaryHeaderBytes + size_t(t) * kBinaryTriangleBytes;
    double normal_length_squared = 0.0;
    for (int k = 0; k < 12; ++k) {
      const double value = little_endian_float(record + 4 * k);
      if (!std::isfinite(value)) return 0;
      if (k < 3) normal_length_squared += value * value;
    }
    if (normal_length_squared != 0.0 && std::abs(normal_length_squared - 1.0) > 0.2) return 0;
  }
  return bytes.size() - needed;
}

PolygonSoup read_stl(std::string_view bytes, const std::string& path) {
  if (bytes.size() >= kBinaryHeaderBytes) {
    const uint32_t triangle_count = little_endian_u32(bytes.data() + 80);
    // Many binary files also begin with "solid", so the size decides.
    if (bytes.size() == kBinaryHeaderBytes + size_t(triangle_count) * kBinaryTriangleBytes)
      return read_binary_stl(bytes, path, triangle_count);
  }
  const size_t first = bytes.find_first_not_of(" \t\r\n");
  const size_t trailing = binary_stl_trailing_bytes(bytes);
  if (first != std::string_view::npos && is_word(bytes.substr(first, 5), "solid") && trailing == 0) return read_ascii_stl(bytes, path);
  if (trailing > 0) {
    PolygonSoup soup = read_binary_stl(bytes, path, little_endian_u32(bytes.data() + 80));
    soup.warn(0, std::to_string(trailing) + (trailing == 1 ? " byte" : " bytes") + " after the last of the " +
                     std::to_string(soup.polygon_count()) + " triangles ignored");
    return soup;
  }
  if (bytes.size() >= kBinaryHeaderBytes) {
    const uint32_t triangle_count = little_endian_u32(bytes.data() + 80);
    throw InputError({path, 0, 0}, "not a valid STL file: as binary STL its " + std::to_string(triangle_count) +
                                       " triangles need " +
                                       std::to_string(kBinaryHeaderBytes + size_t(triangle_count) * kBinaryTriangleBytes) +
                                       " bytes but the file has " + std::to_string(bytes.size()) +
                                       ", and it does not begin with \"solid\" as ascii STL does");
  }
  throw InputError({path, 0, 0}, "not a valid STL file: too short for binary STL (" + std::to_string(bytes.size()) +
                                     " bytes) and it does not begin with \"solid\" as ascii STL does");
}

}  // namespace umbra
