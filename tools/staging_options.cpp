#include "tools/staging_options.hpp"

#include <cmath>
#include <functional>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "scene/scene_text.hpp"
#include "scene/stage_defaults.hpp"
#include "tools/option_values.hpp"

namespace umbra {
namespace {

// Short of the poles, where the floor's up would be the view's direction.
constexpr ValueRange kCameraElevation{-89.9, 89.9};
// Past these the eye meets the model's middle, or the model is a speck.
constexpr ValueRange kCameraZoom{kLeastCameraZoom, kMostCameraZoom};
constexpr ValueRange kFov{1.0, 170.0}, kLightElevation{-90.0, 90.0}, kCreaseAngle{0.0, 180.0};
// Finer than a millionth of the model makes meshes of billions of
// triangles; coarser than a tenth, no recognisable shape.
constexpr ValueRange kCadDeflection{1e-6, 0.1};
constexpr ValueRange kCadAngle{1.0, 90.0};

// `degrees` to a tenth, as --help says a default that is not a round number.
double to_tenths(double degrees) { return std::round(degrees * 10.0) / 10.0; }

}  // namespace

void add_up_option(CommandOptions& options, std::string& up, std::vector<std::string>& given) {
  add_noted_value(options, given, "--up",
            {"AXIS", "for a MESH: its axis that points up, +x, -x, +y, -y, +z or -z (default: its format's convention, +z for STL "
                     "and 3MF, +y for the others)"},
            [&](const std::string& o, const std::string& t) { up = parse_up_axis(o, t); });
}

void add_camera_orbit_options(CommandOptions& options, StageView& v, std::vector<std::string>& given) {
  const auto add = [&](const std::string& name, const OptionHelp& help, std::function<void(const std::string&, const std::string&)> take) {
    add_noted_value(options, given, name, help, std::move(take));
  };
  add("--camera-azimuth", {"DEG", "the camera's azimuth (default " + number_text(stage_defaults::kCameraAzimuthDeg) + ")"},
      [&](const std::string& o, const std::string& t) { v.camera_azimuth_deg = parse_finite_number(o, t); });
  add("--camera-elevation", ranged({"DEG", "the camera's elevation, {range} (default {default})"}, kCameraElevation,
             stage_defaults::kCameraElevationDeg),
      [&](const std::string& o, const std::string& t) { v.camera_elevation_deg = parse_degrees_in(o, t, kCameraElevation); });
  add("--camera-zoom",
      ranged({"F", "come F times closer than the framing (default {default}; {range}; not with --eye, which places the camera)"}, kCameraZoom,
             v.camera_zoom),
      [&](const std::string& o, const std::string& t) {
        v.camera_zoom = parse_finite_number(o, t);
        if (!(v.camera_zoom >= kCameraZoom.lowest && v.camera_zoom <= kCameraZoom.highest))
          throw UsageError(o + " expects a factor from " + number_text(kCameraZoom.lowest) + " to " + number_text(kCameraZoom.highest) +
                           ", got \"" + t + "\"");
      });
}

void add_staging_options(CommandOptions& options, StagingOptions& staging, std::vector<std::string>& given) {
  StageView& v = staging.view;
  const auto add = [&](const std::string& name, const OptionHelp& help, std::function<void(const std::string&, const std::string&)> take) {
    add_noted_value(options, given, name, help, std::move(take));
  };
  add_up_option(options, staging.up, given);
  options.paragraph(
      "For a MESH, where the camera and the light are: in the staged scene's coordinates (the model fitted into the cube [-1,1]^3, +z "
      "up), angles in degrees round the model's centre, azimuth 0 from its front (-y) growing toward its right (+x), elevation 0 level. "
      "The frame keeps the model and its shadow in view wherever they are, unless --eye or --target place the camera.");
  add_camera_orbit_options(options, v, given);
  add("--fov", ranged({"DEG", "the lens's vertical field of view, {range} (default {default})"}, kFov, v.fov_deg),
      [&](const std::string& o, const std::string& t) { v.fov_deg = parse_degrees_in(o, t, kFov); });
  options.flag("--orthographic", v.orthographic,
               "parallel rays (an orthographic camera), framing the model and its shadow as the lens would; shadows as exact (its "
               "volumes stop past the last surface)");
  add("--eye", {"X,Y,Z", "put the camera there (aimed at the framing's target)"},
      [&](const std::string& o, const std::string& t) { v.eye = parse_point(o, t); });
  add("--target", {"X,Y,Z", "aim the camera there (from the framing's direction)"},
      [&](const std::string& o, const std::string& t) { v.target = parse_point(o, t); });
  add("--light-azimuth", {"DEG", "the light's azimuth (default about " + number_text(to_tenths(stage_defaults::kLightAzimuthDeg)) + ": front left)"},
      [&](const std::string& o, const std::string& t) { v.light_azimuth_deg = parse_finite_number(o, t); });
  add("--light-elevation",
      ranged({"DEG", "the light's elevation, {range} (default about {default}); it stands 4 half-sizes of the model from its centre"},
             kLightElevation, to_tenths(stage_defaults::kLightElevationDeg)),
      [&](const std::string& o, const std::string& t) { v.light_elevation_deg = parse_degrees_in(o, t, kLightElevation); });
  add("--light", {"X,Y,Z", "put the light there"}, [&](const std::string& o, const std::string& t) { v.light = parse_point(o, t); });
  add("--floor",
      {"COLOR", "the floor's colour; none: no floor; or shadow-catcher: the floor unseen but for its shadow, which darkens the "
                "background (with --background transparent, the shadow alone, as alpha) (default grey)"},
      [&](const std::string& o, const std::string& t) {
        staging.no_floor = t == "none";
        staging.floor_catches_shadow = t == "shadow-catcher";
        if (!staging.no_floor && !staging.floor_catches_shadow) staging.floor_color = parse_color(o, t);
      });
  add("--color", {"COLOR", "the model's colour where its file gives it none (default light grey)"},
      [&](const std::string& o, const std::string& t) { staging.model_color = parse_color(o, t); });
  options.flag("--plain", staging.plain_model,
               "draw the model in --color alone: not its file's materials, texture maps or vertex colours");
  options.flag("--flat", staging.flat,
               "shade every face flat (default: smooth, in the file's normals, else across edges whose faces meet at no more than "
               "--crease-angle; flat for a mesh with as many triangles as the picture has pixels, whose facets do not show)");
  add("--crease-angle",
      ranged({"DEG", "where the file gives no normals, faces that meet at more than DEG degrees keep a sharp edge ({range}; default "
                     "{default}); given, a mesh of any size is shaded smooth"},
             kCreaseAngle, staging.crease_deg),
      [&](const std::string& o, const std::string& t) {
        staging.crease_deg = parse_degrees_in(o, t, kCreaseAngle);
        staging.crease_given = true;
      });
  // Not a staging option only: a scene's own background gives way to it.
  options.value("--background",
                {"COLOR", "what shows where no surface is: a colour (#rrggbb or a name such as white), or transparent: alpha 0 there, in "
                          "a PNG with an alpha channel (default: the scene's background statement, or black)"},
                [&](const std::string& o, const std::string& t) {
                  staging.background =
                      t == "transparent" ? Background{glm::dvec3(0.0), true} : Background{parse_color(o, t), false};
                });
}

void note_staging_flags(const StagingOptions& staging, std::vector<std::string>& given) {
  if (staging.plain_model) given.push_back("--plain");
  if (staging.flat) given.push_back("--flat");
  if (staging.view.orthographic) given.push_back("--orthographic");
}

StagingOptions staging_for(StagingOptions staging, const RenderSettings& settings) {
  staging.frame_aspect = double(settings.width) / settings.height;
  staging.frame_pixels = size_t(settings.width) * size_t(settings.height);
  staging.width = settings.width, staging.height = settings.height;
  return staging;
}

void require_consistent_staging(const StagingOptions& staging) {
  const StageView& v = staging.view;
  if (v.light && (v.light_azimuth_deg || v.light_elevation_deg))
    throw UsageError("--light places the light outright; --light-azimuth and --light-elevation place it by angles: give one or the other");
  if (v.eye && v.target && *v.eye == *v.target) throw UsageError("--eye and --target are the same point: the camera would look nowhere");
  if (v.orthographic && v.fov_deg != StageView{}.fov_deg)
    throw UsageError("--fov is a perspective's lens; an --orthographic camera has none (its framing sets how much it sees)");
  if (v.eye && v.camera_zoom != 1.0)
    throw UsageError("--camera-zoom scales the framing's distance, which --eye replaces: give one or the other");
  if (v.eye && v.target && glm::length(glm::cross(*v.target - *v.eye, glm::dvec3(0, 0, 1))) == 0.0)
    throw UsageError("--eye is straight above or below --target: the staged camera keeps +z up, so it cannot look along it");
}

void require_staged(const std::vector<std::string>& given, const std::string& path) {
  if (given.empty() || is_mesh_file(path)) return;
  throw UsageError(given.front() + " is for a mesh file on its own, which umbra stages; \"" + path +
                   "\" is not one (a scene has its own camera and lights)");
}

void add_reading_options(CommandOptions& options, ReadOptions& reading, bool maps) {
  if (maps)
    options.flag("--any-texture-path", reading.anywhere,
                 "read texture maps from any folder: by default a model's maps are read only from inside the folder named on the "
                 "command line (the model's own, for a file named on its own), so that a model from anywhere cannot put another "
                 "image you can read into its picture");
  options.value("--cad-deflection",
                ranged({"F", "how far a STEP, IGES or BREP file's triangles may stray from its surfaces, as a fraction of the model's "
                             "size (its box's diagonal; {range}; default {default})"},
                       kCadDeflection, reading.cad.relative_deflection),
                [&](const std::string& o, const std::string& t) {
                  const double fraction = parse_finite_number(o, t);
                  if (!(fraction >= kCadDeflection.lowest && fraction <= kCadDeflection.highest))
                    throw UsageError(o + " expects a fraction of the model's size from " + number_text(kCadDeflection.lowest) + " to " +
                                     number_text(kCadDeflection.highest) + ", got \"" + t + "\"");
                  reading.cad.relative_deflection = fraction;
                });
  options.value("--cad-angle",
                ranged({"DEG", "the largest angle between neighbouring triangles' normals on those surfaces ({range}; default "
                               "{default}): smaller is smoother, and more triangles"},
                       kCadAngle, to_tenths(glm::degrees(reading.cad.angle))),
                [&](const std::string& o, const std::string& t) { reading.cad.angle = glm::radians(parse_degrees_in(o, t, kCadAngle)); });
}

}  // namespace umbra
