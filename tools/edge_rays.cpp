#include "tools/edge_rays.hpp"

#include "reference/ray_cast_render.hpp"
#include "reference/ray_caster.hpp"

namespace umbra {

EdgeRays::EdgeRays(const Scene& scene, const RenderSettings& settings, const RayCaster* built) : scene_(scene) {
  if (settings.antialias == settings.frame_samples()) return;  // the GL's frame takes them all
  samples_ = settings.antialias;
  caster_ = built;
  if (!caster_) building_.run([this] { caster_ = (built_ = std::make_unique<RayCaster>(scene_)).get(); });
}

EdgeRays::~EdgeRays() {
  try {
    building_.wait();
  } catch (...) {  // the picture failed first, and says why; a failed build adds nothing to that
  }
}

void EdgeRays::antialias(Image& image) {
  building_.wait();  // rethrows what the build threw
  if (caster_) ray_cast_edge_pixels(scene_, *caster_, image, samples_);
}

}  // namespace umbra
