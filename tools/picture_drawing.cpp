#include "tools/picture_drawing.hpp"

#include <algorithm>

#include <tbb/task_group.h>

#include "image/image.hpp"

#include "reference/ray_cast_render.hpp"
#include "render/shadow_renderer.hpp"
#include "tools/command_line.hpp"
#include "tools/edge_rays.hpp"

namespace umbra {
namespace {

// `picture`, drawn over a transparent background, composited over `color`
// (Porter and Duff 1984's "over"): out = colour x alpha + background x (1 - alpha).
Image composited_over(const Image& picture, const glm::dvec3& color) {
  Image out(picture.width, picture.height, 3);
  for (int y = 0; y < picture.height; ++y)
    for (int x = 0; x < picture.width; ++x) {
      const double alpha = picture.at(x, y, 3) / 255.0;
      for (int c = 0; c < 3; ++c)
        out.at(x, y, c) = channel_byte(picture.at(x, y, c) / 255.0 * alpha + color[c] * (1.0 - alpha));
    }
  return out;
}

// Draws `views` pictures of `scene`, each once `place(i)` has put its
// camera where view i's is (the first view's may already be), handing each
// to `each`: the plan made once and updated per view, one renderer whose
// buffers hold the surfaces for all of them.
void draw_each(const Scene& scene, size_t views, const std::function<void(size_t)>& place, const RenderSettings& settings,
               const PictureRequest& request, std::optional<HeadlessContext>& context, HeadlessGl gl,
               const BeforeDrawing& before, const RayCaster* caster, const std::function<void(size_t, DrawnPicture&&)>& each) {
  // A shadow catcher over an opaque background is the transparent picture
  // composited over that colour: a pixel's mean of samples keeps the
  // surfaces apart from what is behind them by coverage alone, so with a
  // tone curve the catcher's darkened background would pass for the
  // background itself, and its shadow be lost. (The scene is copied for it.)
  const bool catches = std::any_of(scene.materials.begin(), scene.materials.end(), [](const Material& m) { return m.shadow_catcher; });
  if (catches && !scene.background.transparent) {
    Scene transparent = scene;
    transparent.background.transparent = true;
    const auto place_both = [&](size_t i) {
      place(i);
      transparent.camera = scene.camera, transparent.lights = scene.lights;
    };
    draw_each(transparent, views, place_both, settings, request, context, gl, before, caster, [&](size_t i, DrawnPicture&& picture) {
      picture.image = composited_over(picture.image, scene.background.color);
      each(i, std::move(picture));
    });
    return;
  }
  if (request.mask && scene.lights.empty()) throw UsageError("a shadow mask is light 1's, and this scene has no light");
  if (settings.method == RenderMethod::kRaycast) {
    if (request.depth) throw UsageError("the depth is the GL's depth buffer, which the ray-cast method does not draw");
    for (size_t i = 0; i < views; ++i) {
      place(i);
      RayCastFrame frame = ray_cast_frame(scene, settings.width, settings.height, settings.antialias, settings.antialiased);
      DrawnPicture picture;
      picture.image = std::move(frame.image);
      if (request.mask) picture.mask = frame.masks[0];
      if (request.every_mask) picture.masks = std::move(frame.masks);
      each(i, std::move(picture));
    }
    return;
  }
  // The plan is made on the other cores while the GL context is set up
  // here; the surfaces' buffers only after it, since the casters' and the
  // buffers' transients together raise a large mesh's peak
  // (docs/performance.md, "Render memory"). (The plan outlives the task
  // making it.)
  place(0);
  std::vector<MeshCaster> meshes;
  RenderPlan plan;
  tbb::task_group planning;
  planning.run([&] {
    meshes = prepare_mesh_casters(scene);
    plan = make_render_plan(scene, meshes, settings);
  });
  try {
    if (!context || context->width() != settings.width || context->height() != settings.height)
      context.emplace(settings.width, settings.height, gl);  // the old one gone first
  } catch (...) {
    planning.wait();
    throw;
  }
  planning.wait();
  const CurrentContext current(*context);
  ShadowRenderer renderer(scene, plan);
  if (before) before(plan, *context);
  for (size_t i = 0; i < views; ++i) {
    if (i > 0) place(i), update_render_plan(scene, meshes, plan);
    EdgeRays edge_rays(scene, settings, caster);  // its hierarchy built while the GL draws
    DrawnPicture picture;
    if (request.mask || (request.every_mask && !scene.lights.empty()))
      std::tie(picture.image, picture.mask) = renderer.render_image_and_mask(request.show_volumes, 0);
    else
      picture.image = renderer.render_image(request.show_volumes);
    if (request.depth) picture.depth = renderer.view_depth();
    if (request.every_mask)
      for (size_t light = 0; light < scene.lights.size(); ++light)
        picture.masks.push_back(light == 0 ? *picture.mask : renderer.render_mask(light));
    if (!request.mask) picture.mask.reset();
    edge_rays.antialias(picture.image);
    each(i, std::move(picture));
  }
}

}  // namespace

DrawnPicture draw_picture(const Scene& scene, const RenderSettings& settings, const PictureRequest& request,
                          std::optional<HeadlessContext>& context, HeadlessGl gl, const BeforeDrawing& before,
                          const RayCaster* caster) {
  DrawnPicture drawn;
  draw_each(scene, 1, [](size_t) {}, settings, request, context, gl, before, caster,
            [&](size_t, DrawnPicture&& picture) { drawn = std::move(picture); });
  return drawn;
}

void draw_pictures(Scene& scene, const std::vector<Shot>& shots, const RenderSettings& settings, const PictureRequest& request,
                   std::optional<HeadlessContext>& context, HeadlessGl gl, const RayCaster* caster,
                   const std::function<void(size_t, DrawnPicture&&)>& each) {
  draw_each(scene, shots.size(), [&](size_t i) { place_shot(scene, shots[i]); }, settings, request, context, gl, {}, caster, each);
}

}  // namespace umbra
