#pragma once
// Draws a scene with capped z-fail stencil shadow volumes (Everitt and Kilgard 2002) into the
// current GL context's default framebuffer:
//   1. depth + ambient for every surface;
//   2. per light: clear the stencil; draw that light's volumes with colour and
//      depth writes off, back faces incrementing and front faces decrementing
//      (with wrapping) where the depth test fails (z-fail), or, where the plan
//      says the light may use z-pass, front faces incrementing and back faces
//      decrementing where it passes, without caps; then add the light's
//      diffuse + specular term where the stencil is zero.
// With the shadowmap method, step 2 instead renders the light's cube shadow
// map and the light's pass tests each point against it. With the planar
// method, step 2 marks each receiver plane's visible pixels in the stencil
// and projects every caster onto the plane, leaving 2 where it lands; the
// light's pass skips those pixels.
// When a light has more volumes than one stencil count can hold (the plan's
// stencil batches), each batch is counted on its own and the pixels it
// shadows are marked in the colour buffer's alpha, which the light's pass
// then leaves out.

#include <memory>
#include <vector>

#include "mesh/scene/scene.hpp"
#include "image/image.hpp"
#include "render/render_plan.hpp"

namespace umbra {

class ShaderProgram;
class ShadowMap;
class SurfaceBuffers;
class VolumeBuffer;

class ShadowRenderer {
 public:
  // Requires a current GL 3.3 core context whose default framebuffer is
  // plan.settings.width x height with a stencil buffer.
  ShadowRenderer(const Scene& scene, const RenderPlan& plan);
  ~ShadowRenderer();

  // Draws the frame into the default framebuffer. With show_volumes, every
  // light's volumes are drawn over it translucently, front faces only (the
  // debugging view). The plan's camera and size are read each time.
  void draw(bool show_volumes);
  // Waits until the GL has finished every command so far (for timing).
  void finish() const;
  // The shaded image (RGB): draw, then read it back.
  Image render_image(bool show_volumes);
  // What the last draw left in the framebuffer (RGB).
  Image read_image() const;

  // Light `light`'s shadow mask (grey): kMaskNoSurface where no surface is
  // seen, kMaskLit where the visible point faces the light and is outside its
  // shadow, kMaskUnlit elsewhere.
  Image render_mask(size_t light);

 private:
  void apply_view();
  void depth_and_ambient_pass();
  void count_shadow_volumes(size_t light);
  void direct_light_pass(size_t light);
  void show_volumes_pass();
  void mask_pass();
  void draw_surfaces(int pass, size_t light);
  void draw_volumes(size_t light);
  void draw_stencil_batch(size_t light, size_t batch);
  void draw_mesh_volume(const MeshVolumePlan& m);
  bool mapped() const { return plan_.settings.method == RenderMethod::kShadowMap; }
  bool planar() const { return plan_.settings.method == RenderMethod::kPlanar; }
  void project_onto_receivers(size_t light);
  void mark_receiver(const glm::dvec4& plane);
  void test_stencil_for_light() const;
  void render_shadow_map(size_t light);
  // How far every stencil-free pass must look: light `light`'s shadows.
  void shadow_light(size_t light);
  void mark_shadowed_in_alpha();
  void leave_out_marked_pixels() const;
  Image read_pixels(int channels) const;

  const Scene& scene_;
  const RenderPlan& plan_;
  std::unique_ptr<ShaderProgram> triangle_program_, sphere_program_, volume_program_, planar_program_;
  std::unique_ptr<SurfaceBuffers> surfaces_;
  std::unique_ptr<VolumeBuffer> volumes_;
  std::unique_ptr<ShadowMap> shadow_map_;  // for the shadowmap method, made on first use
  double scene_radius_ = 0.0;             // of a ball round every surface, for the map's near plane
  glm::dvec3 viewpoint_{0.0};             // where the surfaces are drawn from: the eye, or a light for its shadow map
  glm::dvec3 scene_center_{0.0};
  std::vector<std::unique_ptr<VolumeBuffer>> mesh_volumes_;  // per scene mesh; made when first drawn
  bool shadow_marked_in_alpha_ = false;  // the last count_shadow_volumes used batches
};

}  // namespace umbra
