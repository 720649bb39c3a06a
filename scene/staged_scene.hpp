#pragma once
// A mesh file shown on its own, without a scene written for it: umbra stages
// it as a product shot (f3d and Blender stage a model much the same way).
// The model stands on a ground plane in its own up axis, lit by one point
// light above and to one side, seen from a raised three-quarter view that
// frames it and its shadow; the ground reaches past the frame's edges. The
// stage is written as scene text that the user can save and edit, and that
// reads back as the same scene.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/mesh_loader.hpp"
#include "scene/motion.hpp"
#include "scene/scene.hpp"

namespace umbra {

// Samples per side a staged mesh is drawn with (its text's `antialias`): a
// picture to show.
constexpr int kStagedAntialias = 3;

// Whether `path` is a mesh file (by its content; see mesh_format.hpp) rather
// than a scene. False for a file that cannot be read: the scene parser then
// says why.
bool is_mesh_file(const std::string& path);

// The error, when `path` is plainly neither a scene nor a mesh file: "PATH:
// neither a scene nor a mesh file (OBJ, ..., or 3MF): a JPEG image"
// (kUnsupportedFormat), or "PATH: the file is empty" or "...: the file holds
// only blank lines" (kEmpty, of any name: such a file is no scene either).
// None for a .scene file, a mesh file, or other text, which the scene parser
// reads (and says, line by line, what is wrong with), and for a file that
// cannot be read (the parser says why).
std::optional<InputError> neither_scene_nor_mesh(const std::string& path);

// Where the stage's camera and light go, in the staged scene's coordinates
// (the model fitted into the cube [-1,1]^3, its up axis turned to +z).
// Angles are in degrees round the model's centre: azimuth 0 looks at the
// model's front (from -y), and grows toward its right (+x); elevation 0 is
// level, 90 straight down from above. The camera keeps the model and its
// shadow in frame wherever it or the light is, unless `eye` or `target`
// place it outright.
// A staging choice that the model's framing rules out (an eye at the very
// point the framing looks at): the option's fault, not the file's, which a
// command says as a usage error.
class StagingChoiceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct StageView {
  // Unset: 35, or for a flat model standing upright, 35 degrees off its face (view_turn_facing).
  std::optional<double> camera_azimuth_deg;
  // Unset: 30, or 60 for a model that lies low (lies_low), whose face reads from there.
  std::optional<double> camera_elevation_deg;
  double camera_zoom = 1.0;  // over the framing distance: 2 shows the model twice as large
  double fov_deg = 30.0;     // the lens's vertical field of view
  bool orthographic = false; // parallel rays, framing the model and its shadow as the lens would
  std::optional<glm::dvec3> eye, target;
  // The light: `light` outright, or 4 model half-sizes from its centre in
  // the direction these give; unset, above and to the left of the front
  // (azimuth about -47.7, elevation about 60.2), so that the shadow falls
  // beside the model rather than behind it.
  std::optional<double> light_azimuth_deg, light_elevation_deg;
  std::optional<glm::dvec3> light;
  double light_turn_deg = 0.0;  // then turned about the z axis (--light-angle)
  // Frame the model's shadow on the floor's plane too, whether or not a
  // floor is drawn (the floor never moves the camera); a sphere of views,
  // which looks from below too, frames the model alone.
  bool frame_shadow = true;
  // A motion the frame holds in every frame of: the model turning through a
  // whole turn under the light, or the light orbiting it (motion.hpp).
  Turning turning = Turning::kNone;
  // Over 0, the model comes first: its shadow is framed only as far as lets
  // the camera stand this many times as far back as the model alone needs
  // (staging sets it for a spindly model under the default light).
  double shadow_room = 0.0;

  bool operator==(const StageView&) const = default;
};

// The floor, light and camera for a model whose box, fitted and turned so that
// its up axis is +z, is [lo, hi]; the camera frames `points` (points of the
// model) and their shadows on the floor, in a picture `aspect` (width over
// height) wide: by the narrower of its two fields of view.
struct Stage {
  glm::dvec3 light{0.0};
  double floor_z = 0.0;  // a thousandth below the model, written to a millionth
  glm::dvec3 floor_centre{0.0};
  double floor_half_size = 0.0;
  Camera camera;
  bool shadow_cut = false;  // part of the shadow was left out of the frame so that the model comes first
};
Stage stage_for(const glm::dvec3& lo, const glm::dvec3& hi, const std::vector<glm::dvec3>& points, double aspect = 1.0,
                const StageView& view = {});

// Points of `mesh` that show its extent to a camera: the corners of up to
// `most` of its triangles, spread over them, and the corners that reach
// furthest along each axis.
std::vector<glm::dvec3> framing_points(const Mesh& mesh, size_t most = 4096);

// The name the staged scene goes by in messages: "MESH (staged)", in the mesh's folder.
std::string staged_scene_name(const std::string& mesh_path);

// How a mesh file on its own is staged: stood on its `up` axis ("" for its
// format's own), framed for a picture `frame_aspect` (width over height) wide.
struct StagingOptions {
  std::string up;
  double frame_aspect = 1.0;
  StageView view;
  // The stage's floor: its colour (diffuse and ambient), or none at all.
  std::optional<glm::dvec3> floor_color;
  bool no_floor = false;
  bool floor_catches_shadow = false;  // a shadow catcher (Material::shadow_catcher)
  // The model's colour where its file gives none (the scene's default material).
  std::optional<glm::dvec3> model_color;
  bool plain_model = false;  // that colour alone: not the file's materials, maps or vertex colours
  // Shaded smooth (the mesh statement's `smooth`) across edges whose faces
  // meet at no more than this, where the file gives no normals; or flat.
  // Unless the crease angle is given, a mesh with as many triangles as the
  // picture has pixels (`frame_pixels`; 0: unknown) is drawn flat: no facet
  // of it shows.
  double crease_deg = 30.0;
  bool crease_given = false;
  bool flat = false;
  size_t frame_pixels = 0;
  // The picture's size and samples, written into the staged scene (`size`,
  // `antialias N [all]`) so that the saved scene draws the same picture
  // with no options: width 0 writes no size; no antialias writes the
  // staged default.
  int width = 0, height = 0;
  std::optional<int> antialias;
  bool antialias_all = false;
  // The background, for a mesh file's stage and a scene file alike (a
  // scene's own then gives way).
  std::optional<Background> background;
};

// parse_scene_file for a scene, or the staged scene for a mesh file; either
// way with its lights turned by `staging.view.light_turn_deg` about the z
// axis (a staged light before the camera frames its shadow), and with
// `staging.background` where given.
// `staged` (when given) receives the staged scene's text, or "" for a scene
// file. A mesh file with no faces is an InputError: there is nothing to show.
// `maps` says where texture maps may be read from.
Scene parse_scene_or_mesh_file(const std::string& path, const MeshLoadProgress& progress = {}, std::string* staged = nullptr,
                               const StagingOptions& staging = {}, const ReadOptions& maps = {});

// The stage for a mesh already in memory (a mesh handed over as arrays:
// array_soup.hpp; a file's, tinted for the defect picture), named
// soup->path, as parse_scene_or_mesh_file stages a file; its up axis,
// where `staging` gives none, is `own_up`, the convention its format
// would have (+y for arrays, as glTF's and OBJ's).
Scene stage_polygon_soup(std::shared_ptr<const PolygonSoup> soup, std::string* staged = nullptr, const StagingOptions& staging = {},
                         const std::string& own_up = "+y");

}  // namespace umbra
