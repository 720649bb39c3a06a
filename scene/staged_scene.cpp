#include "scene/staged_scene.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "mesh/input_error.hpp"
#include "mesh/io/mapped_file.hpp"
#include "mesh/io/mesh_format.hpp"
#include "scene/pose_choice.hpp"
#include "scene/scene_parser.hpp"
#include "scene/stage_statements.hpp"
#include "scene/up_axis.hpp"

namespace umbra {
namespace {

// The unit vector from the model's centre toward azimuth and elevation
// (StageView's convention).
glm::dvec3 toward(double azimuth_deg, double elevation_deg) {
  const double a = glm::radians(azimuth_deg), e = glm::radians(elevation_deg);
  return {std::sin(a) * std::cos(e), -std::cos(a) * std::cos(e), std::sin(e)};
}

// The light by default (StageView's defaults for the view): from the front
// and to the left, high up, so that the shadow falls to the back and right.
const glm::dvec3 kToLight = glm::normalize(glm::dvec3(-0.55, -0.5, 1.3));
const double kLightAzimuthDeg = glm::degrees(std::atan2(kToLight.x, -kToLight.y));
const double kLightElevationDeg = glm::degrees(std::asin(kToLight.z));
// The studio's light (FillLight) and floor, chosen so that a face turned from
// the key light is lighter than its shadow on the floor, and a pale model
// stands out from the floor.
const glm::dvec3 kKeyLight(0.55), kHeadlight(0.3), kSky(0.25), kGround(0.22), kFloor(0.55, 0.55, 0.58);
constexpr double kCameraAzimuthDeg = 35.0;  // StageView's default
constexpr double kCameraElevationDeg = 30.0, kLowModelElevationDeg = 60.0;
constexpr double kLightDistance = 4.0;  // from the model's centre; the fitted model's longest side is 2
constexpr double kMargin = 1.2;         // the frame's half-size over the framed points'
// Behind the floor's horizon, where a low camera sees past it: a studio's pale grey.
const glm::dvec3 kStageBackground(0.8, 0.8, 0.82);
// How far from the model's centre a shadow is framed: a point little below
// a low light casts its shadow toward the horizon, which no frame holds.
constexpr double kShadowReach = 8.0;
// A spindly model, which covers under kSpindly of the box it shows the
// camera (a diplodocus's neck and legs, a lamp post), has its shadow framed
// only as far as lets the camera stand kShadowRoom times as far back as
// the model alone needs, under the default light: its shadow, which shows
// more mass than the model does, would leave it small in the frame. A solid
// model keeps its whole shadow in view, and so does a light the user moved.
constexpr double kSpindly = 0.42, kShadowRoom = 1.25;
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

bool is_mesh_file(const std::string& path) {
  return std::filesystem::path(path).extension() != ".scene" && !detect_mesh_format_of_file(path).empty();
}

std::optional<InputError> neither_scene_nor_mesh(const std::string& path) {
  try {
    const MappedFile file(path);
    const std::string_view bytes = file.bytes();
    // No statement at all: nothing to say of it but that, whatever its name.
    if (const std::string blank = blank_content(bytes); !blank.empty()) return InputError({path}, blank, InputProblem::kEmpty);
    if (std::filesystem::path(path).extension() == ".scene" || !detect_mesh_format(bytes, path).empty()) return std::nullopt;
    std::string what = other_known_format(bytes);
    if (what.empty() && !looks_like_text(bytes.substr(0, 1 << 16))) what = "binary data";
    if (what.empty()) return std::nullopt;
    return InputError({path}, "neither a scene nor a mesh file (" + mesh_format_names() + "): " + what, InputProblem::kUnsupportedFormat);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

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
  // Named, not bound: a lambda below reads them, which C++17 allows of
  // variables only.
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

std::string staged_scene_name(const std::string& mesh_path) { return mesh_path + " (staged)"; }

namespace {

// The stage for the mesh at `path`, or for `soup` (named `path`, its own up
// axis `soup_up`) where given.
Scene stage_mesh(const std::string& path, const std::shared_ptr<const PolygonSoup>& soup, const std::string& soup_up,
                 const MeshLoadProgress& progress, std::string* staged, const StagingOptions& staging, const ReadOptions& maps) {
  const std::string& up = staging.up;
  const std::string file_name = std::filesystem::path(path).filename().string();
  // A scene's quoted path holds no double quote and no line break: such a
  // name is loaded as it is, and written into the scene's text with '?' in
  // their place and a comment that says so.
  const bool nameable = file_name.find_first_of("\"\n\r") == std::string::npos;
  std::string written_name = file_name;
  for (char& ch : written_name)
    if (ch == '"' || ch == '\n' || ch == '\r') ch = '?';
  const std::string format_up = soup ? soup_up : up_axis_of_file(path);
  const std::string name = staged_scene_name(path);
  const int mesh_line = 4;
  // The mesh stood on `axis`, and its statement's text: loaded first, as
  // where the floor, light and camera go depends on its box.
  std::string mesh_statement;
  const auto load = [&](const std::string& axis) {
    const UpTurn& turn = up_turn(axis);
    mesh_statement = "mesh \"" + written_name + "\" fit";
    if (turn.degrees != 0) mesh_statement += " rotate " + StageStatements::point(turn.axis) + " " + StageStatements::number(turn.degrees);
    if (staging.plain_model) mesh_statement += " plain";
    if (!nameable) mesh_statement += "  # a scene cannot name this file (a double quote or a line break in its name): rename it";
    MeshStatement statement;
    statement.mesh.path = file_name;
    statement.mesh.fit = true;
    if (turn.degrees != 0) statement.mesh.rotation_axis = turn.axis, statement.mesh.rotation_deg = turn.degrees;  // as its text says
    statement.mesh.plain = staging.plain_model;
    if (!staging.flat) statement.mesh.smooth_deg = StageStatements::written(staging.crease_deg);  // as its text reads back
    if (!staging.crease_given && staging.frame_pixels > 0) statement.mesh.smooth_triangle_limit = staging.frame_pixels;
    statement.mesh.where = {name, mesh_line, 1};
    statement.path_at = {name, mesh_line, 6};
    statement.soup = soup;
    statement.staged = true;
    Scene loaded;
    loaded.path = name;
    loaded.materials.emplace_back().name = "default";
    // What the staged scene's mesh statement says belongs to the file: no
    // line of a scene the user never wrote.
    const std::string about_the_file = "mesh file \"" + path + "\"";
    try {
      load_scene_meshes({std::move(statement)}, loaded, progress, maps);
    } catch (const InputError& e) {
      if (e.where().file != name) throw;
      std::string message = e.message();
      if (message.rfind(about_the_file, 0) == 0) message.erase(0, about_the_file.size() + (message[about_the_file.size()] == ':' ? 2 : 1));
      throw InputError({path}, message, e.problem());
    }
    const Mesh& m = loaded.meshes.at(0);
    if (m.triangles.empty()) throw InputError({path}, "has no faces: there is nothing to show", InputProblem::kNoFaces);
    if (m.smooth_deg) {
      const size_t comment = mesh_statement.find("  #");  // the statement's words come before its comment
      mesh_statement.insert(comment == std::string::npos ? mesh_statement.size() : comment,
                            " smooth " + StageStatements::number(*m.smooth_deg));
    }
    return loaded;
  };
  std::string axis = !up.empty() ? up : format_up;
  Scene loaded = load(axis);
  // Where the format's convention plainly does not read, a better pose, said
  // on the line after the mesh's, as is a mesh drawn flat for its fineness;
  // --up decides outright.
  std::string notes;
  if (up.empty())
    if (const auto better = better_pose(loaded.meshes[0], axis, loaded.materials)) {
      axis = better->up;
      loaded = load(axis);
      notes = "# up is " + axis + ", not " + format_up + " as its format has it: " + better->why + "\n";
    }
  Mesh& mesh = loaded.meshes.at(0);
  if (!staging.flat && !mesh.smooth_deg)
    notes += "# shaded flat: " + std::to_string(mesh.triangles.size()) + " triangles for " + std::to_string(staging.frame_pixels) +
             " pixels are finer than the picture and show no facets (--crease-angle smooths them all the same)\n";
  const std::string header = "# " + written_name + " on its own, as umbra stages a mesh file: fitted into the\n"
                             "# cube [-1,1]^3 with its " + axis + " axis up" + (up.empty() ? " (--up changes it)" : "") +
                             (staging.no_floor ? ", in the air,\n" : ", standing on a floor,\n") +
                             std::string(staging.view == StageView{} ? "# lit from above and to the left, seen from a raised three-quarter view.\n"
                                                          : "# lit and seen from where the command line's options put the light and camera.\n");

  StageView view = staging.view;
  // A flat part is seen by its face, lit on the side the camera sees, not by its edge.
  const bool default_view = !view.camera_azimuth_deg && !view.eye && !view.target && !view.light && !view.light_azimuth_deg &&
                            !view.light_elevation_deg;
  if (const auto turn = view_turn_facing(mesh); turn && default_view) {
    view.camera_azimuth_deg = kCameraAzimuthDeg + *turn;
    view.light_azimuth_deg = kLightAzimuthDeg + *turn;
    view.light_elevation_deg = kLightElevationDeg;
  }
  // A plate lying flat is seen from higher up, so that its face reads.
  if (!view.camera_elevation_deg && !view.eye && lies_low(mesh)) {
    view.camera_elevation_deg = kLowModelElevationDeg;
    notes += "# seen from " + StageStatements::number(kLowModelElevationDeg) + " degrees up, not " +
             StageStatements::number(kCameraElevationDeg) + ": it lies low (its height under a tenth of its footprint's side), so its face reads\n";
  }
  // A spindly model comes first in its frame, under the default light.
  if (!view.light && !view.light_azimuth_deg && !view.light_elevation_deg && view.light_turn_deg == 0.0 &&
      view.turning != Turning::kLight &&
      silhouette_fill(mesh, toward(view.camera_azimuth_deg.value_or(kCameraAzimuthDeg), view.camera_elevation_deg.value_or(kCameraElevationDeg))) <
          kSpindly)
    view.shadow_room = kShadowRoom;
  const Stage stage = stage_for(mesh.bounds_min, mesh.bounds_max, framing_points(mesh), staging.frame_aspect, view);
  if (stage.shadow_cut)
    notes += "# its shadow runs out of the frame: framed whole, it would leave the model small (moving the light frames it whole)\n";
  // A studio's light: the key light casts the one shadow; a headlight and a
  // sky fill the shaded sides so that they keep their shape and stay lighter
  // than the shadow on the floor, and a soft tone curve keeps highlights
  // from flattening at white. Set as values and written as text together,
  // after the header's lines, the mesh's and the notes'.
  Scene scene;
  scene.path = name;
  scene.materials.emplace_back().name = "default";
  const auto lines = [](const std::string& text) { return int(std::count(text.begin(), text.end(), '\n')); };
  StageStatements statements(scene, lines(header) + 1 + lines(notes) + 1);
  statements.light(stage.light, kKeyLight);
  statements.headlight(kHeadlight);
  statements.hemisphere(kSky, kGround);
  statements.soft_tone();
  if (staging.model_color) statements.model_color(*staging.model_color);
  if (!staging.no_floor) {
    statements.floor_material(staging.floor_color.value_or(kFloor), staging.floor_catches_shadow);
    const glm::dvec3& f = stage.floor_centre;
    statements.floor(f.z, f.x, f.y, stage.floor_half_size);
  }
  statements.camera(stage.camera);
  statements.background(staging.background.value_or(Background{kStageBackground, false}));
  if (staging.width > 0) statements.size(staging.width, staging.height);
  statements.antialias(staging.antialias.value_or(kStagedAntialias), staging.antialias_all);
  if (staged) *staged = header + mesh_statement + "\n" + notes + statements.text();
  // The file's own materials follow the stage's; the mesh's indices move with them.
  const int moved = int(scene.materials.size()) - 1;
  scene.materials.insert(scene.materials.end(), loaded.materials.begin() + 1, loaded.materials.end());
  for (int& m : mesh.triangle_materials)
    if (m > 0) m += moved;
  scene.meshes.push_back(std::move(mesh));
  for (Warning& w : loaded.warnings) {
    if (w.where.file == name) w.where = {path};
    scene.warnings.push_back(std::move(w));
  }
  return scene;
}

}  // namespace

Scene parse_scene_or_mesh_file(const std::string& path, const MeshLoadProgress& progress, std::string* staged,
                               const StagingOptions& staging, const ReadOptions& maps) {
  if (is_mesh_file(path)) return stage_mesh(path, nullptr, "", progress, staged, staging, maps);
  if (staged) staged->clear();
  Scene scene = parse_scene_file(path, progress, maps);
  if (staging.view.light_turn_deg != 0.0) rotate_lights_about_z(scene, staging.view.light_turn_deg);
  if (staging.background) scene.background = *staging.background;
  return scene;
}

Scene stage_polygon_soup(std::shared_ptr<const PolygonSoup> soup, std::string* staged, const StagingOptions& staging,
                         const std::string& own_up) {
  const std::string name = soup->path;
  return stage_mesh(name, soup, own_up, {}, staged, staging, ReadOptions::skip());
}

}  // namespace umbra
