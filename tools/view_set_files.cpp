#include "tools/view_set_files.hpp"

#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "image/animation_file.hpp"
#include "image/exr_file.hpp"
#include "image/partial_file.hpp"
#include "image/picture_file.hpp"
#include "tools/command_line.hpp"
#include "tools/encoding_thread.hpp"
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

WrittenViews write_view_files(const std::string& mesh_path, const std::string& folder, const PictureChoices& choices,
                              const ViewSetRequest& request, const ReadOptions& maps, std::optional<HeadlessContext>& context,
                              const ViewProgress& progress, std::string& messages) {
  namespace fs = std::filesystem;
  PreparedViews prepared = prepare_views(mesh_path, choices, request, maps, progress, messages);
  std::error_code ec;
  fs::create_directories(folder, ec);  // once the file is known to make views
  if (ec) throw std::runtime_error(folder + ": cannot make the folder: " + ec.message());
  Scene& scene = prepared.scene;
  const RenderSettings& settings = prepared.settings;
  const int count = int(prepared.shots.size());
  std::vector<std::string> stems;
  for (int i = 0; i < count; ++i) stems.push_back(view_stem(i, count));
  PartialFile transforms((fs::path(folder) / "transforms.json").string(), "the cameras");
  const char* what = prepared.turning == Turning::kNone ? "view" : "frame";
  const auto drawing = [&](int i) { return std::string("drawing ") + what + " " + std::to_string(i + 1) + " of " + std::to_string(count); };
  if (progress) progress(0, size_t(count), drawing(0));
  draw_views(scene, prepared.shots, prepared.placement, settings, request.passes, context, choices.gl, [&](int i, DrawnView&& view) {
    if (progress && i + 1 < count) progress(size_t(i) + 1, size_t(count), drawing(i + 1));
    ViewFiles files(folder, stems[size_t(i)], request.passes, scene.lights.size());
    files.write(view, request.passes);
    files.commit();
  });
  {
    std::ofstream out(transforms.temporary_path());
    out << transforms_json(prepared.shots, scene, prepared.placement, settings.width, settings.height, request.passes, stems,
                           prepared.turning)
               .dump(2)
        << "\n";
    if (!out.flush()) throw std::runtime_error(transforms.path() + ": cannot write the cameras");
  }
  transforms.commit();
  return {count, settings.width, settings.height, prepared.triangles()};
}

WrittenViews write_animation_file(const std::string& path, const std::string& output, const PictureChoices& choices,
                                  const ViewSetRequest& request, const AnimationRequest& animation, const ReadOptions& maps,
                                  std::optional<HeadlessContext>& context, const ViewProgress& progress, std::string& messages) {
  PartialFile file(output, "the animation", PartialFile::Ending::kKeepExtension);
  PreparedViews prepared = prepare_views(path, choices, request, maps, progress, messages);
  const RenderSettings& settings = prepared.settings;
  if (animation.format == AnimationFormat::kMp4 && (settings.width % 2 != 0 || settings.height % 2 != 0))
    throw UsageError("an MP4 video's frames (yuv420p) have an even width and height; the picture is " + std::to_string(settings.width) +
                     "x" + std::to_string(settings.height) + ": give --size with even sides");
  const std::unique_ptr<AnimationWriter> writer = open_animation(
      animation.format, file.temporary_path(), output, {settings.width, settings.height, animation.fps, animation.quality});
  const int count = int(prepared.shots.size());
  const auto drawing = [&](int i) { return "drawing frame " + std::to_string(i + 1) + " of " + std::to_string(count); };
  if (progress) progress(0, size_t(count), drawing(0));
  EncodingThread encoding(*writer);
  draw_views(prepared.scene, prepared.shots, prepared.placement, settings, {}, context, choices.gl, [&](int i, DrawnView&& view) {
    if (progress && i + 1 < count) progress(size_t(i) + 1, size_t(count), drawing(i + 1));
    encoding.add(std::move(view.color));
  });
  if (progress) progress(size_t(count), size_t(count), "encoding");
  encoding.finish();
  file.commit();
  return {count, settings.width, settings.height, prepared.triangles()};
}

int write_view_set(const std::string& path, const std::string& output, PictureChoices choices, const ViewSetRequest& request,
                   const std::optional<AnimationRequest>& animation, const ReadOptions& maps, const std::string& shown) {
  std::string messages;  // the mesh's warnings, said before any error
  try {
    std::optional<ProgressBar> bar;
    std::optional<HeadlessContext> context;
    const ViewProgress progress = [&](size_t done, size_t total, const std::string& what) {
      if (!bar || done == 0) bar.emplace(total);
      if (!messages.empty()) bar->clear(), std::cerr << messages, messages.clear();
      bar->update(done, what);
    };
    const WrittenViews written = animation
                                     ? write_animation_file(path, output, choices, request, *animation, maps, context, progress, messages)
                                     : write_view_files(path, output, choices, request, maps, context, progress, messages);
    bar.reset();
    std::cerr << messages;
    const std::string what = request.turning == Turning::kNone ? " view" : " frame";
    std::cout << "wrote " << written.views << what << (written.views == 1 ? "" : "s") << " of " << shown << " (" << written.width
              << "x" << written.height << ")";
    if (animation)
      std::cout << " to " << output << ", " << animation_row(animation->format).name << "\n";
    else
      std::cout << " and their cameras to " << (std::filesystem::path(output) / "transforms.json").string() << "\n";
    return 0;
  } catch (const std::exception&) {
    return render_failure_status(choices.settings, messages);
  }
}

}  // namespace umbra
