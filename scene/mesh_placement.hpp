#pragma once
// How a mesh statement takes its file's points into the scene: fit, then
// scale, then rotate, then translate (scene-format.md). The loader places
// the points by it, and the defect picture its marks; a view's data and
// cameras go back to the file's coordinates by its inverse.

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace umbra {

struct MeshPlacement {
  glm::dvec3 fit_centre{0.0};
  double scale = 1.0;  // the statement's, times the fit's
  glm::dmat3 rotation{1.0};
  glm::dvec3 translation{0.0};

  glm::dvec3 operator()(const glm::dvec3& file_point) const { return rotation * (scale * (file_point - fit_centre)) + translation; }
  // A file's direction turned into the scene, and a length scaled into it.
  glm::dvec3 direction(const glm::dvec3& file_direction) const { return rotation * file_direction; }
  double length(double file_length) const { return file_length * scale; }
  // Back from the scene to the file: a point, a direction, a length.
  glm::dvec3 file_point(const glm::dvec3& scene_point) const {
    return glm::transpose(rotation) * (scene_point - translation) / scale + fit_centre;
  }
  glm::dvec3 file_direction(const glm::dvec3& scene_direction) const { return glm::transpose(rotation) * scene_direction; }
  double file_length(double scene_length) const { return scene_length / scale; }
};

// `mesh`'s placement, from its statement and, where it is fitted, the box
// of its faces' corners in the file (Mesh::file_bounds_min and max).
MeshPlacement placement_of(const Mesh& mesh);

}  // namespace umbra
