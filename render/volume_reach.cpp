#include "render/volume_reach.hpp"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>

namespace umbra {

double volume_reach(const glm::dvec3& light, const SceneBounds& casters, const SceneBounds& region) {
  double reach = std::numeric_limits<double>::infinity();
  if (casters.empty()) return reach;
  for (int axis = 0; axis < 3; ++axis) {
    const double l = light[axis];
    // The light's distance past the casters, and past the region's far face, along this axis.
    if (l > casters.hi[axis]) reach = std::min(reach, (l - region.lo[axis]) / (l - casters.hi[axis]));
    if (l < casters.lo[axis]) reach = std::min(reach, (region.hi[axis] - l) / (casters.lo[axis] - l));
  }
  return kVolumeReachMargin * reach;
}

double finite_volume_reach(const glm::dvec3& light, const SceneBounds& region, double nearest_caster) {
  if (!(nearest_caster > 0.0) || region.empty()) return std::numeric_limits<double>::infinity();
  const glm::dvec3 centre = 0.5 * (region.lo + region.hi);
  const double radius = 0.5 * glm::length(region.hi - region.lo);
  return kVolumeReachMargin * std::max(1.0, (glm::length(light - centre) + radius) / nearest_caster);
}

}  // namespace umbra
