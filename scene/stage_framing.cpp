#include "scene/staged_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "scene/stage_defaults.hpp"
#include "scene/stage_statements.hpp"

namespace umbra {
namespace {

using namespace stage_defaults;

constexpr double kLightDistance = 4.0;  // from the model's centre; the fitted model's longest side is 2
constexpr double kMargin = 1.2;         // the frame's half-size over the framed points'
// How far from the model's centre a shadow is framed: a point little below
// a low light casts its shadow toward the horizon, which no frame holds.
constexpr double kShadowReach = 8.0;
// The steps a motion's framing takes through a whole turn: between two, a
// point turns by at most 5 degrees from one, and moves out from the line
// between them by under 0.4% of its distance from the axis, well inside
// the frame's margin.
constexpr int kFramingTurns = 36;


// Where StageView puts the light round a model centred at `centre`.
glm::dvec3 light_position(const glm::dvec3& centre, const StageView& view) {
  const glm::dvec3 light = view.light.value_or(
      centre + kLightDistance * (view.light_azimuth_deg || view.light_elevation_deg
                                     ? toward(view.light_azimuth_deg.value_or(kLightAzimuthDeg),
                                              view.light_elevation_deg.value_or(kLightElevationDeg))
                                     : kToLight));
  return view.light_turn_deg != 0.0 ? rotated_about_z(light, view.light_turn_deg) : light;
}

// The floor's height: a thousandth below the model's lowest point (the fitted
// model spans 2), so that a face lying on the floor is never coplanar with
// it (which would stripe the picture as the two fight over depth), written
// to a millionth, rounded down.
constexpr double kFloorGap = 1e-3;
double floor_height(double lowest) { return std::floor((lowest - kFloorGap) * 1e6) / 1e6; }

}  // namespace

std::vector<glm::dvec3> framing_points(const Mesh& mesh, size_t most) {
  std::vector<glm::dvec3> points;
  if (mesh.triangles.empty()) return points;
  const size_t stride = std::max<size_t>(1, mesh.triangles.size() / most);
  glm::dvec3 extreme[6];  // lowest and highest x, y and z
  for (glm::dvec3& e : extreme) e = mesh.positions[mesh.triangles[0][0]];
  for (size_t t = 0; t < mesh.triangles.size(); ++t)
    for (const uint32_t v : mesh.triangles[t]) {
      const glm::dvec3& p = mesh.positions[v];
      if (t % stride == 0) points.push_back(p);
      for (int a = 0; a < 3; ++a) {
        if (p[a] < extreme[2 * a][a]) extreme[2 * a] = p;
        if (p[a] > extreme[2 * a + 1][a]) extreme[2 * a + 1] = p;
      }
    }
  if (stride > 1) points.insert(points.end(), std::begin(extreme), std::end(extreme));  // else every corner is in
  return points;
}

Stage stage_for(const glm::dvec3& lo, const glm::dvec3& hi, const std::vector<glm::dvec3>& model_points, double aspect,
                const StageView& view) {
  Stage stage;
  const glm::dvec3 centre = lo / 2.0 + hi / 2.0;
  stage.floor_z = floor_height(lo.z);
  stage.light = light_position(centre, view);
  // What the frame must hold: the model's points and their shadows on the
  // floor, where the light is above the point (else its shadow has no end),
  // the furthest drawn in to `reach` from the model's centre.
  // Under a motion, every frame's: the model turned, or the light, through
  // a whole turn about the z axis in kFramingTurns steps.
  const int turns = view.turning == Turning::kNone ? 1 : kFramingTurns;
  const auto framed_points = [&](double reach, bool shadows) {
    std::vector<glm::dvec3> points;
    for (int turn = 0; turn < turns; ++turn) {
      const double degrees = frame_turn_deg(turn, turns);
      const glm::dvec3 light = view.turning == Turning::kLight ? rotated_about_z(stage.light, degrees) : stage.light;
      for (const glm::dvec3& model_point : model_points) {
        const glm::dvec3 p = view.turning == Turning::kModel ? rotated_about_z(model_point, degrees) : model_point;
        if (turn == 0 || view.turning == Turning::kModel) points.push_back(p);
        if (!shadows || !(light.z > p.z)) continue;
        glm::dvec3 shadow = light + (p - light) * ((light.z - stage.floor_z) / (light.z - p.z));
        const glm::dvec3 out(shadow.x - centre.x, shadow.y - centre.y, 0.0);
        if (glm::length(out) > reach) shadow = glm::dvec3(centre.x, centre.y, stage.floor_z) + out * (reach / glm::length(out));
        points.push_back(shadow);
      }
    }
    if (points.empty()) points = {lo, hi};
    return points;
  };
  const glm::dvec3 back = toward(view.camera_azimuth_deg.value_or(kCameraAzimuthDeg), view.camera_elevation_deg.value_or(kCameraElevationDeg));
  // The camera's axes and lens, wherever along them it comes to stand.
  const Camera lens{back, glm::dvec3(0.0), {0, 0, 1}, view.fov_deg};
  // Named, not bound: a lambda below reads them, which clang before 16
  // (the fuzz build's) refuses of structured bindings.
  const CameraAxes axes = lens.axes();
  const glm::dvec3 right = axes.right, up = axes.up, forward = axes.forward;
  // How far off the axis a point may be, over its depth: up, by the lens,
  // and across, by the lens and the frame's shape.
  const double reach_up = lens.half_height_at_unit_depth() / kMargin, reach_across = reach_up * aspect;
  // Where the camera aims and how far back it stands to hold `points`.
  const auto framing = [&](const std::vector<glm::dvec3>& points) {
    // From the middle of the points' box, which no point's repeats move.
    glm::dvec3 box_lo = points[0], box_hi = points[0];
    for (const glm::dvec3& p : points) box_lo = glm::min(box_lo, p), box_hi = glm::max(box_hi, p);
    glm::dvec3 target = box_lo / 2.0 + box_hi / 2.0;
    double distance = 0.0;
    // The distance at which every point is in the frame; then the target moves
    // to the middle of the points as seen from there, until it stays put.
    for (int pass = 0; pass < 200; ++pass) {
      distance = 0.0;
      for (const glm::dvec3& p : points) {
        const glm::dvec3 q = p - target;
        distance = std::max(distance, std::max(std::abs(glm::dot(q, right)) / reach_across, std::abs(glm::dot(q, up)) / reach_up) -
                                          glm::dot(q, forward));
      }
      double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo, y_lo = x_lo, y_hi = -x_lo;
      for (const glm::dvec3& p : points) {
        const glm::dvec3 q = p - target;
        const double depth = distance + glm::dot(q, forward);
        x_lo = std::min(x_lo, glm::dot(q, right) / depth), x_hi = std::max(x_hi, glm::dot(q, right) / depth);
        y_lo = std::min(y_lo, glm::dot(q, up) / depth), y_hi = std::max(y_hi, glm::dot(q, up) / depth);
      }
      const glm::dvec3 shift = distance * ((x_lo + x_hi) / 2 * right + (y_lo + y_hi) / 2 * up);
      target += shift;
      if (glm::length(shift) < 1e-9 * distance) break;
    }
    return std::pair{target, distance};
  };
  std::vector<glm::dvec3> points = framed_points(kShadowReach, view.frame_shadow);
  auto [target, distance] = framing(points);
  // The model comes first where `shadow_room` is set: where its whole
  // shadow would set the camera back over that many times as far as the
  // model alone does, the shadow is framed only as far from the model's
  // centre as keeps the camera there (the furthest such reach, by bisection).
  if (view.frame_shadow && view.shadow_room > 0.0) {
    const double closest = view.shadow_room * framing(framed_points(0.0, false)).second;
    if (distance > closest) {
      double fits = 0.0, cut = kShadowReach;
      for (int step = 0; step < 20; ++step) {
        const double reach = (fits + cut) / 2.0;
        (framing(framed_points(reach, true)).second <= closest ? fits : cut) = reach;
      }
      points = framed_points(fits, true);
      std::tie(target, distance) = framing(points);
      stage.shadow_cut = true;
    }
  }
  double ortho_height = 0.0;
  if (view.orthographic) {
    // The points' extent across the view, centred; the eye stands where the
    // perspective's would, or further back, behind every point, as an
    // orthographic camera sees only what lies ahead of its eye's plane.
    double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo, y_lo = x_lo, y_hi = -x_lo, behind = 0.0;
    for (const glm::dvec3& p : points) {
      const glm::dvec3 q = p - target;
      x_lo = std::min(x_lo, glm::dot(q, right)), x_hi = std::max(x_hi, glm::dot(q, right));
      y_lo = std::min(y_lo, glm::dot(q, up)), y_hi = std::max(y_hi, glm::dot(q, up));
      behind = std::max(behind, -glm::dot(q, forward));
    }
    target += (x_lo + x_hi) / 2 * right + (y_lo + y_hi) / 2 * up;
    ortho_height = std::max(y_hi - y_lo, (x_hi - x_lo) / aspect) * kMargin / view.camera_zoom;
    distance = std::max(distance, behind + ortho_height);
  } else {
    distance /= view.camera_zoom;
  }
  // An eye or target given outright replaces the framed one; the other keeps
  // its place relative to it.
  const glm::dvec3 aim = view.target.value_or(target);
  const glm::dvec3 eye = view.eye.value_or(aim + distance * back);
  if (view.eye) {
    // As the staged text will hold them, to 6 digits: a given eye may meet
    // the framing's target there, or stand straight above it.
    const glm::dvec3 e = StageStatements::written(eye), a = StageStatements::written(aim);
    const std::string given =
        "--eye " + StageStatements::number(eye.x) + "," + StageStatements::number(eye.y) + "," + StageStatements::number(eye.z);
    if (e == a)
      throw StagingChoiceError(given + " is the point the staged camera looks at (the middle of the model and its shadow): give "
                               "--target as well, or put the eye elsewhere");
    if (glm::length(glm::cross(a - e, glm::dvec3(0, 0, 1))) == 0.0)
      throw StagingChoiceError(given + " is straight above or below the point the staged camera looks at, and the camera keeps +z "
                               "up: give --target as well, or move the eye sideways");
  }
  stage.camera = Camera{eye, aim, {0, 0, 1}, view.fov_deg, ortho_height};
  // Far past every edge of the frame: the floor's horizon is never in view.
  stage.floor_centre = {centre.x, centre.y, stage.floor_z};
  stage.floor_half_size = 20.0 * (view.eye ? std::max(distance, glm::length(eye - centre)) : distance);
  return stage;
}

}  // namespace umbra
