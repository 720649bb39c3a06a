#pragma once
// One picture of a scene as `umbra render` draws it, in memory: the GL's
// frame with its edges antialiased by exact rays (edge_rays.hpp), or the
// ray-cast reference's; and, where asked, light 1's shadow mask and the
// view depth. The command, its batches and the Python module all draw
// through this.

#include <functional>
#include <optional>
#include <vector>

#include "image/image.hpp"
#include "render/headless_context.hpp"
#include "render/render_plan.hpp"
#include "scene/motion.hpp"
#include "scene/scene.hpp"

namespace umbra {

class RayCaster;

struct PictureRequest {
  bool show_volumes = false;  // the volumes drawn over the picture (--show-volumes)
  bool mask = false;          // light 1's shadow mask too (ShadowRenderer::render_mask)
  bool depth = false;         // the view depth too (ShadowRenderer::view_depth): the GL's methods only
  bool every_mask = false;    // every light's shadow mask, in DrawnPicture::masks
};

struct DrawnPicture {
  Image image;
  std::optional<Image> mask;
  std::vector<Image> masks;  // per light, where every_mask asks
  std::vector<float> depth;  // rows from the top; empty unless asked
};

// Called with the plan once it is made and the context is current, before
// anything is drawn (--explain prints the plan there). Not called for the
// ray-cast method, which has neither.
using BeforeDrawing = std::function<void(const RenderPlan&, const HeadlessContext&)>;

// `scene` drawn as `settings` say (their samples as set_picture_samples
// leaves them). For the GL's methods the context is made on `gl` on first
// use, or again for another picture size, while the plan is made on the
// other cores, and kept in `context` for the next picture; `caster`, where
// given, is a ray hierarchy already built over the scene's surfaces, for
// the edges' rays (many views of one scene share one); it is current on
// the calling thread while this draws, and released after. Throws
// UsageError for depth with the ray-cast method, and for a mask of a scene
// without a light.
DrawnPicture draw_picture(const Scene& scene, const RenderSettings& settings, const PictureRequest& request,
                          std::optional<HeadlessContext>& context, HeadlessGl gl, const BeforeDrawing& before = {},
                          const RayCaster* caster = nullptr);

// Many views of one scene, its camera and lights put where each of `shots`
// puts them in turn (and left at the last), each handed to `each` as it is
// drawn: as draw_picture draws each, but with the plan made once and
// updated per view and one renderer, whose buffers hold the surfaces for
// all of them.
void draw_pictures(Scene& scene, const std::vector<Shot>& shots, const RenderSettings& settings, const PictureRequest& request,
                   std::optional<HeadlessContext>& context, HeadlessGl gl, const RayCaster* caster,
                   const std::function<void(size_t, DrawnPicture&&)>& each);

}  // namespace umbra
