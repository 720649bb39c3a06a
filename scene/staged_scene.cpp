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
#include "scene/stage_defaults.hpp"
#include "scene/stage_statements.hpp"
#include "scene/up_axis.hpp"

namespace umbra {
namespace {

using namespace stage_defaults;

// The studio's light (FillLight) and floor, chosen so that a face turned from
// the key light is lighter than its shadow on the floor, and a pale model
// stands out from the floor.
const glm::dvec3 kKeyLight(0.55), kHeadlight(0.3), kSky(0.25), kGround(0.22), kFloor(0.55, 0.55, 0.58);
// Behind the floor's horizon, where a low camera sees past it: a studio's pale grey.
const glm::dvec3 kStageBackground(0.8, 0.8, 0.82);
}  // namespace

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
  // A spindly model comes first in its frame, under the default light: one
  // the options neither place (outright or by its angles) nor turn.
  const StageView& given = staging.view;
  const bool light_given = given.light || given.light_azimuth_deg || given.light_elevation_deg || given.light_turn_deg != 0.0 ||
                           given.turning == Turning::kLight;
  if (!light_given &&
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
