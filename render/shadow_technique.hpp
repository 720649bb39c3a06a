#pragma once
// How a light's shadows are made known to its direct pass: one object per
// method, behind this interface. ShadowRenderer draws the depth and ambient
// pass, then for each light asks its technique to cast the light's shadows
// and to limit the direct pass to the pixels they leave lit.
//
//   VolumeCountShadows  (volume_count_shadows.hpp)  auto, zfail, zpass, triangles
//   ShadowMapShadows    (shadow_map_shadows.hpp)    shadowmap
//   PlanarShadows       (planar_shadows.hpp)        planar

#include <cstddef>
#include <memory>

#include "render/render_method.hpp"
#include "render/shaders.hpp"

namespace umbra {

class FrameDrawing;

class ShadowTechnique {
 public:
  virtual ~ShadowTechnique() = default;
  // Light `light`'s shadows, left where the direct pass can read them (the
  // stencil, a bound shadow map, marks in the colour buffer's alpha).
  virtual void cast(size_t light) = 0;
  // The GL state under which the direct pass adds light only where the last
  // cast() left the surface lit; baseline_state() undoes it.
  virtual void limit_to_lit() const = 0;
  // How the surface shader's lit passes test for shadow.
  virtual shaders::ShadowTest shadow_test() const { return shaders::kNoShadowTest; }
  // Whether there are shadow volumes to show (--show-volumes).
  virtual bool draws_volumes() const { return false; }
  // Whether what cast() left stays as it was through the direct pass and a
  // colour clear, so that a mask of the same light, drawn at the same samples
  // over the same depth, need not cast it again.
  virtual bool cast_outlives_direct_pass() const { return false; }
};

// The technique for `method` (not kRaycast, which is the CPU reference).
std::unique_ptr<ShadowTechnique> make_shadow_technique(RenderMethod method, FrameDrawing& drawing);

}  // namespace umbra
