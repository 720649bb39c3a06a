#pragma once
// How a mesh statement takes its file's points into the scene: fit, then
// scale, then rotate, then translate (scene-format.md). The loader places
// the points by it, and the defect picture its marks.

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace umbra {

struct MeshPlacement {
  glm::dvec3 fit_centre{0.0};
  double scale = 1.0;  // the statement's, times the fit's
  glm::dmat3 rotation{1.0};
  glm::dvec3 translation{0.0};

  glm::dvec3 operator()(const glm::dvec3& file_point) const { return rotation * (scale * (file_point - fit_centre)) + translation; }
};

// `mesh`'s placement, from its statement and, where it is fitted, the box
// of its faces' corners in the file (Mesh::file_bounds_min and max).
MeshPlacement placement_of(const Mesh& mesh);

}  // namespace umbra
