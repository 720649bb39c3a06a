#pragma once
// Many views of one staged model and the data behind each picture, for
// datasets: the views' cameras round the model, each view's picture and
// data passes (depth, normals, object and shadow masks), and the cameras'
// poses and intrinsics as a transforms.json (Mildenhall et al., "NeRF",
// 2020; Muller et al., "Instant Neural Graphics Primitives", 2022) in the
// mesh file's own coordinates and units. The model is loaded once and the
// GL context made once; views differ only in their camera.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <nlohmann/json.hpp>

#include "image/image.hpp"
#include "reference/surface_passes.hpp"
#include "render/headless_context.hpp"
#include "render/render_settings.hpp"
#include "scene/mesh_placement.hpp"
#include "scene/motion.hpp"
#include "scene/scene.hpp"
#include "scene/staged_scene.hpp"

namespace umbra {

// A view's data beside its colour picture. One table: --passes, the files'
// names, transforms.json's keys and the Python module's arrays follow it.
enum class DataPass { kDepth, kNormal, kObject, kShadow };
struct DataPassRow {
  DataPass pass;
  const char* name;       // in --passes, the file's name (NNN.name.ext) and Python's dict
  const char* extension;  // ".exr" or ".png"
  const char* frame_key;  // transforms.json's key for the frame's file of it
};
extern const DataPassRow kDataPasses[4];
const DataPassRow& data_pass_row(DataPass pass);
// "depth, normal, object or shadow": for messages.
std::string data_pass_names();
// --passes LIST: comma-separated names, each at most once. Throws UsageError.
std::vector<DataPass> parse_data_passes(const std::string& option, const std::string& text);

// Where the views stand: evenly round the model at the staged elevation
// (starting from the staged azimuth), or evenly over the whole sphere of
// directions (a Fibonacci lattice: Gonzalez, "Measurement of Areas on a
// Sphere Using Fibonacci and Latitude-Longitude Lattices", 2010).
enum class ViewSpread { kRing, kSphere };

struct ViewSetRequest {
  int count = 1;
  ViewSpread spread = ViewSpread::kRing;
  Turning turning = Turning::kNone;  // --turntable's frames, not views round the model: the model or the light turning
  std::vector<DataPass> passes;
  std::optional<std::string> cameras;  // --cameras FILE: the views a transforms.json names, not count's
};

// The views a transforms.json names (transforms_json's own, or a dataset
// tool's), for the staged scene `staged` whose model `placement` placed:
// each frame's umbra_camera where it has one (exactly the camera and
// lights that drew it), else its transform_matrix (camera to the mesh
// file's world, OpenGL's camera axes) and the intrinsics, which must be
// umbra's pinhole: square pixels (fl_x = fl_y) and the principal point at
// the picture's centre; and its light_positions where it has them (the
// staged scene's lights where not).
// Read in two steps: the file's picture size and lens first, since the
// model's staging depends on the picture's size; then its cameras, for the
// model staged.
struct TransformsFile {
  std::string path;  // for messages
  int width = 0, height = 0;  // its w and h
  double fovy_deg = 45.0;     // a pinhole's
  double ortho_height = 0.0;  // an orthographic camera's, in the file's units ("camera_model": "ORTHOGRAPHIC")
  Turning turning = Turning::kNone;  // "umbra_turning": a motion's frames, staged as that motion stages them
  nlohmann::json frames;  // at least one
  size_t count() const { return frames.size(); }
};
// `text` is the file's content, `path` its name for messages. Throws
// InputError naming the file and what in it is wrong.
TransformsFile read_transforms(const std::string& text, const std::string& path);
std::vector<Shot> shots_of(const TransformsFile& file, const Scene& staged, const MeshPlacement& placement);

// A sphere of views looks from below too, where a floor would hide the
// model: it has none unless --floor (in `given`, the staging options named) asks.
void leave_floor_out_of_sphere(StagingOptions& staging, const std::vector<std::string>& given, ViewSpread spread);
// "ring" or "sphere" as a spread; throws UsageError naming `option`.
ViewSpread parse_view_spread(const std::string& option, const std::string& text);

// The shots of `count` views of the staged scene `staged`, each framing
// the model as staging frames it (stage_for, with `view`'s zoom and lens),
// its light held still in the model's frame: round it at the staged
// elevation, view 0 the staged camera's, each framing the model and its
// shadow; or over the sphere, each framing the model alone. Throws StagingChoiceError for a spread that leaves
// the view's framing nowhere to stand.
std::vector<Shot> view_shots(const Scene& staged, const StageView& view, double aspect, int count, ViewSpread spread);

// transforms.json's content for views of `width` x `height` pixels of the
// mesh placed in the scene by `placement`: the intrinsics, and per frame
// its picture's and passes' file names (from the folder the JSON is in),
// its camera's pose (camera to world, OpenGL's camera axes) in the mesh
// file's coordinates, and its lights there; and the motion that staged
// them, where one did.
nlohmann::ordered_json transforms_json(const std::vector<Shot>& shots, const Scene& scene, const MeshPlacement& placement,
                                       int width, int height, const std::vector<DataPass>& passes,
                                       const std::vector<std::string>& stems, Turning turning = Turning::kNone);

// Every shot's lights off every caster of `scene` (require_lights_off_casters,
// shot by shot; the scene is left as it was). Throws InputError.
void require_lights_off_casters(Scene& scene, const std::vector<Shot>& shots);

// One view drawn: its colour picture (as umbra render draws it), and the
// passes asked for: every light's shadow mask (as --mask draws light 1's),
// and the model's depth, normals and coverage from exact rays, in the mesh
// file's units and axes (depth along the view axis; normals unit, on the
// side the camera sees).
struct DrawnView {
  Image color;
  std::vector<Image> shadow;  // per light
  SurfacePasses surface;      // empty unless depth, normal or object is asked for
};

// Draws `scene` (a staged mesh, its model scene.meshes[0] placed by
// `placement`) from each of `shots` in turn (its camera and lights left at
// the last), in one GL context (made in
// `context` where it holds none of the picture's size, and kept there),
// handing each view to `each` as it is drawn.
void draw_views(Scene& scene, const std::vector<Shot>& shots, const MeshPlacement& placement,
                const RenderSettings& settings, const std::vector<DataPass>& passes, std::optional<HeadlessContext>& context,
                HeadlessGl gl,
                const std::function<void(int index, DrawnView&& view)>& each);

// The file name stem of view `index` of `count`: 000, 001, ... (as many
// digits as the largest index needs, at least 3).
std::string view_stem(int index, int count);

}  // namespace umbra
