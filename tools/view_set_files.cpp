#include "tools/view_set_files.hpp"

#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "image/exr_file.hpp"
#include "image/partial_file.hpp"
#include "image/picture_file.hpp"
#include "mesh/io/mapped_file.hpp"
#include "scene/mesh_placement.hpp"
#include "scene/scene_checks.hpp"
#include "tools/command_line.hpp"
#include "tools/progress_bar.hpp"

namespace umbra {
namespace {

// The files of one view, made before it is drawn and renamed into place together.
class ViewFiles {
 public:
  ViewFiles(const std::filesystem::path& folder, const std::string& stem, const std::vector<DataPass>& passes, size_t lights) {
    const auto add = [&](const std::string& name, const char* what) { files_.emplace_back((folder / name).string(), what); };
    add(stem + ".png", "the picture");
    for (const DataPass pass : passes) {
      const DataPassRow& row = data_pass_row(pass);
      if (pass == DataPass::kShadow && lights > 1)
        for (size_t l = 0; l < lights; ++l) add(stem + "." + row.name + std::to_string(l + 1) + row.extension, "a shadow mask");
      else
        add(stem + "." + row.name + row.extension, row.name);
    }
  }

  void write(const DrawnView& view, const std::vector<DataPass>& passes) {
    size_t next = 0;
    write_picture_into(view.color, files_[next++]);
    const SurfacePasses& s = view.surface;
    for (const DataPass pass : passes) switch (pass) {
        case DataPass::kDepth:
          write_exr_into(s.depth, s.width, s.height, {"Z"}, files_[next++]);
          break;
        case DataPass::kNormal: {
          std::vector<float> rgb;
          rgb.reserve(s.normal.size() * 3);
          for (const glm::vec3& n : s.normal) rgb.insert(rgb.end(), {n.x, n.y, n.z});
          write_exr_into(rgb, s.width, s.height, {"R", "G", "B"}, files_[next++]);
          break;
        }
        case DataPass::kObject: {
          Image object(s.width, s.height, 1);
          object.pixels = s.object;
          write_picture_into(object, files_[next++]);
          break;
        }
        case DataPass::kShadow:
          for (const Image& mask : view.shadow) write_picture_into(mask, files_[next++]);
          break;
      }
  }

  void commit() {
    for (PartialFile& f : files_) f.commit();
  }

 private:
  std::deque<PartialFile> files_;  // PartialFile stays where it is made
};

}  // namespace

WrittenViews write_view_files(const std::string& mesh_path, const std::string& folder, PictureChoices choices,
                              const ViewSetRequest& request, const TextureMaps& maps, std::optional<HeadlessContext>& context,
                              const ViewProgress& progress, std::string& messages) {
  namespace fs = std::filesystem;
  // A file umbra would stage, not a scene: its views stand round its model.
  if (!is_mesh_file(mesh_path))
    throw InputError({mesh_path}, "views are drawn of a mesh file on its own, which umbra stages; this is not one (a scene has its "
                                  "own camera)", InputProblem::kUnsupportedFormat);
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) throw std::runtime_error(folder + ": cannot make the folder: " + ec.message());
  RenderSettings& settings = choices.settings;
  if (progress) progress(0, 1, "loading " + mesh_path);
  // The cameras file is read first: a bad one stops the run before the
  // model's load, and its size is the picture's, which staging weighs.
  std::optional<TransformsFile> given;
  if (request.cameras) {
    given = read_transforms(std::string(MappedFile(*request.cameras).bytes()), *request.cameras);
    if (!choices.size_given) settings.width = given->width, settings.height = given->height, choices.size_given = true;
  }
  Scene scene = parse_scene_or_mesh_file(mesh_path, {}, nullptr, staging_for(choices.staging, settings), maps);
  const MeshPlacement placement = placement_of(scene.meshes.at(0));
  set_picture_size(settings, choices.size_given, scene);
  const int count = given ? int(given->count()) : request.count;
  set_picture_samples(settings, choices.antialias, choices.antialias_all, choices.show_volumes, scene, size_t(count));
  require_drawable_size(settings.width, settings.height, settings.frame_samples());
  for (const Warning& w : scene.warnings) messages += w.where.str() + ": warning: " + w.message + "\n";
  require_lights_off_casters(scene);
  require_caught_shadows_kept(scene, settings.method);
  const std::vector<Camera> cameras =
      given ? cameras_of(*given, scene, placement)
            : view_cameras(scene, choices.staging.view, double(settings.width) / settings.height, count, request.spread);
  std::vector<std::string> stems;
  for (int i = 0; i < count; ++i) stems.push_back(view_stem(i, count));
  PartialFile transforms((fs::path(folder) / "transforms.json").string(), "the cameras");
  const auto drawing = [&](int i) { return "drawing view " + std::to_string(i + 1) + " of " + std::to_string(count); };
  if (progress) progress(0, size_t(count), drawing(0));
  draw_views(scene, cameras, placement, settings, request.passes, context, choices.gl, [&](int i, DrawnView&& view) {
    if (progress && i + 1 < count) progress(size_t(i) + 1, size_t(count), drawing(i + 1));
    ViewFiles files(folder, stems[size_t(i)], request.passes, scene.lights.size());
    files.write(view, request.passes);
    files.commit();
  });
  {
    std::ofstream out(transforms.temporary_path());
    out << transforms_json(cameras, scene, placement, settings.width, settings.height, request.passes, stems).dump(2) << "\n";
    if (!out.flush()) throw std::runtime_error(transforms.path() + ": cannot write the cameras");
  }
  transforms.commit();
  size_t triangles = scene.triangles.size();
  for (const Mesh& m : scene.meshes) triangles += m.triangles.size();
  return {count, settings.width, settings.height, triangles};
}

int write_view_set(const std::string& mesh_path, const std::string& folder, PictureChoices choices, const ViewSetRequest& request,
                   bool any_texture_path, const std::string& shown) {
  std::string messages;  // the mesh's warnings, said before any error
  try {
    std::optional<ProgressBar> bar;
    std::optional<HeadlessContext> context;
    const WrittenViews written = write_view_files(mesh_path, folder, choices, request, TextureMaps{true, "", any_texture_path},
                                                  context, [&](size_t done, size_t total, const std::string& what) {
      if (!bar || done == 0) bar.emplace(total);
      if (!messages.empty()) bar->clear(), std::cerr << messages, messages.clear();
      bar->update(done, what);
    }, messages);
    bar.reset();
    std::cerr << messages;
    std::cout << "wrote " << written.views << (written.views == 1 ? " view" : " views") << " of " << shown << " ("
              << written.width << "x" << written.height << ") and their cameras to "
              << (std::filesystem::path(folder) / "transforms.json").string() << "\n";
    return 0;
  } catch (const std::exception&) {
    return render_failure_status(choices.settings, messages);
  }
}

}  // namespace umbra
