#pragma once
// A view's data passes, from one exact eye ray through each pixel's centre
// (the ray caster's): what a dataset needs beside the picture. Where the ray
// first meets one of the `model`'s triangles, its distance along the view
// axis and the normal it is shaded with; elsewhere (nothing, or a surface
// that is not the model, such as the floor) +infinity and 0.

#include <vector>

#include <glm/vec3.hpp>

#include "scene/scene.hpp"

namespace umbra {

class RayCaster;

struct SurfacePasses {
  int width = 0, height = 0;
  std::vector<float> depth;        // rows from the top: along the view axis, in scene units; +inf off the model
  std::vector<glm::vec3> normal;   // unit, in scene coordinates, on the side the camera sees; 0 off the model
  std::vector<uint8_t> object;     // 255 on the model, 0 off it

  bool on_model(size_t pixel) const { return object[pixel] != 0; }
};

// `model` indexes scene.meshes; `caster` is built over `scene`. The normal is
// the smooth shading normal where the mesh is shaded smooth, else its
// face's, turned to the side the eye sees, as the picture shades it.
SurfacePasses surface_passes(const Scene& scene, const RayCaster& caster, size_t model, int width, int height);

}  // namespace umbra
