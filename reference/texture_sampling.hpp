#pragma once
// A texture map sampled as the GL samples it with GL_LINEAR and no mipmaps
// (the OpenGL 3.3 core specification, section 3.8.11): the four texels round
// the point, weighted by its distances from their centres, each texel index
// wrapped by the map's wrap mode.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "mesh/texture_image.hpp"

namespace umbra {

// The map's RGB at texture coordinates `uv` (v down the image), in [0, 1].
glm::dvec3 sample_bilinear(const TextureImage& texture, const glm::dvec2& uv);

}  // namespace umbra
