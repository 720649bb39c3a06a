#pragma once
// Shadow volumes counted per pixel (Crow 1977; counted on graphics hardware
// by Heidmann 1991): capped z-fail (Everitt and Kilgard 2002), or uncapped
// z-pass where the plan proves it exact, per light as the plan says (methods
// auto, zfail, zpass, triangles). The count is summed in the frame target's
// 32-bit float count buffer rather than the 8-bit stencil, so that it never
// wraps however many volumes overlap: no bound on a mesh's layers is needed,
// and a light's volumes are counted in one pass however many there are.

#include "render/shadow_technique.hpp"

namespace umbra {

class VolumeCountShadows : public ShadowTechnique {
 public:
  explicit VolumeCountShadows(FrameDrawing& drawing) : drawing_(drawing) {}
  void cast(size_t light) override;
  void limit_to_lit() const override;
  // The count texture: the direct pass only reads it.
  bool cast_outlives_direct_pass() const override { return true; }
  bool draws_volumes() const override { return true; }
  shaders::ShadowTest shadow_test() const override { return shaders::kVolumeCountTest; }

 private:
  FrameDrawing& drawing_;
};

}  // namespace umbra
