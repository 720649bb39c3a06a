#include "render/shadow_technique.hpp"

#include <stdexcept>

#include "render/planar_shadows.hpp"
#include "render/shadow_map_shadows.hpp"
#include "render/stencil_volume_shadows.hpp"

namespace umbra {

std::unique_ptr<ShadowTechnique> make_shadow_technique(RenderMethod method, FrameDrawing& drawing) {
  switch (method) {
    case RenderMethod::kShadowMap:
      return std::make_unique<ShadowMapShadows>(drawing);
    case RenderMethod::kPlanar:
      return std::make_unique<PlanarShadows>(drawing);
    case RenderMethod::kRaycast:
      throw std::logic_error("the ray-cast reference draws no GL frame");
    default:  // auto, zfail, zpass, triangles: the plan says how each light counts
      return std::make_unique<StencilVolumeShadows>(drawing);
  }
}

}  // namespace umbra
