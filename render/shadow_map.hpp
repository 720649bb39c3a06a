#pragma once
// An omnidirectional shadow map for a point light (Williams 1978): a cube map whose
// six faces each hold, per texel, the distance from the light to the nearest
// surface seen through it (32-bit float), rendered with a depth buffer into a
// framebuffer object.

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace umbra {

// The view-projection of cube face `face` (GL's order: +x, -x, +y, -y, +z,
// -z) seen from `light`: 90 degrees, square, near plane at `near`, far plane
// at infinity. The texture lookup with direction (P - light) lands on the
// texel this face drew P to.
glm::dmat4 cube_face_view_projection(const glm::dvec3& light, int face, double near);

class ShadowMap {
 public:
  explicit ShadowMap(int size);
  ~ShadowMap();
  ShadowMap(const ShadowMap&) = delete;
  ShadowMap& operator=(const ShadowMap&) = delete;

  int size() const { return size_; }
  // Binds face `face` as the render target with its viewport, cleared to
  // "nothing nearer than very far".
  void begin_face(int face);
  // Binds the default framebuffer again (its viewport is the caller's).
  void end() const;
  // Binds the cube map to texture unit `unit` for sampling.
  void bind(int unit) const;

 private:
  int size_;
  unsigned framebuffer_ = 0, cube_ = 0, depth_ = 0;
};

}  // namespace umbra
