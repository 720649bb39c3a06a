#include "tools/view_set.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "mesh/input_error.hpp"
#include "reference/ray_caster.hpp"
#include "scene/scene_checks.hpp"
#include "tools/command_line.hpp"
#include "tools/picture_drawing.hpp"

namespace umbra {

const DataPassRow kDataPasses[4] = {
    {DataPass::kDepth, "depth", ".exr", "depth_file_path"},
    {DataPass::kNormal, "normal", ".exr", "normal_file_path"},
    {DataPass::kObject, "object", ".png", "mask_path"},
    {DataPass::kShadow, "shadow", ".png", "shadow_file_path"},
};

const DataPassRow& data_pass_row(DataPass pass) { return kDataPasses[size_t(pass)]; }

std::string data_pass_names() {
  std::string names;
  for (size_t i = 0; i < std::size(kDataPasses); ++i)
    names += (i == 0 ? "" : i + 1 == std::size(kDataPasses) ? " or " : ", ") + std::string(kDataPasses[i].name);
  return names;
}

std::vector<DataPass> parse_data_passes(const std::string& option, const std::string& text) {
  std::vector<DataPass> passes;
  std::stringstream words(text);
  for (std::string word; std::getline(words, word, ',');) {
    const auto row = std::find_if(std::begin(kDataPasses), std::end(kDataPasses), [&](const DataPassRow& r) { return word == r.name; });
    if (row == std::end(kDataPasses))
      throw UsageError(option + " takes " + data_pass_names() + ", separated by commas (colour is always drawn); got \"" + word + "\"");
    if (std::count(passes.begin(), passes.end(), row->pass)) throw UsageError(option + " names " + word + " twice");
    passes.push_back(row->pass);
  }
  if (passes.empty()) throw UsageError(option + " needs at least one of " + data_pass_names());
  return passes;
}

void leave_floor_out_of_sphere(StagingOptions& staging, const std::vector<std::string>& given, ViewSpread spread) {
  if (spread == ViewSpread::kSphere && !std::count(given.begin(), given.end(), "--floor")) staging.no_floor = true;
}

ViewSpread parse_view_spread(const std::string& option, const std::string& text) {
  if (text != "ring" && text != "sphere") throw UsageError(option + " takes ring or sphere, got \"" + text + "\"");
  return text == "ring" ? ViewSpread::kRing : ViewSpread::kSphere;
}

std::vector<Shot> view_shots(const Scene& staged, const StageView& view, double aspect, int count, ViewSpread spread) {
  const Mesh& mesh = staged.meshes.at(0);
  const Camera& first = staged.camera;
  // The staged camera's own direction from what it looks at: its azimuth
  // and elevation in StageView's convention.
  const glm::dvec3 back = glm::normalize(first.eye - first.target);
  const double azimuth = glm::degrees(std::atan2(back.x, -back.y)), elevation = glm::degrees(std::asin(back.z));
  std::vector<Shot> shots;
  const Shot still = shot_of(staged);  // its lights stay where they are
  if (spread == ViewSpread::kRing) shots.push_back(still);
  const std::vector<glm::dvec3> points = framing_points(mesh);
  StageView turned = view;
  turned.light = staged.lights.at(0).position;  // held still in the model's frame
  turned.light_turn_deg = 0.0;
  turned.light_azimuth_deg = turned.light_elevation_deg = std::nullopt;
  turned.eye = turned.target = std::nullopt;
  // The golden angle: each view on the sphere turns by it from the last.
  const double golden_deg = 180.0 * (3.0 - std::sqrt(5.0));
  // Seen from below too, the sphere's views frame the model alone.
  turned.frame_shadow = spread == ViewSpread::kRing;
  for (int i = spread == ViewSpread::kRing ? 1 : 0; i < count; ++i) {
    if (spread == ViewSpread::kRing) {
      turned.camera_azimuth_deg = azimuth + 360.0 * i / count;
      turned.camera_elevation_deg = elevation;
    } else {
      // Fibonacci lattice: equal areas of the sphere, from near its top to
      // near its bottom, turning from the staged azimuth.
      const double z = 1.0 - (2.0 * i + 1.0) / count;
      turned.camera_azimuth_deg = azimuth + golden_deg * i;
      turned.camera_elevation_deg = glm::degrees(std::asin(z));
    }
    shots.push_back({stage_for(mesh.bounds_min, mesh.bounds_max, points, aspect, turned).camera, still.lights});
  }
  return shots;
}

namespace {

nlohmann::ordered_json row_major(const glm::dmat4& m) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({m[0][r], m[1][r], m[2][r], m[3][r]});
  return rows;
}

nlohmann::ordered_json point_json(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

}  // namespace

nlohmann::ordered_json transforms_json(const std::vector<Shot>& shots, const Scene& scene, const MeshPlacement& placement,
                                       int width, int height, const std::vector<DataPass>& passes,
                                       const std::vector<std::string>& stems, Turning turning) {
  const Camera& lens = shots.at(0).camera;
  nlohmann::ordered_json json;
  // An orthographic camera has no focal length: what the picture spans, in
  // the file's units, the first view's here and each view's in its frame,
  // as each is framed (a pinhole's keys left out, so that a tool that knows
  // only those stops).
  const auto span = [&](nlohmann::ordered_json& into, const Camera& c) {
    into["ortho_width"] = placement.file_length(c.ortho_height * width / height);
    into["ortho_height"] = placement.file_length(c.ortho_height);
  };
  if (lens.orthographic()) {
    span(json, lens);
  } else {
    const double focal = lens.focal_length_pixels(height);
    json["camera_angle_x"] = 2.0 * std::atan(width / (2.0 * focal));
    json["camera_angle_y"] = 2.0 * std::atan(height / (2.0 * focal));
    json["fl_x"] = focal;
    json["fl_y"] = focal;
  }
  json["cx"] = width / 2.0;
  json["cy"] = height / 2.0;
  json["w"] = width;
  json["h"] = height;
  json["camera_model"] = lens.orthographic() ? "ORTHOGRAPHIC" : "PINHOLE";
  // The motion the frames were staged for: --cameras stages theirs alike.
  if (turning != Turning::kNone) json["umbra_turning"] = turning_name(turning);
  nlohmann::ordered_json frames = nlohmann::ordered_json::array();
  for (size_t i = 0; i < shots.size(); ++i) {
    const Camera& c = shots[i].camera;
    const CameraAxes a = c.axes();
    // Camera to the file's world: its axes (x right, y up, z back) and eye
    // in the file's coordinates; rigid, as the placement's scale is uniform.
    glm::dmat4 pose(1.0);
    pose[0] = glm::dvec4(placement.file_direction(a.right), 0.0);
    pose[1] = glm::dvec4(placement.file_direction(a.up), 0.0);
    pose[2] = glm::dvec4(placement.file_direction(-a.forward), 0.0);
    pose[3] = glm::dvec4(placement.file_point(c.eye), 1.0);
    nlohmann::ordered_json frame;
    frame["file_path"] = stems[i] + ".png";
    if (c.orthographic()) span(frame, c);
    for (const DataPass pass : passes) {
      const DataPassRow& row = data_pass_row(pass);
      if (pass == DataPass::kShadow && scene.lights.size() > 1) {
        nlohmann::ordered_json files = nlohmann::ordered_json::array();
        for (size_t l = 0; l < scene.lights.size(); ++l) files.push_back(stems[i] + "." + row.name + std::to_string(l + 1) + row.extension);
        frame[row.frame_key] = files;
      } else {
        frame[row.frame_key] = stems[i] + "." + row.name + row.extension;
      }
    }
    frame["transform_matrix"] = row_major(pose);
    nlohmann::ordered_json lights = nlohmann::ordered_json::array(), placed_lights = nlohmann::ordered_json::array();
    for (const glm::dvec3& l : shots[i].lights) {
      lights.push_back(point_json(placement.file_point(l)));
      placed_lights.push_back(point_json(l));
    }
    frame["light_positions"] = lights;
    // The camera and lights as umbra placed them, in the staged scene's
    // coordinates: --cameras draws them again exactly.
    frame["umbra_camera"] = {{"eye", point_json(c.eye)}, {"target", point_json(c.target)}, {"up", point_json(c.up)}};
    if (c.orthographic()) frame["umbra_camera"]["orthographic"] = c.ortho_height;
    else frame["umbra_camera"]["fovy"] = c.fovy_deg;
    frame["umbra_camera"]["lights"] = placed_lights;
    frames.push_back(frame);
  }
  json["frames"] = frames;
  return json;
}

namespace {

// A number of `json` at `key`, or an InputError naming the file and where.
double number_at(const nlohmann::json& json, const char* key, const std::string& path, const std::string& where) {
  const auto found = json.find(key);
  if (found == json.end() || !found->is_number() || !std::isfinite(found->get<double>()))
    throw InputError({path}, where + " needs \"" + key + "\", a finite number", InputProblem::kMalformed);
  return found->get<double>();
}

// `value` as a point, or an InputError saying that `what` must be one.
glm::dvec3 point_value(const nlohmann::json& value, const std::string& path, const std::string& what) {
  if (!value.is_array() || value.size() != 3 ||
      !std::all_of(value.begin(), value.end(), [](const nlohmann::json& v) { return v.is_number() && std::isfinite(v.get<double>()); }))
    throw InputError({path}, what + " must be 3 finite numbers", InputProblem::kMalformed);
  return {value[0].get<double>(), value[1].get<double>(), value[2].get<double>()};
}

glm::dvec3 point_at(const nlohmann::json& json, const char* key, const std::string& path, const std::string& where) {
  const auto found = json.find(key);
  return point_value(found == json.end() ? nlohmann::json() : *found, path, where + "'s \"" + key + "\"");
}

}  // namespace

TransformsFile read_transforms(const std::string& text, const std::string& path) {
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // a parse error, or a number beyond a double (out_of_range)
    throw InputError({path}, std::string("not JSON: ") + e.what(), InputProblem::kMalformed);
  }
  if (!json.is_object()) throw InputError({path}, "a transforms.json is an object, with \"frames\"", InputProblem::kMalformed);
  TransformsFile file;
  file.path = path;
  const double w = number_at(json, "w", path, "the file"), h = number_at(json, "h", path, "the file");
  if (w != std::floor(w) || h != std::floor(h) || w < 1 || h < 1 || std::max(w, h) > kLargestPictureSide)
    throw InputError({path}, "w and h must be whole numbers of pixels from 1 to " + std::to_string(kLargestPictureSide),
                     InputProblem::kMalformed);
  file.width = int(w), file.height = int(h);
  const double cx = number_at(json, "cx", path, "the file"), cy = number_at(json, "cy", path, "the file");
  if (std::abs(cx - w / 2) > 1e-9 * w || std::abs(cy - h / 2) > 1e-9 * h)
    throw InputError({path}, "cx and cy must be the picture's centre, w / 2 and h / 2 (umbra's camera looks through it)",
                     InputProblem::kMalformed);
  const auto model = json.find("camera_model");
  if (model != json.end() && *model == "ORTHOGRAPHIC") {
    const double ortho_w = number_at(json, "ortho_width", path, "the file"), ortho_h = number_at(json, "ortho_height", path, "the file");
    if (!(ortho_h > 0.0) || std::abs(ortho_w - ortho_h * w / h) > 1e-9 * ortho_w)
      throw InputError({path}, "ortho_width and ortho_height must be above 0 and in the picture's proportion (umbra draws square pixels)",
                       InputProblem::kMalformed);
    file.ortho_height = ortho_h;
  } else {
    const double fl_x = number_at(json, "fl_x", path, "the file"), fl_y = number_at(json, "fl_y", path, "the file");
    // A pinhole with square pixels, centred: what umbra's camera is.
    if (!(fl_y > 0.0) || std::abs(fl_x - fl_y) > 1e-9 * fl_y)
      throw InputError({path}, "fl_x and fl_y must be one focal length above 0 (umbra draws square pixels)", InputProblem::kMalformed);
    file.fovy_deg = glm::degrees(2.0 * std::atan(h / (2.0 * fl_y)));
  }
  if (const auto turning = json.find("umbra_turning"); turning != json.end())
    if (!turning->is_string() || !parse_turning(turning->get<std::string>(), file.turning))
      throw InputError({path}, "\"umbra_turning\" is \"model\" or \"light\": the motion that staged the frames",
                       InputProblem::kMalformed);
  const auto frames = json.find("frames");
  if (frames == json.end() || !frames->is_array() || frames->empty())
    throw InputError({path}, "needs \"frames\", a list of at least one camera", InputProblem::kMalformed);
  file.frames = std::move(*frames);
  return file;
}

std::vector<Shot> shots_of(const TransformsFile& file, const Scene& staged, const MeshPlacement& placement) {
  const std::string& path = file.path;
  const nlohmann::json* const frames = &file.frames;
  std::vector<Shot> shots;
  const glm::dvec3 centre = 0.5 * (staged.meshes.at(0).bounds_min + staged.meshes.at(0).bounds_max);
  for (size_t i = 0; i < frames->size(); ++i) {
    const nlohmann::json& frame = (*frames)[i];
    const std::string where = "frame " + std::to_string(i);
    if (!frame.is_object()) throw InputError({path}, where + " is not an object", InputProblem::kMalformed);
    Camera camera;
    Shot shot = shot_of(staged);
    // The frame's lights, as many as the scene has: umbra's own exactly, or a file's placed with the model.
    const auto lights_at = [&](const nlohmann::json& json, const char* key, bool in_file) {
      const auto found = json.find(key);
      if (found == json.end()) return;
      if (!found->is_array() || found->size() != shot.lights.size())
        throw InputError({path}, where + "'s \"" + key + "\" must list " + std::to_string(shot.lights.size()) +
                                     (shot.lights.size() == 1 ? " light" : " lights") + ", as the scene has",
                         InputProblem::kMalformed);
      for (size_t l = 0; l < shot.lights.size(); ++l) {
        const glm::dvec3 p = point_value((*found)[l], path, where + "'s \"" + key + "\" light " + std::to_string(l + 1));
        shot.lights[l] = in_file ? placement(p) : p;
      }
    };
    if (const auto placed = frame.find("umbra_camera"); placed != frame.end() && placed->is_object()) {
      if (placed->contains("lights")) lights_at(*placed, "lights", false);
      else lights_at(frame, "light_positions", true);
      camera = Camera{point_at(*placed, "eye", path, where), point_at(*placed, "target", path, where), point_at(*placed, "up", path, where)};
      if (placed->contains("orthographic")) {
        camera.ortho_height = number_at(*placed, "orthographic", path, where);
        if (!(camera.ortho_height > 0.0))
          throw InputError({path}, where + "'s orthographic height must be above 0", InputProblem::kMalformed);
      } else {
        camera.fovy_deg = number_at(*placed, "fovy", path, where);
      }
    } else {
      const auto m = frame.find("transform_matrix");
      if (m == frame.end() || !m->is_array() || m->size() < 3)
        throw InputError({path}, where + " needs \"transform_matrix\", 4 rows of 4 numbers", InputProblem::kMalformed);
      glm::dmat4 pose(1.0);
      for (int r = 0; r < 3; ++r) {
        const nlohmann::json& row = (*m)[size_t(r)];
        if (!row.is_array() || row.size() != 4 ||
            !std::all_of(row.begin(), row.end(), [](const nlohmann::json& v) { return v.is_number() && std::isfinite(v.get<double>()); }))
          throw InputError({path}, where + "'s transform_matrix needs 4 rows of 4 finite numbers", InputProblem::kMalformed);
        for (int c = 0; c < 4; ++c) pose[c][r] = row[size_t(c)].get<double>();
      }
      // The file's frame into the staged scene's: the eye placed, the axes turned.
      const glm::dvec3 eye = placement(glm::dvec3(pose[3]));
      const glm::dvec3 back = placement.direction(glm::dvec3(pose[2])), up = placement.direction(glm::dvec3(pose[1]));
      if (!(glm::length(back) > 0.0) || !(glm::length(glm::cross(back, up)) > 0.0))
        throw InputError({path}, where + "'s transform_matrix has no camera axes (its z and y columns are 0 or parallel)",
                         InputProblem::kMalformed);
      const glm::dvec3 forward = -glm::normalize(back);
      // Aimed along its axis, as far as the model's centre lies along it (or as far as the centre is).
      const double along = glm::dot(centre - eye, forward);
      // An orthographic frame's own span, where it gives one, else the file's.
      const double ortho_height = file.ortho_height > 0.0 && frame.contains("ortho_height")
                                      ? number_at(frame, "ortho_height", path, where)
                                      : file.ortho_height;
      if (file.ortho_height > 0.0 && !(ortho_height > 0.0))
        throw InputError({path}, where + "'s ortho_height must be above 0", InputProblem::kMalformed);
      camera = Camera{eye, eye + forward * (along > 0.0 ? along : glm::length(centre - eye) + 1.0), up, file.fovy_deg,
                      placement.length(ortho_height)};
      lights_at(frame, "light_positions", true);
    }
    const auto finite = [](const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); };
    if (!finite(camera.eye) || !finite(camera.target) || !finite(camera.up))
      throw InputError({path}, where + "'s camera lies beyond what double precision holds, placed with the model",
                       InputProblem::kMalformed);
    if (camera.eye == camera.target || !(camera.fovy_deg > 0.0 && camera.fovy_deg < 180.0) || !std::isfinite(camera.ortho_height) ||
        !(glm::length(glm::cross(camera.target - camera.eye, camera.up)) > 0.0))
      throw InputError({path}, where + "'s camera looks nowhere: its eye is its target, its up is along its view or its fovy is not "
                               "between 0 and 180 degrees", InputProblem::kMalformed);
    for (const glm::dvec3& l : shot.lights)
      if (!finite(l))
        throw InputError({path}, where + "'s lights lie beyond what double precision holds, placed with the model",
                         InputProblem::kMalformed);
    shot.camera = camera;
    shots.push_back(std::move(shot));
  }
  return shots;
}

void require_lights_off_casters(Scene& scene, const std::vector<Shot>& shots) {
  const Shot placed = shot_of(scene);
  for (const Shot& shot : shots) {
    place_shot(scene, shot);
    require_lights_off_casters(static_cast<const Scene&>(scene));
  }
  place_shot(scene, placed);
}

void draw_views(Scene& scene, const std::vector<Shot>& shots, const MeshPlacement& placement,
                const RenderSettings& settings, const std::vector<DataPass>& passes, std::optional<HeadlessContext>& context,
                HeadlessGl gl, const std::function<void(int, DrawnView&&)>& each) {
  const auto asked = [&](DataPass p) { return std::count(passes.begin(), passes.end(), p) > 0; };
  const bool surface = asked(DataPass::kDepth) || asked(DataPass::kNormal) || asked(DataPass::kObject);
  std::optional<RayCaster> caster;
  // One hierarchy over the surfaces, which no view moves, for the passes'
  // rays and the edges' (where the GL's frame does not take every sample).
  // It pads its boxes by the largest coordinate a ray starts from: built
  // with the camera whose rays start furthest out.
  if (surface || settings.antialias != settings.frame_samples()) {
    const Camera placed = scene.camera;
    scene.camera = std::max_element(shots.begin(), shots.end(), [](const Shot& a, const Shot& b) {
      return RayCaster::farthest_ray_start(a.camera) < RayCaster::farthest_ray_start(b.camera);
    })->camera;
    caster.emplace(scene);
    scene.camera = placed;
  }
  PictureRequest request;
  request.every_mask = asked(DataPass::kShadow);
  draw_pictures(scene, shots, settings, request, context, gl, caster ? &*caster : nullptr, [&](size_t i, DrawnPicture&& drawn) {
    DrawnView view{std::move(drawn.image), std::move(drawn.masks), {}};
    if (surface) {
      view.surface = surface_passes(scene, *caster, 0, settings.width, settings.height);
      for (float& d : view.surface.depth) d = float(placement.file_length(d));  // infinity stays
      for (glm::vec3& n : view.surface.normal) n = glm::vec3(placement.file_direction(glm::dvec3(n)));
    }
    each(int(i), std::move(view));
  });
}

std::string view_stem(int index, int count) {
  const int digits = std::max(3, int(std::to_string(std::max(0, count - 1)).size()));
  std::string stem = std::to_string(index);
  return std::string(size_t(std::max(0, digits - int(stem.size()))), '0') + stem;
}

}  // namespace umbra
