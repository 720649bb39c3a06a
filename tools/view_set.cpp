#include "tools/view_set.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "reference/ray_caster.hpp"
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

std::vector<Camera> view_cameras(const Scene& staged, const StageView& view, double aspect, int count, ViewSpread spread) {
  const Mesh& mesh = staged.meshes.at(0);
  const Camera& first = staged.camera;
  // The staged camera's own direction from what it looks at: its azimuth
  // and elevation in StageView's convention.
  const glm::dvec3 back = glm::normalize(first.eye - first.target);
  const double azimuth = glm::degrees(std::atan2(back.x, -back.y)), elevation = glm::degrees(std::asin(back.z));
  std::vector<Camera> cameras{first};
  const std::vector<glm::dvec3> points = framing_points(mesh);
  StageView turned = view;
  turned.light = staged.lights.at(0).position;  // held still in the model's frame
  turned.light_turn_deg = 0.0;
  turned.light_azimuth_deg = turned.light_elevation_deg = std::nullopt;
  turned.eye = turned.target = std::nullopt;
  // The golden angle: each view on the sphere turns by it from the last.
  const double golden_deg = 180.0 * (3.0 - std::sqrt(5.0));
  for (int i = 1; i < count; ++i) {
    if (spread == ViewSpread::kRing) {
      turned.camera_azimuth_deg = azimuth + 360.0 * i / count;
      turned.camera_elevation_deg = elevation;
    } else {
      // Fibonacci lattice: equal areas of the sphere, from near its top to
      // near its bottom; view 0 keeps the staged camera.
      const double z = 1.0 - (2.0 * i + 1.0) / count;
      turned.camera_azimuth_deg = azimuth + golden_deg * i;
      turned.camera_elevation_deg = glm::degrees(std::asin(z));
    }
    cameras.push_back(stage_for(mesh.bounds_min, mesh.bounds_max, points, aspect, turned).camera);
  }
  return cameras;
}

namespace {

// The placement's inverse: scene coordinates back to the mesh file's.
struct FileFrame {
  const MeshPlacement& placement;
  glm::dvec3 point(const glm::dvec3& p) const {
    return glm::transpose(placement.rotation) * (p - placement.translation) / placement.scale + placement.fit_centre;
  }
  glm::dvec3 direction(const glm::dvec3& d) const { return glm::transpose(placement.rotation) * d; }
};

nlohmann::ordered_json row_major(const glm::dmat4& m) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (int r = 0; r < 4; ++r) rows.push_back({m[0][r], m[1][r], m[2][r], m[3][r]});
  return rows;
}

nlohmann::ordered_json point_json(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

}  // namespace

nlohmann::ordered_json transforms_json(const std::vector<Camera>& cameras, const Scene& scene, const MeshPlacement& placement,
                                       int width, int height, const std::vector<DataPass>& passes,
                                       const std::vector<std::string>& stems) {
  const FileFrame file{placement};
  const Camera& lens = cameras.at(0);
  const double focal = lens.focal_length_pixels(height);
  nlohmann::ordered_json json;
  json["camera_angle_x"] = 2.0 * std::atan(width / (2.0 * focal));
  json["camera_angle_y"] = 2.0 * std::atan(height / (2.0 * focal));
  json["fl_x"] = focal;
  json["fl_y"] = focal;
  json["cx"] = width / 2.0;
  json["cy"] = height / 2.0;
  json["w"] = width;
  json["h"] = height;
  json["camera_model"] = "PINHOLE";
  nlohmann::ordered_json frames = nlohmann::ordered_json::array();
  for (size_t i = 0; i < cameras.size(); ++i) {
    const Camera& c = cameras[i];
    const CameraAxes a = c.axes();
    // Camera to the file's world: its axes (x right, y up, z back) and eye
    // in the file's coordinates; rigid, as the placement's scale is uniform.
    glm::dmat4 pose(1.0);
    pose[0] = glm::dvec4(file.direction(a.right), 0.0);
    pose[1] = glm::dvec4(file.direction(a.up), 0.0);
    pose[2] = glm::dvec4(file.direction(-a.forward), 0.0);
    pose[3] = glm::dvec4(file.point(c.eye), 1.0);
    nlohmann::ordered_json frame;
    frame["file_path"] = stems[i] + ".png";
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
    nlohmann::ordered_json lights = nlohmann::ordered_json::array();
    for (const Light& l : scene.lights) lights.push_back(point_json(file.point(l.position)));
    frame["light_positions"] = lights;
    // The camera as umbra placed it, in the staged scene's coordinates: --cameras draws it again exactly.
    frame["umbra_camera"] = {{"eye", point_json(c.eye)}, {"target", point_json(c.target)}, {"up", point_json(c.up)}, {"fovy", c.fovy_deg}};
    frames.push_back(frame);
  }
  json["frames"] = frames;
  return json;
}

void draw_views(Scene& scene, const std::vector<Camera>& cameras, const MeshPlacement& placement,
                const RenderSettings& settings, const std::vector<DataPass>& passes, std::optional<HeadlessContext>& context,
                HeadlessGl gl, const std::function<void(int, DrawnView&&)>& each) {
  const auto asked = [&](DataPass p) { return std::count(passes.begin(), passes.end(), p) > 0; };
  const bool surface = asked(DataPass::kDepth) || asked(DataPass::kNormal) || asked(DataPass::kObject);
  std::optional<RayCaster> caster;
  // One hierarchy over the surfaces, which no view moves, for the passes'
  // rays and the edges' (where the GL's frame does not take every sample).
  if (surface || settings.antialias != settings.frame_samples()) caster.emplace(scene);
  PictureRequest request;
  request.every_mask = asked(DataPass::kShadow);
  const glm::dmat3 to_file = glm::transpose(placement.rotation);
  draw_pictures(scene, cameras, settings, request, context, gl, caster ? &*caster : nullptr, [&](size_t i, DrawnPicture&& drawn) {
    DrawnView view{std::move(drawn.image), std::move(drawn.masks), {}};
    if (surface) {
      view.surface = surface_passes(scene, *caster, 0, settings.width, settings.height);
      for (float& d : view.surface.depth) d = float(d / placement.scale);  // infinity stays
      for (glm::vec3& n : view.surface.normal) n = glm::vec3(to_file * glm::dvec3(n));
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
