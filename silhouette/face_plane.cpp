#include "silhouette/face_plane.hpp"

#include <algorithm>
#include <limits>

namespace umbra {
namespace {

// A generous bound on the rounding of n . x - offset against the exact
// orient3d(a, b, c, x): n and offset carry a few roundings each of sizes
// |b-a||c-a| and |n||a|, the evaluation a few more of |n||x|. 64 units in the
// last place of those magnitudes covers them all several times over; inside
// the bound the exact predicate decides.
constexpr double kRelativeError = 64.0 * std::numeric_limits<double>::epsilon();

float rounded_up(double x) { return std::nextafter(float(x), std::numeric_limits<float>::infinity()); }

}  // namespace

FacePlane face_plane(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a;
  const glm::dvec3 n = glm::cross(ab, ac);
  const double reach = std::max({glm::length(a), glm::length(b), glm::length(c)});
  const double scale = kRelativeError * glm::length(ab) * glm::length(ac);
  return {n, glm::dot(n, a), rounded_up(scale), rounded_up(scale * reach)};
}

}  // namespace umbra
