#pragma once
// Antialiasing at edges for a GL picture (AntialiasedPixels::kEdges): the
// ray-cast reference's hierarchy over the scene, built on another core while
// the GL draws the one-sample frame, then the frame's edge pixels drawn again
// from exact rays (ray_cast_edge_pixels). The GL's own shadows are exact
// wherever this is used (antialiased_pixels), so the rays' samples are the
// same surfaces, lights and shadows, only more of them.

#include <memory>

#include <tbb/task_group.h>

#include "image/image.hpp"
#include "render/render_plan.hpp"
#include "scene/scene.hpp"

namespace umbra {

class RayCaster;

class EdgeRays {
 public:
  // Starts building the hierarchy over `scene` where `settings` take samples
  // at edges alone, unless `built` is one already built over its surfaces
  // (many views of one scene share one); else does nothing. `scene` must
  // outlive it, its surfaces unchanged.
  EdgeRays(const Scene& scene, const RenderSettings& settings, const RayCaster* built = nullptr);
  ~EdgeRays();
  EdgeRays(const EdgeRays&) = delete;
  EdgeRays& operator=(const EdgeRays&) = delete;

  // `image`, the GL's picture drawn as the settings say, with its edge
  // pixels drawn again (once the hierarchy is built); unchanged where the
  // settings take every sample in the GL's frame.
  void antialias(Image& image);

 private:
  const Scene& scene_;
  int samples_ = 1;  // per side, at edges; 1: none taken here
  const RayCaster* caster_ = nullptr;  // built_, or the one given
  std::unique_ptr<RayCaster> built_;
  tbb::task_group building_;
};

}  // namespace umbra
