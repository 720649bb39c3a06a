#include "reference/ray_caster.hpp"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "reference/ray_primitives.hpp"

namespace umbra {
namespace {

// One primitive: a sphere, or a triangle's three corners (scene or mesh).
struct Primitive {
  const Sphere* sphere = nullptr;
  const glm::dvec3* corners[3] = {nullptr, nullptr, nullptr};
};

// What a query carries past Embree into the callbacks: the exact ray and the
// nearest exact hit so far. Embree hands back the context it was given.
struct Query {
  RTCIntersectContext context;  // first, so that Query* and its address agree
  glm::dvec3 origin, direction;
  int skip = -1;
  double t_min = 0.0, t_max = std::numeric_limits<double>::infinity();
  double t = std::numeric_limits<double>::infinity();
  int object = -1;
};

std::optional<double> hit(const Primitive& p, const Query& q) {
  if (p.sphere) return hit_sphere(*p.sphere, q.origin, q.direction, q.t_min);
  return hit_triangle(*p.corners[0], *p.corners[1], *p.corners[2], q.origin, q.direction, q.t_min);
}

// A float just above a double, so that Embree's culling keeps every box
// whose exact hit could still be nearer.
float float_above(double v) {
  const float f = float(v);
  return double(f) >= v ? f : std::nextafter(f, std::numeric_limits<float>::infinity());
}
float float_below(double v) {
  const float f = float(v);
  return double(f) <= v ? f : std::nextafter(f, -std::numeric_limits<float>::infinity());
}

}  // namespace

struct RayCaster::Impl {
  const Scene& scene;
  std::vector<Primitive> primitives;  // by object id: spheres, triangles, then each mesh's triangles
  double pad = 0.0;                   // added to every box: more than the float ray's distance from the exact one
  RTCDevice device = nullptr;
  RTCScene bvh = nullptr;

  explicit Impl(const Scene& s) : scene(s) {}
  ~Impl() {
    if (bvh) rtcReleaseScene(bvh);
    if (device) rtcReleaseDevice(device);
  }

  static void bounds(const RTCBoundsFunctionArguments* args) {
    const Impl& self = *static_cast<const Impl*>(args->geometryUserPtr);
    const Primitive& p = self.primitives[args->primID];
    glm::dvec3 lo, hi;
    if (p.sphere) {
      lo = p.sphere->center - p.sphere->radius;
      hi = p.sphere->center + p.sphere->radius;
    } else {
      lo = glm::min(*p.corners[0], glm::min(*p.corners[1], *p.corners[2]));
      hi = glm::max(*p.corners[0], glm::max(*p.corners[1], *p.corners[2]));
    }
    RTCBounds& b = *args->bounds_o;
    b.lower_x = float_below(lo.x - self.pad), b.lower_y = float_below(lo.y - self.pad), b.lower_z = float_below(lo.z - self.pad);
    b.upper_x = float_above(hi.x + self.pad), b.upper_y = float_above(hi.y + self.pad), b.upper_z = float_above(hi.z + self.pad);
  }

  // The exact test for one primitive; true when it is the nearest so far.
  static bool consider(const Impl& self, Query& q, unsigned id) {
    if (int(id) == q.skip) return false;
    const auto t = hit(self.primitives[id], q);
    if (!t || *t >= q.t_max) return false;
    // Ties go to the lower id, as in the brute-force search.
    if (*t > q.t || (*t == q.t && int(id) > q.object)) return false;
    q.t = *t;
    q.object = int(id);
    return true;
  }

  static void intersect(const RTCIntersectFunctionNArguments* args) {
    if (args->valid[0] != -1) return;
    Query& q = *reinterpret_cast<Query*>(args->context);
    if (!consider(*static_cast<const Impl*>(args->geometryUserPtr), q, args->primID)) return;
    RTCRayHit& rh = *reinterpret_cast<RTCRayHit*>(args->rayhit);
    // In units of the float direction, whose length differs from 1 by ~1e-7.
    rh.ray.tfar = std::min(rh.ray.tfar, float_above(q.t * (1.0 + 1e-6)));
    rh.hit.geomID = args->geomID;
    rh.hit.primID = args->primID;
  }

  static void occluded(const RTCOccludedFunctionNArguments* args) {
    if (args->valid[0] != -1) return;
    Query& q = *reinterpret_cast<Query*>(args->context);
    if (consider(*static_cast<const Impl*>(args->geometryUserPtr), q, args->primID))
      reinterpret_cast<RTCRay*>(args->ray)->tfar = -std::numeric_limits<float>::infinity();
  }
};

double RayCaster::farthest_ray_start(const Camera& camera) {
  const glm::dvec3 eye = glm::abs(camera.eye);
  return std::max({eye.x, eye.y, eye.z}) + 64.0 * camera.ortho_height;
}

RayCaster::RayCaster(const Scene& scene, Search search) : impl_(std::make_unique<Impl>(scene)) {
  Impl& m = *impl_;
  double largest = 0.0;  // coordinate, over everything a ray may start from or go to
  const auto grow = [&](const glm::dvec3& p) {
    largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  };
  grow(glm::dvec3(farthest_ray_start(scene.camera)));
  for (const Light& l : scene.lights) grow(l.position);
  for (const Sphere& s : scene.spheres) {
    m.primitives.push_back({&s, {}});
    grow(s.center + s.radius);
    grow(s.center - s.radius);
  }
  for (const Triangle& t : scene.triangles) {
    m.primitives.push_back({nullptr, {&t.a, &t.b, &t.c}});
    for (const glm::dvec3* c : {&t.a, &t.b, &t.c}) grow(*c);
  }
  for (const Mesh& mesh : scene.meshes) {
    for (const auto& t : mesh.triangles)
      m.primitives.push_back({nullptr, {&mesh.positions[t[0]], &mesh.positions[t[1]], &mesh.positions[t[2]]}});
    grow(mesh.bounds_min);
    grow(mesh.bounds_max);
  }
  // A float ray is within a few float roundings (6e-8 relative) of the exact
  // one over the scene's extent; 1e-5 of the largest coordinate is far more.
  m.pad = 1e-5 * largest + std::numeric_limits<double>::min();
  if (search == Search::kBruteForce || (search == Search::kAuto && m.primitives.size() < kHierarchyFrom)) return;

  m.device = rtcNewDevice(nullptr);
  if (!m.device) throw std::runtime_error("Embree could not start (rtcNewDevice failed)");
  m.bvh = rtcNewScene(m.device);
  rtcSetSceneFlags(m.bvh, RTC_SCENE_FLAG_ROBUST);
  if (!m.primitives.empty()) {
    RTCGeometry geometry = rtcNewGeometry(m.device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, unsigned(m.primitives.size()));
    rtcSetGeometryUserData(geometry, &m);
    rtcSetGeometryBoundsFunction(geometry, &Impl::bounds, &m);
    rtcSetGeometryIntersectFunction(geometry, &Impl::intersect);
    rtcSetGeometryOccludedFunction(geometry, &Impl::occluded);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(m.bvh, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(m.bvh);
  if (const RTCError e = rtcGetDeviceError(m.device); e != RTC_ERROR_NONE)
    throw std::runtime_error("Embree failed to build the hierarchy (error " + std::to_string(int(e)) + ")");
}

RayCaster::~RayCaster() = default;

std::optional<RayHit> RayCaster::nearest_hit(const glm::dvec3& origin, const glm::dvec3& direction, int skip,
                                             double t_min) const {
  if (!impl_->bvh) return umbra::nearest_hit(impl_->scene, origin, direction, skip, t_min);
  Query q;
  rtcInitIntersectContext(&q.context);
  q.origin = origin, q.direction = direction, q.skip = skip, q.t_min = t_min;
  RTCRayHit rh{};
  rh.ray.org_x = float(origin.x), rh.ray.org_y = float(origin.y), rh.ray.org_z = float(origin.z);
  rh.ray.dir_x = float(direction.x), rh.ray.dir_y = float(direction.y), rh.ray.dir_z = float(direction.z);
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = ~0u;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(impl_->bvh, &q.context, &rh);
  if (q.object < 0) return std::nullopt;
  const glm::dvec3 p = origin + q.t * direction;
  const Primitive& prim = impl_->primitives[size_t(q.object)];
  const glm::dvec3 normal =
      prim.sphere ? (p - prim.sphere->center) / prim.sphere->radius
                  : glm::normalize(glm::cross(*prim.corners[1] - *prim.corners[0], *prim.corners[2] - *prim.corners[0]));
  return RayHit{q.t, p, normal, q.object, {prim.corners[0], prim.corners[1], prim.corners[2]}};
}

bool RayCaster::shadow_ray_blocked(const glm::dvec3& point, int self, const glm::dvec3& light) const {
  if (!impl_->bvh) return umbra::shadow_ray_blocked(impl_->scene, point, self, light);
  const glm::dvec3 to_light = light - point;
  const double distance = glm::length(to_light);
  Query q;
  rtcInitIntersectContext(&q.context);
  q.origin = point, q.direction = to_light / distance, q.skip = self, q.t_min = shadow_ray_start(point, distance);
  q.t_max = distance;
  RTCRay ray{};
  ray.org_x = float(point.x), ray.org_y = float(point.y), ray.org_z = float(point.z);
  ray.dir_x = float(q.direction.x), ray.dir_y = float(q.direction.y), ray.dir_z = float(q.direction.z);
  ray.tnear = 0.0f;
  ray.tfar = float_above(distance * (1.0 + 1e-6));
  ray.mask = ~0u;
  rtcOccluded1(impl_->bvh, &q.context, &ray);
  return q.object >= 0;
}

}  // namespace umbra
