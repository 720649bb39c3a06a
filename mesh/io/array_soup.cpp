#include "mesh/io/array_soup.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "mesh/input_error.hpp"

namespace umbra {
namespace {

// Element (row, column) of `a` as T.
template <typename T>
T element(const ArrayView& a, size_t row, size_t column) {
  const auto* bytes = static_cast<const unsigned char*>(a.data) + ptrdiff_t(row) * a.row_stride + ptrdiff_t(column) * a.column_stride;
  T value;
  std::memcpy(&value, bytes, sizeof(T));  // strides need not keep elements aligned
  return value;
}

// Calls `f` with a value of the C++ type that `a`'s elements are, or
// returns false when there is none.
template <typename F>
bool with_element_type(const ArrayView& a, F&& f) {
  switch (a.kind * 16 + int(a.item_size)) {
    case 'f' * 16 + 4: f(float()); return true;
    case 'f' * 16 + 8: f(double()); return true;
    case 'i' * 16 + 1: f(int8_t()); return true;
    case 'i' * 16 + 2: f(int16_t()); return true;
    case 'i' * 16 + 4: f(int32_t()); return true;
    case 'i' * 16 + 8: f(int64_t()); return true;
    case 'u' * 16 + 1: f(uint8_t()); return true;
    case 'u' * 16 + 2: f(uint16_t()); return true;
    case 'u' * 16 + 4: f(uint32_t()); return true;
    case 'u' * 16 + 8: f(uint64_t()); return true;
    default: return false;
  }
}

std::string type_name(const ArrayView& a) {
  const char* kind = a.kind == 'f' ? "float" : a.kind == 'i' ? "int" : a.kind == 'u' ? "uint" : nullptr;
  return kind ? kind + std::to_string(a.item_size * 8) : std::string("'") + a.kind + "' elements";
}

std::string shape_text(const ArrayView& a) { return "(" + std::to_string(a.rows) + ", " + std::to_string(a.columns) + ")"; }

}  // namespace

PolygonSoup soup_from_arrays(const ArrayView& vertices, const ArrayView& faces, const std::string& name) {
  const auto fail = [&](const std::string& message) { throw InputError({name}, message); };
  if (vertices.columns != 3) fail("vertices must be an (n, 3) array of points, got shape " + shape_text(vertices));
  if (faces.columns < 3 && !(faces.rows == 0)) fail("faces must be an (m, 3) array of vertex indices (or (m, k), k >= 3), got shape " + shape_text(faces));
  if (vertices.rows > std::numeric_limits<uint32_t>::max()) fail("more vertices than umbra indexes (2^32 - 1)");
  if (faces.rows * faces.columns > std::numeric_limits<uint32_t>::max()) fail("more face corners than umbra indexes (2^32 - 1)");
  if (faces.kind != 'i' && faces.kind != 'u') fail("faces must hold integers (vertex indices), got " + type_name(faces));
  PolygonSoup soup;
  soup.path = name;
  soup.format = "arrays (" + type_name(vertices) + " vertices, " + type_name(faces) + " faces)";
  soup.points.resize(vertices.rows);
  const bool known_points = with_element_type(vertices, [&](auto zero) {
    using T = decltype(zero);
    for (size_t i = 0; i < vertices.rows; ++i)
      for (size_t c = 0; c < 3; ++c) {
        const double v = double(element<T>(vertices, i, c));
        if (!std::isfinite(v))
          fail("vertices[" + std::to_string(i) + ", " + std::to_string(c) + "] is " + (std::isnan(v) ? "NaN" : "infinite") +
               ": every coordinate must be a finite number");
        soup.points[i][int(c)] = v;
      }
  });
  if (!known_points) fail("vertices must hold numbers, got " + type_name(vertices));
  const size_t k = faces.columns;
  soup.corners.resize(faces.rows * k);
  soup.polygon_starts.resize(faces.rows + 1);
  with_element_type(faces, [&](auto zero) {
    using T = decltype(zero);
    for (size_t f = 0; f < faces.rows; ++f) {
      for (size_t c = 0; c < k; ++c) {
        const T index = element<T>(faces, f, c);
        // Compared as signed or unsigned as it is, so that -1 is not read as a huge index.
        const bool negative = std::numeric_limits<T>::is_signed && index < T(0);
        if (negative || uint64_t(index) >= vertices.rows)
          fail("faces[" + std::to_string(f) + ", " + std::to_string(c) + "] is " +
               (negative ? std::to_string(int64_t(index)) : std::to_string(uint64_t(index))) +
               ", but vertices has " + std::to_string(vertices.rows) + " rows: a face's corners index the vertices, from 0");
        soup.corners[f * k + c] = uint32_t(index);
      }
      soup.polygon_starts[f + 1] = uint32_t((f + 1) * k);
    }
  });
  return soup;
}

}  // namespace umbra
