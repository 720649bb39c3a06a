#pragma once
// The first stage of the mesh check: what each face of the file is. A face
// that repeats a vertex or duplicates an earlier face is left out of the
// topology (reported once, as what it is); a face whose corners are collinear
// stays in it (a closed mesh needs it) but is reported as degenerate.

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "mesh/io/polygon_soup.hpp"

namespace umbra {

struct FaceClasses {
  std::vector<uint32_t> corners;  // the merged vertex of each corner, face after face as in the soup
  std::vector<uint8_t> repeats_vertex, collinear, duplicate;  // per face
  std::vector<uint32_t> duplicate_of;  // for a duplicate, the first face with its vertices
  bool in_topology(size_t f) const { return !repeats_vertex[f] && !duplicate[f]; }
  bool degenerate(size_t f) const { return repeats_vertex[f] || collinear[f]; }
};

// `corners` is soup.corners mapped to merged vertices, whose positions are
// `positions`; duplicates are found whatever their rotation or orientation.
FaceClasses classify_file_faces(const PolygonSoup& soup, std::vector<uint32_t> corners, const std::vector<glm::dvec3>& positions);

}  // namespace umbra
