#include "render/shadow_map_shadows.hpp"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>

#include "render/frame_drawing.hpp"
#include "render/gl.hpp"
#include "render/shaders.hpp"
#include "render/shadow_map.hpp"

namespace umbra {

ShadowMapShadows::ShadowMapShadows(FrameDrawing& drawing) : drawing_(drawing) {}
ShadowMapShadows::~ShadowMapShadows() = default;

// The six faces from the light, each the surfaces' distances from it, then
// the camera's view again. The near plane is well inside the nearest surface
// for any light outside the casters, at a scale that follows the scene's.
void ShadowMapShadows::cast(size_t light) {
  const int size = drawing_.plan().settings.shadow_map_size;
  if (!map_ || map_->size() != size) map_ = std::make_unique<ShadowMap>(size);
  const glm::dvec3 position = drawing_.scene().lights[light].position;
  const double near = std::max(1e-4 * (glm::length(position - drawing_.scene_center()) + drawing_.scene_radius()),
                               std::numeric_limits<double>::min());
  baseline_state();
  for (int face = 0; face < 6; ++face) {
    map_->begin_face(face);
    drawing_.view_from(position, cube_face_view_projection(position, face, near), size, size);
    drawing_.draw_nearest_surfaces(shaders::kDistance, light, shaders::kNoShadowTest);
  }
  map_->end();
  drawing_.apply_view(drawing_.samples_per_side());  // back to the frame
  map_->bind(shaders::kShadowMapUnit);
}

// Anywhere: the shader compares each point's distance with the map's.
void ShadowMapShadows::limit_to_lit() const { add_light_once_state(); }

}  // namespace umbra
