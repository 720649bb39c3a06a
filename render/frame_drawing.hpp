#pragma once
// What every shadow technique draws with: the shader programs, the scene's
// surface and volume buffers, and the view. ShadowRenderer owns one; each
// technique (stencil volumes, shadow maps, planar projection) borrows it.

#include <memory>
#include <optional>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scene/scene.hpp"
#include "render/draw_pacing.hpp"
#include "render/frame_target.hpp"
#include "render/render_plan.hpp"
#include "render/shaders.hpp"

namespace umbra {

class ShaderProgram;
class SurfaceBuffers;
class VolumeBuffer;

// The GL state every pass starts from and returns to.
void baseline_state();
// A light's direct pass adds its term by blending, and each pixel gets it
// once: a lit fragment raises the (cleared) stencil, so that a coplanar face
// drawn over it later (an export's overlapping faces) adds the light a
// second time nowhere.
void add_light_once_state();

class FrameDrawing {
 public:
  // Requires a current GL 3.3 core context. Draws as `sending` says.
  FrameDrawing(const Scene& scene, const RenderPlan& plan, DrawSending sending);
  ~FrameDrawing();
  FrameDrawing(const FrameDrawing&) = delete;
  FrameDrawing& operator=(const FrameDrawing&) = delete;

  const Scene& scene() const { return scene_; }
  const RenderPlan& plan() const { return plan_; }

  // The plan's camera and image size, read every frame (a viewer moves the
  // camera and resizes the window), with the frame target bound at that size
  // times `samples` per side: the settings' frame_samples for an image, 1
  // for a mask.
  void apply_view(int samples);
  // The samples per side the last apply_view drew with (for a shadow map,
  // which draws elsewhere and comes back, and for reading the frame).
  int samples_per_side() const { return samples_per_side_; }
  // Where apply_view draws: the frame, kept in floating point.
  const FrameTarget& target() const { return target_; }
  FrameTarget& target() { return target_; }
  // Every surface with the shading pass `pass` (shaders.hpp) for light
  // `light`; its lit passes test for shadow as `test` says.
  void draw_surfaces(int pass, size_t light, shaders::ShadowTest test);
  // As draw_surfaces, for a pass that draws the surfaces' depth (the first
  // from a viewpoint); then, where a mesh's back faces were culled on trust
  // (BackFaces::kHiddenUnlessSeen), asks whether one would have shown
  // (SurfaceBuffers::ask_whether_back_faces_show), unless this view was
  // found clean before. The answer waits for back_faces_showed.
  void draw_nearest_surfaces(int pass, size_t light, shaders::ShadowTest test);
  // Whether a back face showed in any view asked about since last time:
  // then those meshes are drawn whole from now on, and the caller draws its
  // picture again. Read once the picture is drawn, the answers cost no wait.
  bool back_faces_showed();
  // The surfaces from another viewpoint: a shadow map's face, drawn into a
  // viewport of width x height.
  void view_from(const glm::dvec3& viewpoint, const glm::dmat4& view_projection, int width, int height);
  // Light `light`'s volumes in the colour `tint` (--show-volumes), with the
  // current state.
  void draw_volumes(size_t light, const glm::vec4& tint);
  // Light `light`'s volumes into the target's count, each front face adding
  // `front_adds` and each back face its opposite, with the current state.
  void count_volumes(size_t light, float front_adds);
  // The visible pixels of the triangles in `plane`, with the current stencil operation.
  void mark_receiver(const glm::dvec4& plane);
  // Sends light `light`'s casters for the planar method to the GL, for
  // draw_projected_casters to draw onto each receiver.
  void upload_projected_casters(size_t light);
  // Light `light`'s projected casters (the planar method), with the current state.
  void draw_projected_casters(size_t light, const glm::dvec4& plane);

  // A ball round every surface: scales for near planes and tolerances.
  const glm::dvec3& scene_center() const { return scene_center_; }
  double scene_radius() const { return scene_radius_; }

 private:
  void draw_light_volumes(size_t light, ShaderProgram& program);
  void draw_mesh_volume(const MeshVolumePlan& m);

  const Scene& scene_;
  const RenderPlan& plan_;
  FrameTarget target_;
  DrawPacing pacing_;  // every draw of surfaces and volumes goes through it
  int samples_per_side_ = 1;
  std::unique_ptr<ShaderProgram> triangle_program_, sphere_program_, volume_program_, count_program_,
      planar_program_;
  std::unique_ptr<ShaderProgram> depth_program_;  // made when draw_nearest_surfaces first asks
  std::unique_ptr<SurfaceBuffers> surfaces_;
  std::unique_ptr<VolumeBuffer> volumes_;
  std::vector<std::unique_ptr<VolumeBuffer>> mesh_volumes_;  // per scene mesh; made when first drawn
  // Where the surfaces are drawn from, for culling back faces
  // (SurfaceBuffers::culls): the eye, or a light for its shadow map.
  std::optional<glm::dvec3> viewpoint_;
  // The camera's: its eye, or an orthographic camera's stand-in behind its eye's plane.
  std::optional<glm::dvec3> culling_viewpoint() const;
  // The view drawn from (view_from), and those from which
  // draw_nearest_surfaces found no back face showing: a still camera asks once.
  struct View {
    glm::dmat4 view_projection{1.0};
    int width = 0, height = 0;
    bool operator==(const View&) const = default;
  };
  View view_;
  std::vector<View> views_asked_, views_without_back_faces_;
  glm::dvec3 scene_center_{0.0};
  double scene_radius_ = 0.0;
};

}  // namespace umbra
