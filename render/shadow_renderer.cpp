#include "render/shadow_renderer.hpp"

#include <algorithm>
#include <functional>
#include <limits>
#include <vector>

#include "render/frame_drawing.hpp"
#include "scene/camera.hpp"
#include "image/pixel_mean.hpp"
#include "render/gl.hpp"
#include "render/shaders.hpp"
#include "render/shadow_technique.hpp"

namespace umbra {

ShadowRenderer::ShadowRenderer(const Scene& scene, const RenderPlan& plan, DrawSending sending)
    : plan_(plan), drawing_(std::make_unique<FrameDrawing>(scene, plan, sending)) {}

ShadowRenderer::~ShadowRenderer() = default;

ShadowTechnique& ShadowRenderer::technique() {
  const RenderMethod method = plan_.settings.method;
  if (!technique_ || method_pass(method) != method_pass(technique_method_)) technique_ = make_shadow_technique(method, *drawing_);
  technique_method_ = method;
  return *technique_;
}

void ShadowRenderer::depth_and_ambient_pass(int samples) {
  drawing_->apply_view(samples);
  baseline_state();
  // The background, alpha 0, where nothing is drawn; alpha 1 where a surface
  // is (the ambient pass writes it, the others add none): pixel_mean.hpp.
  const Background& background = drawing_->scene().background;
  const glm::vec4 clear(background_sample(background.color, background.transparent));
  glClearColor(clear.r, clear.g, clear.b, clear.a);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  last_cast_light_.reset();
  drawing_->draw_nearest_surfaces(shaders::kAmbient, 0, technique().shadow_test());
}

void ShadowRenderer::direct_light_pass(size_t light) {
  technique().limit_to_lit();
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  drawing_->draw_surfaces(shaders::kDirect, light, technique().shadow_test());
  baseline_state();
}

void ShadowRenderer::show_volumes_pass() {
  if (!technique().draws_volumes()) return;
  static const glm::vec4 tints[] = {{1.0f, 0.85f, 0.1f, 0.3f}, {0.2f, 0.8f, 1.0f, 0.3f}, {1.0f, 0.3f, 0.8f, 0.3f}};
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);  // the frame's alpha stays its coverage
  glEnable(GL_CULL_FACE);  // front faces only: a wrongly oriented quad shows as missing
  glCullFace(GL_BACK);
  for (size_t i = 0; i < plan_.lights.size(); ++i) drawing_->draw_volumes(i, tints[i % 3]);
  baseline_state();
}

void ShadowRenderer::draw(bool show_volumes, const std::function<void()>& while_first_pass_draws) {
  bool first = true;
  do {  // again, those meshes drawn whole, where a back face culled on trust showed
    depth_and_ambient_pass(plan_.settings.frame_samples());
    glFlush();  // the GL starts on it while the light's passes are prepared (SurfaceBuffers::use_light)
    if (first && while_first_pass_draws) while_first_pass_draws();
    first = false;
    for (size_t i = 0; i < plan_.lights.size(); ++i) {
      if (!plan_.light_adds_direct[i]) continue;  // adds nothing but its ambient term, already drawn
      technique().cast(i);
      last_cast_light_ = i;
      direct_light_pass(i);
    }
    if (show_volumes) show_volumes_pass();
  } while (drawing_->back_faces_showed());
}

void ShadowRenderer::show(unsigned into) const {
  drawing_->target().show(plan_.settings.width, plan_.settings.height, drawing_->scene().tone, nothing_seen(), into);
}

Image ShadowRenderer::read_shown() const {
  return drawing_->target().read_shown(plan_.settings.width, plan_.settings.height, drawing_->scene().tone, nothing_seen());
}

glm::vec3 ShadowRenderer::nothing_seen() const {
  const Background& background = drawing_->scene().background;
  return glm::vec3(background_sample(background.color, background.transparent));
}

Image ShadowRenderer::render_image(bool show_volumes) {
  draw(show_volumes);
  return read_image();
}

Image ShadowRenderer::read_image() const {
  const Scene& scene = drawing_->scene();
  const Background& background = scene.background;
  Image image(plan_.settings.width, plan_.settings.height, background.transparent ? 4 : 3);
  // Only a shadow catcher's samples need resolving: without one, none is spent per sample.
  const auto& materials = drawing_->scene().materials;
  const bool catches = std::any_of(materials.begin(), materials.end(), [](const Material& m) { return m.shadow_catcher; });
  std::function<glm::dvec4(const glm::dvec4&)> resolve;
  if (catches) resolve = [&](const glm::dvec4& sample) { return resolved_sample(sample, background.color, background.transparent); };
  drawing_->target().for_each_pixel_mean(
      drawing_->samples_per_side(), [&](int x, int y, const glm::dvec4& mean) { put_pixel_mean(image, x, y, mean, background.color, scene.tone); }, resolve);
  return image;
}

std::vector<float> ShadowRenderer::read_depth() const { return drawing_->target().read_depth(); }

std::vector<float> ShadowRenderer::view_depth() {
  if (drawing_->samples_per_side() != 1) do {
      depth_and_ambient_pass(1);
    } while (drawing_->back_faces_showed());
  const std::vector<float> window = read_depth();
  const RenderSettings& s = plan_.settings;
  const glm::dmat4 projection = plan_.projection();
  std::vector<float> depth(window.size());
  const int w = s.width, h = s.height;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)  // the GL's row 0 is the bottom
      depth[size_t(y) * size_t(w) + size_t(x)] = float(view_depth_of_window_depth(projection, window[size_t(h - 1 - y) * size_t(w) + size_t(x)]));
  return depth;
}

void ShadowRenderer::finish() const { glFinish(); }

Image ShadowRenderer::render_mask(size_t light) {
  do {
    depth_and_ambient_pass(1);  // one sample, at the pixel's centre
    technique().cast(light);
    mask_passes(light);
  } while (drawing_->back_faces_showed());
  return read_mask();
}

std::pair<Image, Image> ShadowRenderer::render_image_and_mask(bool show_volumes, size_t light) {
  Image image = render_image(show_volumes);
  if (drawing_->samples_per_side() != 1 || last_cast_light_ != light || !technique().cast_outlives_direct_pass())
    return {std::move(image), render_mask(light)};
  mask_passes(light);
  return {std::move(image), read_mask()};
}

void ShadowRenderer::mask_passes(size_t light) {
  // Every pixel starts unlit, then a visible surface turns lit where it faces
  // the light and its technique says it is lit; read_mask marks the pixels
  // no surface was drawn into.
  glClearColor(kMaskUnlit / 255.0f, kMaskUnlit / 255.0f, kMaskUnlit / 255.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  technique().limit_to_lit();  // unlit + lit
  drawing_->draw_surfaces(shaders::kMaskLit, light, technique().shadow_test());
  baseline_state();
}

// The pixels without a surface come from the depth buffer, not from a pass
// over every surface: on llvmpipe that pass cost 0.1 s of the engine's 0.8 s
// with --mask at one sample (docs/performance.md).
Image ShadowRenderer::read_mask() const {
  Image mask(plan_.settings.width, plan_.settings.height, 1);
  drawing_->target().for_each_pixel_mean(1, [&](int x, int y, const glm::dvec4& mean) { mask.at(x, y) = channel_byte(mean.r); });
  const std::vector<uint8_t> covered = drawing_->target().read_covered();
  const int w = mask.width, h = mask.height;
  for (int y = 0; y < h; ++y)  // GL's row 0 is the bottom
    for (int x = 0; x < w; ++x)
      if (!covered[size_t(h - 1 - y) * size_t(w) + size_t(x)]) mask.at(x, y) = kMaskNoSurface;
  return mask;
}

}  // namespace umbra
