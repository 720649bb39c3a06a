#include "render/shadow_technique.hpp"

#include <stdexcept>

#include "render/planar_shadows.hpp"
#include "render/shadow_map_shadows.hpp"
#include "render/volume_count_shadows.hpp"

namespace umbra {

std::unique_ptr<ShadowTechnique> make_shadow_technique(RenderMethod method, FrameDrawing& drawing) {
  switch (method_pass(method)) {
    case ShadowPass::kCountedVolumes:
      return std::make_unique<VolumeCountShadows>(drawing);
    case ShadowPass::kShadowMap:
      return std::make_unique<ShadowMapShadows>(drawing);
    case ShadowPass::kPlanar:
      return std::make_unique<PlanarShadows>(drawing);
    case ShadowPass::kRayCast:
      break;
  }
  throw std::logic_error("the ray-cast reference draws no GL frame");
}

}  // namespace umbra
