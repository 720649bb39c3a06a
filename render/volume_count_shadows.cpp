#include "render/volume_count_shadows.hpp"

#include "render/frame_drawing.hpp"
#include "render/gl.hpp"
#include "render/shaders.hpp"

namespace umbra {
namespace {

void bind_count_texture(unsigned texture) {
  glActiveTexture(GL_TEXTURE0 + shaders::kVolumeCountUnit);
  glBindTexture(GL_TEXTURE_2D, texture);
  glActiveTexture(GL_TEXTURE0 + shaders::kMaterialTextureUnit);
}

}  // namespace

void VolumeCountShadows::cast(size_t light) {
  const LightPlan& lp = drawing_.plan().lights[light];
  bind_count_texture(0);  // not read while it is drawn into
  drawing_.target().bind_count();
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  // z-pass counts the faces in front of the surface (the depth test passes
  // with GL_LESS: front faces +1, back faces -1); z-fail those behind it or
  // level with it (where GL_LESS would fail: back faces +1, front faces -1).
  glDepthFunc(lp.count == DepthCount::kWhereDepthPasses ? GL_LESS : GL_GEQUAL);
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
  drawing_.count_volumes(light, lp.count == DepthCount::kWhereDepthPasses ? 1.0f : -1.0f);
  glDisable(GL_DEPTH_CLAMP);
  baseline_state();
  drawing_.target().bind_colour();
}

// Where the count is zero: the shader reads it.
void VolumeCountShadows::limit_to_lit() const {
  add_light_once_state();
  bind_count_texture(drawing_.target().count_texture());
}

}  // namespace umbra
