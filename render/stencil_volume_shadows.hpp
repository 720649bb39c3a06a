#pragma once
// Shadow volumes counted in the stencil (Heidmann 1991): capped z-fail
// (Everitt and Kilgard 2002), or uncapped z-pass where the plan proves it
// exact, per light as the plan says (methods auto, zfail, zpass, triangles).
// A light whose volumes may count past the stencil's 255 is counted in
// batches; each batch's shadowed pixels are marked in the colour buffer's
// alpha, which the direct pass leaves out.

#include "render/shadow_technique.hpp"

namespace umbra {

class StencilVolumeShadows : public ShadowTechnique {
 public:
  explicit StencilVolumeShadows(FrameDrawing& drawing) : drawing_(drawing) {}
  void cast(size_t light) override;
  void limit_to_lit() const override;
  bool draws_volumes() const override { return true; }

 private:
  void mark_shadowed_in_alpha();

  FrameDrawing& drawing_;
  bool marked_in_alpha_ = false;  // the last cast counted in batches
};

}  // namespace umbra
