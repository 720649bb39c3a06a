#include "tools/view_preparation.hpp"

#include "mesh/input_error.hpp"
#include "mesh/io/mapped_file.hpp"
#include "scene/scene_checks.hpp"
#include "scene/staged_scene.hpp"
#include "tools/command_line.hpp"

namespace umbra {

std::vector<Shot> requested_shots(const Scene& scene, const MeshPlacement& placement, const ViewSetRequest& request,
                                  const std::optional<TransformsFile>& given, const StageView& view, double aspect) {
  if (given) return shots_of(*given, scene, placement);
  if (request.turning != Turning::kNone) return motion_shots(scene, request.turning, request.count);
  return view_shots(scene, view, aspect, request.count, request.spread);
}

PreparedViews prepare_views(const std::string& path, PictureChoices choices, const ViewSetRequest& request, const ReadOptions& maps,
                            const ViewProgress& progress, std::string& messages) {
  const bool mesh = is_mesh_file(path);
  // A file umbra would stage, not a scene: its views stand round its model.
  // A scene's camera turns with its lights, or its lights alone.
  if (!mesh && (request.turning == Turning::kNone || request.cameras))
    throw InputError({path}, "views are drawn of a mesh file on its own, which umbra stages; this is not one (a scene has its "
                             "own camera: --turntable turns it)", InputProblem::kUnsupportedFormat);
  PreparedViews prepared;
  RenderSettings& settings = choices.settings;
  if (progress) progress(0, 1, "loading " + path);
  // The cameras file is read first: a bad one stops the run before the
  // model's load, and its size is the picture's, which staging weighs.
  std::optional<TransformsFile> given;
  if (request.cameras) {
    given = read_transforms(std::string(MappedFile(*request.cameras).bytes()), *request.cameras);
    if (!choices.size_given) settings.width = given->width, settings.height = given->height, choices.size_given = true;
  }
  // A motion's frames are staged for the whole motion (its own, or the one that drew the cameras file's).
  prepared.turning = given ? given->turning : request.turning;
  choices.staging.view.turning = prepared.turning;
  Scene& scene = prepared.scene;
  scene = parse_scene_or_mesh_file(path, {}, nullptr, staging_for(choices.staging, settings), maps);
  if (mesh) prepared.placement = placement_of(scene.meshes.at(0));
  set_picture_size(settings, choices.size_given, scene);
  const int count = given ? int(given->count()) : request.count;
  set_picture_samples(settings, choices.antialias, choices.antialias_all, choices.show_volumes, scene, size_t(count));
  require_drawable_size(settings.width, settings.height, settings.frame_samples());
  for (const Warning& w : scene.warnings) messages += w.where.str() + ": warning: " + w.message + "\n";
  require_caught_shadows_kept(scene, settings.method);
  prepared.shots =
      requested_shots(scene, prepared.placement, request, given, choices.staging.view, double(settings.width) / settings.height);
  require_lights_off_casters(scene, prepared.shots);
  prepared.settings = settings;
  return prepared;
}

size_t PreparedViews::triangles() const {
  size_t triangles = scene.triangles.size();
  for (const Mesh& m : scene.meshes) triangles += m.triangles.size();
  return triangles;
}

}  // namespace umbra
