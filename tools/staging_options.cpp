#include "tools/staging_options.hpp"

#include <functional>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "scene/scene_text.hpp"
#include "tools/option_values.hpp"

namespace umbra {
namespace {

// An option whose value `take` checks and keeps, its name then noted in `given`.
void add_noted(CommandOptions& options, std::vector<std::string>& given, const std::string& name,
               std::function<void(const std::string&, const std::string&)> take) {
  options.value(name, [&given, take = std::move(take)](const std::string& o, const std::string& t) {
    take(o, t);
    given.push_back(o);
  });
}

}  // namespace

void add_camera_orbit_options(CommandOptions& options, StageView& v, std::vector<std::string>& given) {
  const auto add = [&](const std::string& name, std::function<void(const std::string&, const std::string&)> take) {
    add_noted(options, given, name, std::move(take));
  };
  add("--camera-azimuth", [&](const std::string& o, const std::string& t) { v.camera_azimuth_deg = parse_finite_number(o, t); });
  // Short of the poles, where the floor's up would be the view's direction.
  add("--camera-elevation", [&](const std::string& o, const std::string& t) {
    v.camera_elevation_deg = parse_degrees_in(o, t, -89.9, 89.9);
  });
  add("--camera-zoom", [&](const std::string& o, const std::string& t) {
    v.camera_zoom = parse_finite_number(o, t);
    // Past these the eye meets the model's middle, or the model is a speck.
    if (!(v.camera_zoom >= kLeastCameraZoom && v.camera_zoom <= kMostCameraZoom))
      throw UsageError(o + " expects a factor from " + number_text(kLeastCameraZoom) + " to " + number_text(kMostCameraZoom) + ", got \"" +
                       t + "\"");
  });
}

void add_staging_options(CommandOptions& options, StagingOptions& staging, std::vector<std::string>& given) {
  StageView& v = staging.view;
  const auto add = [&](const std::string& name, std::function<void(const std::string&, const std::string&)> take) {
    add_noted(options, given, name, std::move(take));
  };
  add("--up", [&](const std::string& o, const std::string& t) { staging.up = parse_up_axis(o, t); });
  add_camera_orbit_options(options, v, given);
  add("--fov", [&](const std::string& o, const std::string& t) { v.fov_deg = parse_degrees_in(o, t, 1.0, 170.0); });
  options.flag("--orthographic", v.orthographic);
  add("--eye", [&](const std::string& o, const std::string& t) { v.eye = parse_point(o, t); });
  add("--target", [&](const std::string& o, const std::string& t) { v.target = parse_point(o, t); });
  add("--light-azimuth", [&](const std::string& o, const std::string& t) { v.light_azimuth_deg = parse_finite_number(o, t); });
  add("--light-elevation", [&](const std::string& o, const std::string& t) {
    v.light_elevation_deg = parse_degrees_in(o, t, -90.0, 90.0);
  });
  add("--light", [&](const std::string& o, const std::string& t) { v.light = parse_point(o, t); });
  add("--floor", [&](const std::string& o, const std::string& t) {
    staging.no_floor = t == "none";
    staging.floor_catches_shadow = t == "shadow-catcher";
    if (!staging.no_floor && !staging.floor_catches_shadow) staging.floor_color = parse_color(o, t);
  });
  add("--color", [&](const std::string& o, const std::string& t) { staging.model_color = parse_color(o, t); });
  options.flag("--plain", staging.plain_model);
  options.flag("--flat", staging.flat);
  add("--crease-angle", [&](const std::string& o, const std::string& t) {
    staging.crease_deg = parse_degrees_in(o, t, 0.0, 180.0);
    staging.crease_given = true;
  });
  // Not a staging option only: a scene's own background gives way to it.
  options.value("--background", [&](const std::string& o, const std::string& t) {
    staging.background = t == "transparent" ? Background{glm::dvec3(0.0), true} : Background{parse_color(o, t), false};
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
  if (maps) options.flag("--any-texture-path", reading.anywhere);
  options.value("--cad-deflection", [&](const std::string& o, const std::string& t) {
    const double fraction = parse_finite_number(o, t);
    // Finer than a millionth of the model makes meshes of billions of
    // triangles; coarser than a tenth, no recognisable shape.
    if (!(fraction >= 1e-6 && fraction <= 0.1))
      throw UsageError(o + " expects a fraction of the model's size from 1e-06 to 0.1, got \"" + t + "\"");
    reading.cad.relative_deflection = fraction;
  });
  options.value("--cad-angle", [&](const std::string& o, const std::string& t) {
    reading.cad.angle = glm::radians(parse_degrees_in(o, t, 1.0, 90.0));
  });
}

}  // namespace umbra
