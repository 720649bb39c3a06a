#pragma once
// A mesh handed over as arrays, as NumPy and trimesh hold one: an (n, 3)
// array of points and an (m, k) array of faces, k >= 3 corners each. The
// arrays are read where they lie, through their strides, and become a
// polygon soup that the check, the repair and the stage take as they take a
// file's.

#include <cstddef>
#include <string>

#include "mesh/io/polygon_soup.hpp"

namespace umbra {

// A two-dimensional array in memory, described as NumPy describes one: its
// element's kind ('f' floating point, 'i' signed or 'u' unsigned integer)
// and size in bytes, its shape, and the bytes between rows and columns.
struct ArrayView {
  const void* data = nullptr;
  char kind = 'f';
  size_t item_size = 8;
  size_t rows = 0, columns = 0;
  ptrdiff_t row_stride = 0, column_stride = 0;
};

// The soup of `vertices` (n x 3, floating point or integer) and `faces`
// (m x k, k >= 3, integer), named `name` in messages and reports. Throws
// InputError at `name` when either array has another shape or element
// type, a coordinate is not finite, or a face names no vertex ("faces[12, 2]
// is 99, but vertices has 8 rows").
PolygonSoup soup_from_arrays(const ArrayView& vertices, const ArrayView& faces, const std::string& name);

}  // namespace umbra
