#include "tools/picture_drawing.hpp"

#include <tbb/task_group.h>

#include "reference/ray_cast_render.hpp"
#include "render/shadow_renderer.hpp"
#include "tools/command_line.hpp"
#include "tools/edge_rays.hpp"

namespace umbra {

DrawnPicture draw_picture(const Scene& scene, const RenderSettings& settings, const PictureRequest& request,
                          std::optional<HeadlessContext>& context, HeadlessGl gl, const BeforeDrawing& before) {
  if (request.mask && scene.lights.empty()) throw UsageError("a shadow mask is light 1's, and this scene has no light");
  DrawnPicture picture;
  if (settings.method == RenderMethod::kRaycast) {
    if (request.depth) throw UsageError("the depth is the GL's depth buffer, which the ray-cast method does not draw");
    RayCastFrame frame = ray_cast_frame(scene, settings.width, settings.height, settings.antialias, settings.antialiased);
    picture.image = std::move(frame.image);
    if (request.mask) picture.mask = std::move(frame.masks[0]);
    return picture;
  }
  // The plan is made on the other cores while the GL context is set up
  // here; the surfaces' buffers only after it, since the casters' and the
  // buffers' transients together raise a large mesh's peak
  // (docs/performance.md, "Render memory"). (The plan outlives the task
  // making it.)
  RenderPlan plan;
  tbb::task_group planning;
  planning.run([&] { plan = make_render_plan(scene, settings); });
  try {
    if (!context || context->width() != settings.width || context->height() != settings.height)
      context.emplace(settings.width, settings.height, gl);  // the old one gone first
  } catch (...) {
    planning.wait();
    throw;
  }
  planning.wait();
  const CurrentContext current(*context);
  EdgeRays edge_rays(scene, settings);  // its hierarchy built while the GL draws
  ShadowRenderer renderer(scene, plan);
  if (before) before(plan, *context);
  if (request.mask)
    std::tie(picture.image, picture.mask) = renderer.render_image_and_mask(request.show_volumes, 0);
  else
    picture.image = renderer.render_image(request.show_volumes);
  if (request.depth) picture.depth = renderer.view_depth();
  edge_rays.antialias(picture.image);
  return picture;
}

}  // namespace umbra
