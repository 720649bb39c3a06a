#include "scene/pose_choice.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "scene/up_axis.hpp"

namespace umbra {
namespace {

// A model is flat when its thinnest side is under this share of its longest.
constexpr double kFlat = 0.02;
// A base "at 0" is within this share of the model's longest side of it.
constexpr double kAtZero = 1e-3;
// How much larger a footprint the axis it was built on must give.
constexpr double kBroader = 1.5;

int thinnest(const glm::dvec3& extent) {
  int t = 0;
  for (int k = 1; k < 3; ++k)
    if (extent[k] < extent[t]) t = k;
  return t;
}

bool is_flat(const glm::dvec3& extent) {
  return extent[thinnest(extent)] < kFlat * std::max({extent.x, extent.y, extent.z});
}

// The way a flat model's face turns, in stage coordinates (not of unit
// length), or 0 where nothing tells: its textured faces' (a label's side),
// else, for a model that is one-sided (the area of its faces turned one way
// over a tenth more than the other way), that way; with `by_detail`, else
// the way most of its triangles turn (an engraved or embossed side is cut
// into more of them than a plain one), by a tenth of them or more.
glm::dvec3 face_side(const Mesh& mesh, const std::vector<Material>& materials, bool by_detail) {
  glm::dvec3 textured(0.0), facing(0.0), counted(0.0);
  double area = 0.0;
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& [a, b, c] = mesh.triangles[t];
    const glm::dvec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    const double length = glm::length(n);
    if (!(length > 0.0)) continue;
    facing += n;
    area += length;
    counted += n / length;
    const size_t material = size_t(mesh.material_of(t));
    if (!mesh.triangle_uvs.empty() && material < materials.size() && materials[material].texture) textured += n;
  }
  if (textured != glm::dvec3(0.0)) return textured;
  if (glm::length(facing) > 0.1 * area) return facing;
  if (by_detail && glm::length(counted) > 0.1 * double(mesh.triangles.size())) return counted;
  return glm::dvec3(0.0);
}

}  // namespace

std::optional<PoseChoice> better_pose(const Mesh& mesh, const std::string& format_up, const std::vector<Material>& materials) {
  if (mesh.triangles.empty()) return std::nullopt;
  const glm::dmat3 turn = up_rotation(format_up);
  const glm::dvec3 extent = mesh.bounds_max - mesh.bounds_min;  // on the stage
  if (is_flat(extent)) {
    // It lies flat, its face up. Lying already, it keeps its side up unless
    // its texture or its one side plainly faces down; standing, the side
    // that tells (by detail too), else the side the camera saw.
    const int thin = thinnest(extent);
    const glm::dvec3 side = face_side(mesh, materials, thin != 2);
    glm::dvec3 up(0.0);
    if (thin == 2) {
      if (!(side.z < 0.0)) return std::nullopt;
      up.z = -1.0;
    } else {
      // The default camera (azimuth 35) sees a panel's +x side, or its -y side.
      const double seen = thin == 0 ? 1.0 : -1.0;
      up[thin] = side[thin] > 0.0 ? 1.0 : side[thin] < 0.0 ? -1.0 : seen;
    }
    return PoseChoice{axis_name(glm::transpose(turn) * up),
                      thin == 2 ? "it is flat and lay face down, so it is turned over to show its face"
                                : "it is flat and stood on its edge, so it lies flat, its face up"};
  }
  // Where the file was built standing: its base at 0 along an axis.
  const glm::dvec3 lo = mesh.file_bounds_min, hi = mesh.file_bounds_max, size = hi - lo;
  const double longest = std::max({size.x, size.y, size.z});
  if (!(longest > 0.0)) return std::nullopt;
  const auto base_at_zero = [&](int axis, bool positive) { return std::abs(positive ? lo[axis] : hi[axis]) <= kAtZero * longest; };
  const auto footprint = [&](int axis) { return size[(axis + 1) % 3] * size[(axis + 2) % 3]; };
  const int format_axis = format_up[1] - 'x';
  if (base_at_zero(format_axis, format_up[0] == '+')) return std::nullopt;
  std::optional<std::string> built_on;
  for (int axis = 0; axis < 3; ++axis)
    for (const bool positive : {true, false}) {
      if (axis == format_axis || !base_at_zero(axis, positive) || footprint(axis) < kBroader * footprint(format_axis)) continue;
      if (built_on) return std::nullopt;  // more than one: no plain answer
      built_on = std::string(positive ? "+" : "-") + "xyz"[axis];
    }
  if (!built_on) return std::nullopt;
  const std::string why = "it was built standing on that axis (its base is at 0 along it, not along " + format_up +
                          "), on a footprint at least 1.5 times as large";
  // A panel built on the plane at 0, its face turned away from the rest of
  // it (a label over its backing), stands on its back, its face up: the side
  // its textured faces, or a one-sided model's faces, plainly turn to.
  const glm::dvec3 side = glm::transpose(turn) * face_side(mesh, materials, false);  // in the file's axes
  const int axis = (*built_on)[1] - 'x';
  const double up_sign = (*built_on)[0] == '+' ? 1.0 : -1.0;
  if (side[axis] * up_sign < 0.0 && std::abs(side[axis]) > 0.5 * glm::length(side))
    return PoseChoice{std::string(up_sign > 0.0 ? "-" : "+") + "xyz"[axis], why + ", and stands on its back to show its face"};
  return PoseChoice{*built_on, why};
}

bool lies_low(const Mesh& mesh) {
  const glm::dvec3 extent = mesh.bounds_max - mesh.bounds_min;
  return extent.z < 0.1 * std::min(extent.x, extent.y);
}

double silhouette_fill(const Mesh& mesh, const glm::dvec3& direction) {
  if (mesh.triangles.empty()) return 0.0;
  // Axes across the view: any two perpendicular to it and to each other.
  const glm::dvec3 across = glm::normalize(std::abs(direction.z) < 0.9 ? glm::cross(direction, glm::dvec3(0, 0, 1))
                                                                         : glm::cross(direction, glm::dvec3(1, 0, 0)));
  const glm::dvec3 upward = glm::cross(across, direction);
  const auto seen = [&](uint32_t v) { return glm::dvec2(glm::dot(mesh.positions[v], across), glm::dot(mesh.positions[v], upward)); };
  // Up to 2^16 faces, spread over them: a fine mesh has hundreds to a cell.
  const size_t stride = std::max<size_t>(1, mesh.triangles.size() >> 16);
  glm::dvec2 lo(HUGE_VAL), hi(-HUGE_VAL);
  for (size_t t = 0; t < mesh.triangles.size(); t += stride)
    for (const uint32_t v : mesh.triangles[t]) lo = glm::min(lo, seen(v)), hi = glm::max(hi, seen(v));
  constexpr int kCells = 64;
  const glm::dvec2 cell = (hi - lo) / double(kCells);
  if (!(cell.x > 0.0) || !(cell.y > 0.0)) return 0.0;
  std::vector<uint8_t> covered(kCells * kCells, 0);
  const auto index = [&](const glm::dvec2& p) {
    return size_t(std::clamp(int((p.y - lo.y) / cell.y), 0, kCells - 1) * kCells + std::clamp(int((p.x - lo.x) / cell.x), 0, kCells - 1));
  };
  for (size_t t = 0; t < mesh.triangles.size(); t += stride) {
    const glm::dvec2 p = seen(mesh.triangles[t][0]), q = seen(mesh.triangles[t][1]), r = seen(mesh.triangles[t][2]);
    covered[index((p + q + r) / 3.0)] = 1;
    const double twice = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    if (twice == 0.0) continue;
    const glm::dvec2 box_lo = glm::min(p, glm::min(q, r)), box_hi = glm::max(p, glm::max(q, r));
    for (int j = std::max(0, int((box_lo.y - lo.y) / cell.y - 0.5)); j < kCells && lo.y + (j + 0.5) * cell.y <= box_hi.y; ++j)
      for (int i = std::max(0, int((box_lo.x - lo.x) / cell.x - 0.5)); i < kCells && lo.x + (i + 0.5) * cell.x <= box_hi.x; ++i) {
        const glm::dvec2 o = lo + glm::dvec2(i + 0.5, j + 0.5) * cell;
        const auto side = [&](const glm::dvec2& u, const glm::dvec2& w) { return ((w.x - u.x) * (o.y - u.y) - (w.y - u.y) * (o.x - u.x)) * twice; };
        if (side(p, q) >= 0.0 && side(q, r) >= 0.0 && side(r, p) >= 0.0) covered[size_t(j * kCells + i)] = 1;
      }
  }
  return double(std::count(covered.begin(), covered.end(), 1)) / double(kCells * kCells);
}

std::optional<double> view_turn_facing(const Mesh& mesh) {
  if (mesh.triangles.empty()) return std::nullopt;
  const glm::dvec3 extent = mesh.bounds_max - mesh.bounds_min;
  const int thin = thinnest(extent);
  // The side its faces turn to, by their area: the front of a one-sided
  // panel; and, for a panel at a slant below, its largest face.
  glm::dvec3 facing(0.0), largest(0.0);
  double area = 0.0;
  for (const auto& [a, b, c] : mesh.triangles) {
    const glm::dvec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    facing += n;
    area += glm::length(n);
    if (glm::dot(n, n) > glm::dot(largest, largest)) largest = n;
  }
  // Azimuth 0 looks from -y, 90 from +x.
  if (is_flat(extent)) {
    if (thin == 2) return std::nullopt;
    if (thin == 1) return facing.y > 0.0 ? 180.0 : 0.0;
    return facing.x < 0.0 ? -90.0 : 90.0;
  }
  // A panel at a slant to the stage's axes, flat in a plane of its own (most
  // of its area turned one way, and thin across that plane): the camera
  // turned to the horizontal of the way it faces, as for one along an axis;
  // for one tilted less than 45 degrees from level, of the way its upper
  // side faces, so that the camera, above, looks down onto that side.
  // Its plane's normal: the faces' normals summed, each turned to agree with
  // the largest face's (a panel may hold faces wound both ways), then turned
  // to the side that the faces, wound as they are, face by area.
  glm::dvec3 aligned(0.0);
  for (const auto& [a, b, c] : mesh.triangles) {
    const glm::dvec3 n = glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
    aligned += glm::dot(n, largest) < 0.0 ? -n : n;
  }
  const double length = glm::length(aligned);
  if (!(length > 0.5 * area)) return std::nullopt;
  glm::dvec3 normal = glm::dot(aligned, facing) < 0.0 ? -aligned / length : aligned / length;
  double lo = HUGE_VAL, hi = -HUGE_VAL;
  for (const auto& [a, b, c] : mesh.triangles)
    for (const uint32_t v : {a, b, c}) lo = std::min(lo, glm::dot(mesh.positions[v], normal)), hi = std::max(hi, glm::dot(mesh.positions[v], normal));
  if (!(hi - lo < kFlat * std::max({extent.x, extent.y, extent.z}))) return std::nullopt;
  if (std::abs(normal.z) > std::sqrt(0.5) && normal.z < 0.0) normal = -normal;
  if (std::hypot(normal.x, normal.y) < 1e-3) return std::nullopt;  // level: any side shows it
  return glm::degrees(std::atan2(normal.x, -normal.y));
}

}  // namespace umbra
