#pragma once
// Planar projected shadows (Blinn 1988): per receiver plane (the planes of
// the scene's triangles), its visible pixels are marked in the stencil and
// every caster is projected onto it, leaving 2 where a shadow lands. Spheres
// and meshes receive no shadow.

#include "render/shadow_technique.hpp"

namespace umbra {

class PlanarShadows : public ShadowTechnique {
 public:
  explicit PlanarShadows(FrameDrawing& drawing) : drawing_(drawing) {}
  void cast(size_t light) override;
  void limit_to_lit() const override;

 private:
  FrameDrawing& drawing_;
};

}  // namespace umbra
