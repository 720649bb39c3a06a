#include "render/planar_shadows.hpp"

#include "render/frame_drawing.hpp"
#include "render/gl.hpp"

namespace umbra {

// Per receiver plane: its visible pixels get stencil 1; the casters,
// projected onto it, turn 1 into 2; its pixels left at 1 go back to 0, so
// that the next plane's casters touch only that plane's pixels.
void PlanarShadows::cast(size_t light) {
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  drawing_.upload_projected_casters(light);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glEnable(GL_STENCIL_TEST);
  for (const glm::dvec4& plane : drawing_.plan().lights[light].planar.receiver_planes) {
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    drawing_.mark_receiver(plane);

    glDisable(GL_DEPTH_TEST);  // the shadow lies in the plane: the stencil alone says where
    glEnable(GL_CLIP_DISTANCE0);
    glEnable(GL_CLIP_DISTANCE1);
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    drawing_.draw_projected_casters(light, plane);
    glDisable(GL_CLIP_DISTANCE0);
    glDisable(GL_CLIP_DISTANCE1);
    glEnable(GL_DEPTH_TEST);

    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
    drawing_.mark_receiver(plane);
  }
  baseline_state();
}

// Anywhere but where a projected caster landed; a lit fragment marks its
// pixel as such, so that a coplanar face over it adds no second light.
void PlanarShadows::limit_to_lit() const {
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NOTEQUAL, 2, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);  // the reference value: 2
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
}

}  // namespace umbra
