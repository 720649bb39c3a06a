#include "render/shadow_renderer.hpp"

#include <algorithm>
#include <limits>
#include <string>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "mesh/scene/camera_transform.hpp"
#include "render/gl.hpp"
#include "render/planar_receivers.hpp"
#include "render/shader_program.hpp"
#include "render/shaders.hpp"
#include "render/shadow_map.hpp"
#include "render/surface_buffers.hpp"

namespace umbra {
namespace {

glm::vec3 f(const glm::dvec3& v) { return glm::vec3(v); }

std::string fragment_source(const char* main) { return std::string("#version 330 core\n") + shaders::kShading + main; }

// The state every pass starts from and returns to.
void baseline_state() {
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glDisable(GL_POLYGON_OFFSET_FILL);
}

}  // namespace

ShadowRenderer::ShadowRenderer(const Scene& scene, const RenderPlan& plan) : scene_(scene), plan_(plan) {
  triangle_program_ = std::make_unique<ShaderProgram>("triangle", shaders::kTriangleVertex,
                                                      fragment_source(shaders::kTriangleFragmentMain));
  sphere_program_ = std::make_unique<ShaderProgram>("sphere", shaders::kSphereVertex,
                                                    fragment_source(shaders::kSphereFragmentMain));
  volume_program_ = std::make_unique<ShaderProgram>("volume", shaders::kVolumeVertex, shaders::kVolumeFragment);
  planar_program_ = std::make_unique<ShaderProgram>("planar", shaders::kPlanarVertex, shaders::kVolumeFragment);
  surfaces_ = std::make_unique<SurfaceBuffers>(scene);
  volumes_ = std::make_unique<VolumeBuffer>();
  mesh_volumes_.resize(scene.meshes.size());  // made when a plan first casts from the mesh's silhouette

  glm::dvec3 ambient_sum(0.0);
  for (const Light& light : scene.lights) ambient_sum += light.ambient;
  for (ShaderProgram* p : {triangle_program_.get(), sphere_program_.get()}) {
    p->use();
    p->set("ambient_sum", f(ambient_sum));
    p->set("shadow_map", 1);  // texture unit 1
  }

  const SceneBounds bounds = surface_bounds(scene);
  if (!bounds.empty()) scene_center_ = 0.5 * (bounds.lo + bounds.hi), scene_radius_ = 0.5 * glm::length(bounds.hi - bounds.lo);
}

// The plan's camera and image size, read every frame: a viewer moves the
// camera and resizes the window.
void ShadowRenderer::apply_view() {
  const RenderSettings& s = plan_.settings;
  const glm::mat4 view_projection(infinite_perspective(plan_.camera.fovy_deg, double(s.width) / s.height,
                                                       plan_.near_plane) *
                                  view_matrix(plan_.camera));
  viewpoint_ = plan_.camera.eye;
  for (ShaderProgram* p : {triangle_program_.get(), sphere_program_.get()}) {
    p->use();
    p->set("view_projection", view_projection);
    p->set("eye", f(plan_.camera.eye));
  }
  for (ShaderProgram* p : {volume_program_.get(), planar_program_.get()}) {
    p->use();
    p->set("view_projection", view_projection);
  }
  glViewport(0, 0, s.width, s.height);
}

ShadowRenderer::~ShadowRenderer() = default;

void ShadowRenderer::draw_surfaces(int pass, size_t light) {
  const Light& l = scene_.lights[light];
  const auto set_material = [&](ShaderProgram& p, int index) {
    const Material& m = scene_.materials[size_t(index)];
    p.set("material_ambient", f(m.ambient));
    p.set("material_diffuse", f(m.diffuse));
    p.set("material_specular", f(m.specular));
    p.set("material_shininess", float(m.shininess));
  };
  for (ShaderProgram* p : {triangle_program_.get(), sphere_program_.get()}) {
    p->use();
    p->set("pass", pass);
    p->set("light_position", f(l.position));
    p->set("light_color", f(l.color));
    p->set("shadow_map_on", int(mapped()));
    p->set("specular_used", int(plan_.specular_used));
    p->set("shadow_map_texel", 2.0f / float(plan_.settings.shadow_map_size));
  }
  triangle_program_->use();
  for (const SurfaceBuffers::TriangleGroup& group : surfaces_->triangle_groups()) {
    set_material(*triangle_program_, group.material);
    surfaces_->draw_triangle_group(group, viewpoint_);
  }
  sphere_program_->use();
  for (const Sphere& sphere : scene_.spheres) {
    set_material(*sphere_program_, sphere.material);
    sphere_program_->set("sphere_center", f(sphere.center));
    sphere_program_->set("sphere_radius", float(sphere.radius));
    surfaces_->draw_sphere_box();
  }
}

void ShadowRenderer::depth_and_ambient_pass() {
  apply_view();
  baseline_state();
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  draw_surfaces(shaders::kAmbient, 0);
}

void ShadowRenderer::count_shadow_volumes(size_t light) {
  const LightPlan& lp = plan_.lights[light];
  const size_t batches = lp.stencil_batches.size();
  shadow_marked_in_alpha_ = batches > 1;
  if (shadow_marked_in_alpha_) {  // nothing is marked yet
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    volumes_->upload(lp.all_volumes);  // batches draw ranges of it
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
    } else {  // z-fail (Everitt and Kilgard 2002): back faces increment, front faces decrement where it fails
      glStencilOpSeparate(GL_BACK, GL_KEEP, GL_INCR_WRAP, GL_KEEP);
      glStencilOpSeparate(GL_FRONT, GL_KEEP, GL_DECR_WRAP, GL_KEEP);
    }
    // A triangle's light cap is the triangle itself: push volumes a few depth
    // units back so the cap reliably counts as behind its own surface, which
    // leaves the surface lit, whatever the rasteriser's rounding.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(0.0f, 4.0f);
    if (batches == 1) draw_volumes(light);
    else draw_stencil_batch(light, batch);
    baseline_state();
    if (batch + 1 < batches) mark_shadowed_in_alpha();  // the last batch's count stays in the stencil
  }
}

void ShadowRenderer::shadow_light(size_t light) {
  shadow_marked_in_alpha_ = false;
  if (mapped()) render_shadow_map(light);
  else if (planar()) project_onto_receivers(light);
  else count_shadow_volumes(light);
}

// Per receiver plane: its visible pixels get stencil 1; the casters,
// projected onto it, turn 1 into 2; its pixels left at 1 go back to 0, so
// that the next plane's casters touch only that plane's pixels.
void ShadowRenderer::project_onto_receivers(size_t light) {
  const LightPlan& lp = plan_.lights[light];
  const glm::dvec3 position = scene_.lights[light].position;
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  volumes_->upload(lp.all_volumes);
  const double scale = glm::length(scene_center_) + scene_radius_;
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  glEnable(GL_STENCIL_TEST);
  for (const glm::dvec4& plane : lp.receiver_planes) {
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    mark_receiver(plane);

    planar_program_->use();
    planar_program_->set("shadow_matrix", glm::mat4(planar_shadow_matrix(plane, position)));
    planar_program_->set("plane", glm::vec4(plane));
    planar_program_->set("light_height", float(glm::dot(plane, glm::dvec4(position, 1.0))));
    planar_program_->set("plane_offset", float(1e-6 * scale));
    glDisable(GL_DEPTH_TEST);  // the shadow lies in the plane: the stencil alone says where
    glEnable(GL_CLIP_DISTANCE0);
    glEnable(GL_CLIP_DISTANCE1);
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    volumes_->draw();
    glDisable(GL_CLIP_DISTANCE0);
    glDisable(GL_CLIP_DISTANCE1);
    glEnable(GL_DEPTH_TEST);

    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_ZERO);
    mark_receiver(plane);
  }
  baseline_state();
}

// Runs the stencil operation on the visible pixels of the triangles in `plane`.
void ShadowRenderer::mark_receiver(const glm::dvec4& plane) {
  glDepthFunc(GL_EQUAL);
  triangle_program_->use();
  triangle_program_->set("pass", int(shaders::kMarkReceiver));
  triangle_program_->set("receiver_plane", glm::vec4(plane));
  triangle_program_->set("receiver_tolerance", float(1e-5 * (glm::length(scene_center_) + scene_radius_)));
  for (const SurfaceBuffers::TriangleGroup& group : surfaces_->triangle_groups())
    surfaces_->draw_triangle_group(group, viewpoint_);
}

// The six faces from the light, each the surfaces' distances from it, then
// the camera's view again. The near plane is well inside the nearest surface
// for any light outside the casters, at a scale that follows the scene's.
void ShadowRenderer::render_shadow_map(size_t light) {
  if (!shadow_map_ || shadow_map_->size() != plan_.settings.shadow_map_size)
    shadow_map_ = std::make_unique<ShadowMap>(plan_.settings.shadow_map_size);
  const glm::dvec3 position = scene_.lights[light].position;
  const double near =
      std::max(1e-4 * (glm::length(position - scene_center_) + scene_radius_), std::numeric_limits<double>::min());
  baseline_state();
  for (int face = 0; face < 6; ++face) {
    shadow_map_->begin_face(face);
    const glm::mat4 view_projection(cube_face_view_projection(position, face, near));
    viewpoint_ = position;
    for (ShaderProgram* p : {triangle_program_.get(), sphere_program_.get()}) {
      p->use();
      p->set("view_projection", view_projection);
      p->set("eye", f(position));
    }
    draw_surfaces(shaders::kDistance, light);
  }
  shadow_map_->end();
  apply_view();
  shadow_map_->bind(1);
}

// Light `light`'s volumes with the volume program and the current state.
void ShadowRenderer::draw_volumes(size_t light) {
  const LightPlan& lp = plan_.lights[light];
  volume_program_->use();
  volume_program_->set("extrude_from_light", 0);
  volumes_->upload(lp.all_volumes);
  volumes_->draw();
  volume_program_->set("extrude_from_light", 1);
  volume_program_->set("light_position", f(scene_.lights[light].position));
  for (const MeshVolumePlan& m : lp.mesh_volumes) draw_mesh_volume(m);
}

// One batch of a light whose volumes are counted in several: a range of
// all_volumes (already uploaded) and its mesh volumes.
void ShadowRenderer::draw_stencil_batch(size_t light, size_t batch) {
  const LightPlan& lp = plan_.lights[light];
  const StencilBatch& b = lp.stencil_batches[batch];
  volume_program_->use();
  volume_program_->set("extrude_from_light", 0);
  volumes_->draw_triangles(b.first_triangle, b.end_triangle);
  volume_program_->set("extrude_from_light", 1);
  volume_program_->set("light_position", f(scene_.lights[light].position));
  for (const uint32_t m : b.mesh_volumes) draw_mesh_volume(lp.mesh_volumes[m]);
}

// A mesh's volume; for z-pass the plan made it without caps.
void ShadowRenderer::draw_mesh_volume(const MeshVolumePlan& m) {
  if (!mesh_volumes_[m.mesh]) {
    mesh_volumes_[m.mesh] = std::make_unique<VolumeBuffer>();
    mesh_volumes_[m.mesh]->upload_mesh_vertices(scene_.meshes[m.mesh].positions);
  }
  mesh_volumes_[m.mesh]->upload_indices(m.volume.buffer.data(), m.volume.count);
  mesh_volumes_[m.mesh]->draw();
}

// Alpha = 1 on every visible surface pixel whose stencil count is not zero.
void ShadowRenderer::mark_shadowed_in_alpha() {
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_NOTEQUAL, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  draw_surfaces(shaders::kAmbient, 0);  // every surface pass writes alpha 1
  baseline_state();
}

// For a pass that adds light where the stencil is zero: with batches, blend
// so that pixels marked in alpha get nothing, and leave alpha as it is.
void ShadowRenderer::leave_out_marked_pixels() const {
  glEnable(GL_BLEND);
  if (shadow_marked_in_alpha_) glBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ZERO, GL_ONE);
  else glBlendFunc(GL_ONE, GL_ONE);
}

// Where a pass adds light: stencil 0 (no volume), not 2 (no planar
// shadow), or anywhere (the shadow map decides in the shader).
void ShadowRenderer::test_stencil_for_light() const {
  if (mapped()) return;
  glEnable(GL_STENCIL_TEST);
  if (planar()) glStencilFunc(GL_NOTEQUAL, 2, 0xFF);
  else glStencilFunc(GL_EQUAL, 0, 0xFF);
}

void ShadowRenderer::direct_light_pass(size_t light) {
  test_stencil_for_light();
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  leave_out_marked_pixels();
  draw_surfaces(shaders::kDirect, light);
  baseline_state();
}

void ShadowRenderer::show_volumes_pass() {
  if (mapped() || planar()) return;  // no volumes
  static const glm::vec4 tints[] = {{1.0f, 0.85f, 0.1f, 0.3f}, {0.2f, 0.8f, 1.0f, 0.3f}, {1.0f, 0.3f, 0.8f, 0.3f}};
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_CULL_FACE);  // front faces only: a wrongly oriented quad shows as missing
  glCullFace(GL_BACK);
  volume_program_->use();
  for (size_t i = 0; i < plan_.lights.size(); ++i) {
    volume_program_->use();
    volume_program_->set("tint", tints[i % 3]);
    draw_volumes(i);
  }
  baseline_state();
}

void ShadowRenderer::draw(bool show_volumes) {
  depth_and_ambient_pass();
  for (size_t i = 0; i < scene_.lights.size(); ++i) {
    if (!plan_.light_adds_direct[i]) continue;  // adds nothing but its ambient term, already drawn
    shadow_light(i);
    direct_light_pass(i);
  }
  if (show_volumes) show_volumes_pass();
}

Image ShadowRenderer::render_image(bool show_volumes) {
  draw(show_volumes);
  return read_pixels(3);
}

Image ShadowRenderer::read_image() const { return read_pixels(3); }

void ShadowRenderer::finish() const { glFinish(); }

Image ShadowRenderer::render_mask(size_t light) {
  depth_and_ambient_pass();
  shadow_light(light);
  // Every visible surface starts unlit (0), then lit where it faces the light
  // and the stencil count is zero; alpha keeps any batches' marks.
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  glClearColor(kMaskNoSurface / 255.0f, kMaskNoSurface / 255.0f, kMaskNoSurface / 255.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  draw_surfaces(shaders::kMaskSurface, light);
  test_stencil_for_light();
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  leave_out_marked_pixels();  // 1 * 0 + lit, or nothing where marked
  draw_surfaces(shaders::kMaskLit, light);
  baseline_state();
  return read_pixels(1);
}

Image ShadowRenderer::read_pixels(int channels) const {
  const int w = plan_.settings.width, h = plan_.settings.height;
  std::vector<uint8_t> rgba(size_t(w) * h * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  Image image(w, h, channels);
  for (int y = 0; y < h; ++y)  // GL's row 0 is the bottom
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < channels; ++c) image.at(x, y, c) = rgba[(size_t(h - 1 - y) * w + x) * 4 + size_t(c)];
  return image;
}

}  // namespace umbra
