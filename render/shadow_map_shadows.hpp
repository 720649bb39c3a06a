#pragma once
// Omnidirectional shadow maps (Williams 1978): per light, a cube map of the
// distances from the light to the nearest surface, which the surface shader
// tests each point against. No stencil and no volumes.

#include <memory>

#include "render/shadow_technique.hpp"

namespace umbra {

class ShadowMap;

class ShadowMapShadows : public ShadowTechnique {
 public:
  explicit ShadowMapShadows(FrameDrawing& drawing);
  ~ShadowMapShadows() override;
  void cast(size_t light) override;
  void limit_to_lit() const override;
  // The map: the direct pass only reads it.
  bool cast_outlives_direct_pass() const override { return true; }
  shaders::ShadowTest shadow_test() const override { return shaders::kShadowMapTest; }

 private:
  FrameDrawing& drawing_;
  std::unique_ptr<ShadowMap> map_;  // made on first use, remade when the plan's size changes
};

}  // namespace umbra
