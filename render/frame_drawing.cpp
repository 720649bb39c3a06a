#include "render/frame_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <glm/geometric.hpp>

#include "mesh/texture_image.hpp"
#include "scene/camera.hpp"
#include "render/gl.hpp"
#include "render/planar_receivers.hpp"
#include "render/shader_program.hpp"
#include "render/shaders.hpp"
#include "render/surface_buffers.hpp"

namespace umbra {
namespace {

glm::vec3 f(const glm::dvec3& v) { return glm::vec3(v); }

// A triangle shader's source, its smooth shading compiled in where `smooth`
// (some mesh has shading normals).
std::string with_smoothing(const std::string& source, bool smooth) {
  if (!smooth) return source;
  const size_t version_end = source.find('\n') + 1;  // #define goes after #version
  return source.substr(0, version_end) + "#define UMBRA_SMOOTH\n" + source.substr(version_end);
}

std::string fragment_source(const char* main) { return std::string("#version 330 core\n") + shaders::kShading + main; }

// The shader's name for a map's wrap mode is the mode's own value.
static_assert(int(TextureImage::Wrap::kRepeat) == shaders::kWrapRepeat &&
              int(TextureImage::Wrap::kClampToEdge) == shaders::kWrapClampToEdge &&
              int(TextureImage::Wrap::kMirroredRepeat) == shaders::kWrapMirroredRepeat);
int texture_wrap(TextureImage::Wrap wrap) { return int(wrap); }

}  // namespace

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

void add_light_once_state() {
  glClearStencil(0);
  glClear(GL_STENCIL_BUFFER_BIT);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_EQUAL, 0, 0xFF);
  glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
}

FrameDrawing::FrameDrawing(const Scene& scene, const RenderPlan& plan, DrawSending sending)
    : scene_(scene), plan_(plan), pacing_(sending == DrawSending::kPaced ? draw_piece_limit_for_current_gl() : 0) {
  const bool smooth = std::any_of(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return !m.triangle_normals.empty(); });
  triangle_program_ = std::make_unique<ShaderProgram>("triangle", with_smoothing(shaders::kTriangleVertex, smooth),
                                                      with_smoothing(fragment_source(shaders::kTriangleFragmentMain), smooth));
  sphere_program_ = std::make_unique<ShaderProgram>("sphere", shaders::kSphereVertex,
                                                    fragment_source(shaders::kSphereFragmentMain));
  volume_program_ = std::make_unique<ShaderProgram>("volume", shaders::kVolumeVertex, shaders::kVolumeFragment);
  count_program_ = std::make_unique<ShaderProgram>("volume count", shaders::kVolumeVertex, shaders::kVolumeCountFragment);
  planar_program_ = std::make_unique<ShaderProgram>("planar", shaders::kPlanarVertex, shaders::kVolumeFragment);
  surfaces_ = std::make_unique<SurfaceBuffers>(scene);
  volumes_ = std::make_unique<VolumeBuffer>();
  mesh_volumes_.resize(scene.meshes.size());  // made when a plan first casts from the mesh's silhouette

  glm::dvec3 ambient_sum(0.0);
  for (const Light& light : scene.lights) ambient_sum += light.ambient;
  for (ShaderProgram* p : {triangle_program_.get(), sphere_program_.get()}) {
    p->use();
    p->set("ambient_sum", f(ambient_sum));
    p->set("headlight", f(scene.fill.headlight));
    p->set("sky", f(scene.fill.sky));
    p->set("ground", f(scene.fill.ground));
    p->set("sky_up", f(scene.fill.up));
    p->set("shadow_map", int(shaders::kShadowMapUnit));
    p->set("material_texture", int(shaders::kMaterialTextureUnit));  // triangles only
    p->set("volume_count", int(shaders::kVolumeCountUnit));
    p->set("light_codes", int(shaders::kLightCodeUnit));  // triangles only
  }
  const SceneBounds bounds = surface_bounds(scene);
  if (!bounds.empty()) scene_center_ = 0.5 * (bounds.lo + bounds.hi), scene_radius_ = 0.5 * glm::length(bounds.hi - bounds.lo);
}

FrameDrawing::~FrameDrawing() = default;

void FrameDrawing::apply_view(int samples) {
  samples_per_side_ = samples;
  const RenderSettings& s = plan_.settings;
  const glm::dmat4 view_projection = plan_.projection() * plan_.camera.view();
  const int width = s.width * samples_per_side_, height = s.height * samples_per_side_;
  view_from(plan_.camera.eye, view_projection, width, height);
  viewpoint_ = culling_viewpoint();
  for (ShaderProgram* p : {volume_program_.get(), count_program_.get(), planar_program_.get()}) {
    p->use();
    p->set("view_projection", glm::mat4(view_projection));
  }
  target_.bind(width, height);
  glViewport(0, 0, width, height);
}

std::optional<glm::dvec3> FrameDrawing::culling_viewpoint() const {
  const Camera& c = plan_.camera;
  if (!c.orthographic()) return c.eye;
  // An orthographic camera's rays start on its eye's plane: a point behind
  // that plane stands for them all where every surface lies ahead of it;
  // where the plane cuts the surfaces, a ray may start inside a closed
  // mesh, and nothing is culled.
  const glm::dvec3 forward = c.axes().forward;
  const double ahead = glm::dot(scene_center_ - c.eye, forward);
  if (ahead - scene_radius_ > 0.0) return c.eye - forward * (ahead + scene_radius_);
  return std::nullopt;
}

void FrameDrawing::view_from(const glm::dvec3& viewpoint, const glm::dmat4& view_projection, int width, int height) {
  viewpoint_ = viewpoint;
  view_ = {view_projection, width, height};
  const WindowRays rays = window_rays(view_projection, viewpoint, width, height);
  for (ShaderProgram* p : {triangle_program_.get(), sphere_program_.get()}) {
    p->use();
    p->set("view_projection", glm::mat4(view_projection));
    p->set("window_rays", glm::mat3(rays.directions));
    p->set("window_origins", glm::mat3(rays.origins));
  }
}

void FrameDrawing::draw_surfaces(int pass, size_t light, shaders::ShadowTest test) {
  const Light& l = scene_.lights[light];
  const auto set_material = [&](ShaderProgram& p, int index) {
    const Material& m = scene_.materials[size_t(index)];
    p.set("material_ambient", f(m.ambient));
    p.set("material_diffuse", f(m.diffuse));
    p.set("material_specular", f(m.specular));
    p.set("material_shininess", float(m.shininess));
    p.set("material_catcher", int(m.shadow_catcher));
  };
  for (ShaderProgram* p : {triangle_program_.get(), sphere_program_.get()}) {
    p->use();
    p->set("pass", pass);
    p->set("light_position", f(l.position));
    p->set("light_color", f(l.color));
    p->set("shadow_test", int(test));
    p->set("specular_used", int(plan_.specular_used));
    p->set("shadow_map_texel", 2.0f / float(plan_.settings.shadow_map_size));
  }
  triangle_program_->use();
  // Only the lit passes read a triangle's side of the light. Asked for it
  // first there, a moved light's sides are worked out while the GL draws the
  // ambient pass and counts the volumes.
  if (pass == shaders::kDirect || pass == shaders::kMaskLit) surfaces_->use_light(light, l.position);
  for (const SurfaceBuffers::TriangleGroup& group : surfaces_->triangle_groups()) {
    set_material(*triangle_program_, group.material);
    const unsigned texture = surfaces_->material_texture(group.material);
    triangle_program_->set("material_textured", int(texture != 0));
    if (const TextureImage* image = scene_.materials[size_t(group.material)].texture.get())
      triangle_program_->set("material_wrap", glm::ivec2(texture_wrap(image->wrap_u), texture_wrap(image->wrap_v)));
    glActiveTexture(GL_TEXTURE0 + shaders::kMaterialTextureUnit);
    glBindTexture(GL_TEXTURE_2D, texture);
    surfaces_->draw_triangle_group(group, viewpoint_, pacing_);
  }
  sphere_program_->use();
  for (const Sphere& sphere : scene_.spheres) {
    set_material(*sphere_program_, sphere.material);
    sphere_program_->set("sphere_center", f(sphere.center));
    sphere_program_->set("sphere_radius", float(sphere.radius));
    surfaces_->draw_sphere_box();
  }
}

void FrameDrawing::draw_nearest_surfaces(int pass, size_t light, shaders::ShadowTest test) {
  draw_surfaces(pass, light, test);
  std::vector<const SurfaceBuffers::TriangleGroup*> to_ask;
  for (const SurfaceBuffers::TriangleGroup& group : surfaces_->triangle_groups())
    if (surfaces_->culls_on_trust(group, viewpoint_)) to_ask.push_back(&group);
  const auto known = [&](const std::vector<View>& views) { return std::find(views.begin(), views.end(), view_) != views.end(); };
  if (to_ask.empty() || known(views_without_back_faces_)) return;
  GLboolean colour_writes[4], depth_writes = GL_TRUE;
  glGetBooleanv(GL_COLOR_WRITEMASK, colour_writes);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_writes);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glDepthMask(GL_FALSE);
  // Depth alone: on llvmpipe, drawing a mesh's back faces with the
  // triangle shader cost about as much as the pass itself.
  if (!depth_program_) depth_program_ = std::make_unique<ShaderProgram>("depth", shaders::kDepthVertex, shaders::kDepthFragment);
  depth_program_->use();
  depth_program_->set("view_projection", glm::mat4(view_.view_projection));
  for (const SurfaceBuffers::TriangleGroup* group : to_ask) surfaces_->ask_whether_back_faces_show(*group, pacing_);
  glColorMask(colour_writes[0], colour_writes[1], colour_writes[2], colour_writes[3]);
  glDepthMask(depth_writes);
  if (!known(views_asked_)) views_asked_.push_back(view_);
}

bool FrameDrawing::back_faces_showed() {
  const bool shown = surfaces_->back_faces_showed();
  // Clean views are not asked again: the eye's, and a few lights' six.
  if (!shown && views_without_back_faces_.size() + views_asked_.size() <= 64)
    views_without_back_faces_.insert(views_without_back_faces_.end(), views_asked_.begin(), views_asked_.end());
  views_asked_.clear();
  return shown;
}

void FrameDrawing::draw_volumes(size_t light, const glm::vec4& tint) {
  volume_program_->use();
  volume_program_->set("tint", tint);
  draw_light_volumes(light, *volume_program_);
}

void FrameDrawing::count_volumes(size_t light, float front_adds) {
  count_program_->use();
  count_program_->set("front_adds", front_adds);
  draw_light_volumes(light, *count_program_);
}

void FrameDrawing::draw_light_volumes(size_t light, ShaderProgram& program) {
  const LightPlan& lp = plan_.lights[light];
  program.set("light_position", f(scene_.lights[light].position));
  program.set("extruded_w", std::isinf(lp.volume_reach) ? 0.0f : float(1.0 / lp.volume_reach));
  program.set("extrude_from_light", 0);
  volumes_->upload(lp.all_volumes);
  volumes_->draw(pacing_);
  program.set("extrude_from_light", 1);
  for (const MeshVolumePlan& m : lp.mesh_volumes) draw_mesh_volume(m);
}

void FrameDrawing::upload_projected_casters(size_t light) { volumes_->upload(plan_.lights[light].planar.casters); }

// A mesh's volume; for z-pass the plan made it without caps.
void FrameDrawing::draw_mesh_volume(const MeshVolumePlan& m) {
  if (!mesh_volumes_[m.mesh]) {
    mesh_volumes_[m.mesh] = std::make_unique<VolumeBuffer>();
    mesh_volumes_[m.mesh]->upload_mesh_vertices(scene_.meshes[m.mesh].positions);
  }
  mesh_volumes_[m.mesh]->upload_indices(m.volume.buffer.data(), m.volume.count);
  mesh_volumes_[m.mesh]->draw(pacing_);
}

void FrameDrawing::mark_receiver(const glm::dvec4& plane) {
  glDepthFunc(GL_EQUAL);
  triangle_program_->use();
  triangle_program_->set("pass", int(shaders::kMarkReceiver));
  triangle_program_->set("receiver_plane", glm::vec4(plane));
  triangle_program_->set("receiver_tolerance", float(1e-5 * (glm::length(scene_center_) + scene_radius_)));
  for (const SurfaceBuffers::TriangleGroup& group : surfaces_->triangle_groups())
    surfaces_->draw_triangle_group(group, viewpoint_, pacing_);
}

void FrameDrawing::draw_projected_casters(size_t light, const glm::dvec4& plane) {
  const glm::dvec3 position = scene_.lights[light].position;
  const double scale = glm::length(scene_center_) + scene_radius_;
  planar_program_->use();
  planar_program_->set("shadow_matrix", glm::mat4(planar_shadow_matrix(plane, position)));
  planar_program_->set("plane", glm::vec4(plane));
  planar_program_->set("light_height", float(glm::dot(plane, glm::dvec4(position, 1.0))));
  planar_program_->set("plane_offset", float(1e-6 * scale));
  volumes_->draw(pacing_);
}

}  // namespace umbra
