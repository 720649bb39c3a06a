#pragma once
// How a mesh file on its own is read and staged, as the commands take it:
// the pose, the camera, the light, the floor, the model's colour and
// shading, the background; and how finely CAD surfaces are cut.

#include <string>
#include <vector>

#include "render/render_plan.hpp"
#include "scene/staged_scene.hpp"
#include "tools/command_options.hpp"

namespace umbra {

constexpr double kLeastCameraZoom = 0.01, kMostCameraZoom = 100.0;  // --camera-zoom's range

// How a mesh file on its own is staged: --up AXIS; the camera's
// --camera-azimuth, --camera-elevation, --camera-zoom, --fov, --eye and
// --target; the light's --light-azimuth, --light-elevation and --light;
// --floor COLOR|none|shadow-catcher, --color COLOR, --plain; the model's
// shading, --flat or --crease-angle DEG. The names of those given (the flags
// aside: note_staging_flags adds them once parsed) are added to `given`, for
// a command to refuse them where nothing is staged. Also
// --background COLOR|transparent, which a scene file takes too.
void add_staging_options(CommandOptions& options, StagingOptions& staging, std::vector<std::string>& given);
// Of those, --up AXIS alone (umbra volume takes it), its name noted in `given`.
void add_up_option(CommandOptions& options, std::string& up, std::vector<std::string>& given);
// Of those, the camera's orbit alone: --camera-azimuth, --camera-elevation
// and --camera-zoom (umbra check --picture takes them).
void add_camera_orbit_options(CommandOptions& options, StageView& view, std::vector<std::string>& given);
// Adds the staging flags that were given (--plain, --flat) to `given`.
void note_staging_flags(const StagingOptions& staging, std::vector<std::string>& given);
// `staging` for a picture of `settings`' size: framed for its shape.
StagingOptions staging_for(StagingOptions staging, const RenderSettings& settings);
// A UsageError for staging options that contradict each other: --light with
// --light-azimuth or --light-elevation, --eye at --target.
void require_consistent_staging(const StagingOptions& staging);
// A UsageError naming the first of `given` when `path` is not a mesh file
// (a scene has its own camera and lights).
void require_staged(const std::vector<std::string>& given, const std::string& path);
// How mesh files are read: --cad-deflection F and --cad-angle DEG (how
// finely STEP, IGES and BREP surfaces are cut into triangles); with `maps`,
// --any-texture-path too.
void add_reading_options(CommandOptions& options, ReadOptions& reading, bool maps);

}  // namespace umbra
