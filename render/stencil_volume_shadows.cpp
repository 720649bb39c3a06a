#include "render/stencil_volume_shadows.hpp"

#include "render/frame_drawing.hpp"
#include "render/gl.hpp"
#include "render/shaders.hpp"

namespace umbra {

void StencilVolumeShadows::cast(size_t light) {
  const LightPlan& lp = drawing_.plan().lights[light];
  const size_t batches = lp.stencil_batches.size();
  marked_in_alpha_ = batches > 1;
  if (marked_in_alpha_) {  // nothing is marked yet
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    drawing_.upload_volumes(light);  // batches draw ranges of it
  }
  for (size_t batch = 0; batch < batches; ++batch) {
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_LESS);  // a volume face level with a surface counts as behind it
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xFF);
    // Wrapping keeps counts beyond 255 correct modulo 256.
    if (lp.z_pass) {  // front faces increment, back faces decrement where the depth test passes
      glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_KEEP, GL_INCR_WRAP);
      glStencilOpSeparate(GL_BACK, GL_KEEP, GL_KEEP, GL_DECR_WRAP);
    } else {  // z-fail: back faces increment, front faces decrement where it fails
      glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
      glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
    }
    // A triangle's light cap is the triangle itself: push volumes a few depth
    // units back so the cap reliably counts as behind its own surface, which
    // leaves the surface lit, whatever the rasteriser's rounding.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(0.0f, 4.0f);
    // Edges between two vertices at infinity that cross the plane through the
    // eye (a dark cap of a large triangle reaching behind the camera) would be
    // clipped at the near plane to points with clip w = 0, which the
    // rasteriser cannot place, and the cap goes missing. With depth clamping
    // nothing is clipped at the near or far plane (Everitt and Kilgard 2002
    // offer NV_depth_clamp for the same purpose); what lies in front of the
    // near plane clamps to depth 0, in front of every surface, as it is.
    glEnable(GL_DEPTH_CLAMP);
    if (batches == 1) drawing_.draw_volumes(light);
    else drawing_.draw_stencil_batch(light, batch);
    glDisable(GL_DEPTH_CLAMP);
    baseline_state();
    if (batch + 1 < batches) mark_shadowed_in_alpha();  // the last batch's count stays in the stencil
  }
}

// Alpha = 1 on every visible surface pixel whose stencil count is not zero.
void StencilVolumeShadows::mark_shadowed_in_alpha() {
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  drawing_.draw_surfaces(shaders::kAmbient, 0, false);  // every surface pass writes alpha 1
  baseline_state();
}

// Where the count is zero, and with batches, nowhere an earlier batch marked:
// blending gives marked pixels nothing and leaves alpha as it is. A lit
// fragment raises the count, so that a coplanar face drawn over it later
// (an export's overlapping faces) adds the light a second time nowhere.
void StencilVolumeShadows::limit_to_lit() const {
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glEnable(GL_BLEND);
  if (marked_in_alpha_) glBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ZERO, GL_ONE);
  else glBlendFunc(GL_ONE, GL_ONE);
}

}  // namespace umbra
