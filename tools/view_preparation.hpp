#pragma once
// Many pictures of one file made ready to draw, for umbra render --views,
// --cameras and --turntable and for the Python module: the file loaded
// (staged for the motion asked for), its picture settings, and the shot of
// each picture.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "scene/mesh_loader.hpp"
#include "scene/mesh_placement.hpp"
#include "scene/motion.hpp"
#include "scene/scene.hpp"
#include "tools/picture_choices.hpp"
#include "tools/view_set.hpp"

namespace umbra {

// What was written: how many views, of what size, of how many triangles.
struct WrittenViews {
  int views = 0, width = 0, height = 0;
  size_t triangles = 0;
};
// Told how far the drawing is: done of total, and what is under way.
using ViewProgress = std::function<void(size_t done, size_t total, const std::string& what)>;

// The shots `request` asks of the scene `scene` (a staged mesh's model
// placed by `placement`, where it has views round it), in a picture
// `aspect` wide: `given`'s (a cameras file's), a motion's frames, or views
// round the model as `view` frames them.
std::vector<Shot> requested_shots(const Scene& scene, const MeshPlacement& placement, const ViewSetRequest& request,
                                  const std::optional<TransformsFile>& given, const StageView& view, double aspect);

// Many pictures of one file made ready to draw: the file loaded (a mesh
// file staged, for the request's motion where it asks for one), the
// settings it is drawn with, and the shots of each picture: a cameras
// file's, a motion's frames or views round the model.
struct PreparedViews {
  Scene scene;
  MeshPlacement placement;  // the model's, for a mesh file; a scene's own coordinates are the file's
  RenderSettings settings;
  std::vector<Shot> shots;
  Turning turning = Turning::kNone;  // the motion the shots turn through
  size_t triangles() const;
};
// Loads `path` for `request`: views and cameras files need a mesh file
// (InputError for a scene), a motion takes a scene too. The mesh's
// warnings' lines are added to `messages`. Throws as loading throws, and
// as a frame's light on a caster does.
PreparedViews prepare_views(const std::string& path, PictureChoices choices, const ViewSetRequest& request, const ReadOptions& maps,
                            const ViewProgress& progress, std::string& messages);

}  // namespace umbra
