#include "tools/batch_render.hpp"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <thread>

#include <tbb/global_control.h>

#include "image/contact_sheet.hpp"
#include "image/image.hpp"
#include "mesh/input_error.hpp"
#include "reference/ray_cast_render.hpp"
#include "render/headless_context.hpp"
#include "render/shadow_renderer.hpp"
#include "scene/scene_checks.hpp"
#include "scene/staged_scene.hpp"
#include "tools/command_line.hpp"
#include "tools/picture_names.hpp"
#include "tools/progress_bar.hpp"

namespace umbra {
namespace {

constexpr int kSheetThumbWidth = 200;  // a contact sheet's tiles, in pixels

// One file's picture, drawn in the worker's own GL context (made on first
// use, then kept for every file it draws); its warnings and error, if any.
struct Outcome {
  std::string err;
  bool written = false;
};

}  // namespace

int default_supersampling(const std::string& path) { return is_mesh_file(path) ? 3 : 1; }

namespace {

Outcome render_one(const std::string& path, const std::string& root, const std::string& out, const BatchRenderOptions& o,
                   std::optional<HeadlessContext>& context) {
  Outcome outcome;
  try {
    if (const std::string what = neither_scene_nor_mesh(path); !what.empty()) throw InputError({path}, what);
    Scene scene = parse_scene_or_mesh_file(path, {}, nullptr, o.up, TextureMaps{true, root, o.any_texture_path});
    for (const Warning& w : scene.warnings) outcome.err += w.where.str() + ": warning: " + w.message + "\n";
    rotate_lights_about_z(scene, o.light_angle_deg);
    require_lights_off_casters(scene);
    RenderSettings settings = o.settings;
    settings.supersampling = o.antialias.value_or(default_supersampling(path));
    Image image;
    if (settings.method == RenderMethod::kRaycast) {
      image = ray_cast_frame(scene, settings.width, settings.height, settings.supersampling).image;
    } else {
      if (!context) context.emplace(settings.width, settings.height, o.gl);
      const RenderPlan plan = make_render_plan(scene, settings);
      ShadowRenderer renderer(scene, plan);
      image = renderer.render_image(o.show_volumes);
    }
    std::filesystem::create_directories(std::filesystem::path(out).parent_path());
    write_png(image, out);
    outcome.written = true;
  } catch (const std::exception& e) {
    outcome.err += std::string(e.what()) + "\n";
  }
  return outcome;
}

}  // namespace

int run_batch_render(const BatchRenderOptions& o) {
  MeshPaths found;
  try {
    found = expand_mesh_paths(o.paths);
    if (found.meshes.empty()) throw UsageError("no mesh files in " + o.paths[0] + (o.paths.size() > 1 ? " or the others" : ""));
  } catch (const UsageError& e) {
    std::cerr << "umbra render: " << e.what() << "\n";
    return 2;
  }
  // Said once for all the shards: by the first.
  if (o.shard && o.shard->index > 0) found.passed_over.clear();
  for (const auto& [path, what] : found.passed_over) std::cerr << "umbra render: passed over " << path << ": " << what << ", not a mesh\n";
  // Named for all the files, before the shards part: every shard names alike.
  const std::vector<std::string> all_names = distinct_picture_names(found.meshes, found.names, found.roots);
  const std::vector<std::string> files = o.shard ? shard_of(found.meshes, *o.shard) : found.meshes;
  const std::vector<std::string> names = o.shard ? shard_of(all_names, *o.shard) : all_names;
  const std::vector<std::string> roots = o.shard ? shard_of(found.roots, *o.shard) : found.roots;
  const auto picture_path = [&](size_t i) { return (std::filesystem::path(o.out_dir) / (names[i] + ".png")).string(); };
  const auto start = std::chrono::steady_clock::now();
  // --jobs bounds the threads of the whole process, as in umbra check.
  const tbb::global_control threads(tbb::global_control::max_allowed_parallelism, o.jobs);
  const size_t count = files.size();
  std::atomic<size_t> next{0};
  std::mutex print_mutex;
  size_t finished = 0, written = 0;
  std::vector<char> drawn(count, 0);  // this run's pictures: the sheet shows no other
  ProgressBar progress(count);
  const auto work = [&] {
    std::optional<HeadlessContext> context;
    for (size_t i = next++; i < count; i = next++) {
      const Outcome outcome = render_one(files[i], roots[i], picture_path(i), o, context);
      const std::lock_guard<std::mutex> lock(print_mutex);
      progress.clear();
      std::cerr << outcome.err << std::flush;
      written += outcome.written;
      drawn[i] = outcome.written;
      progress.update(++finished, files[i]);
    }
  };
  std::vector<std::thread> workers;
  for (size_t j = 1; j < std::min(o.jobs, count); ++j) workers.emplace_back(work);
  work();
  for (std::thread& t : workers) t.join();
  progress.clear();
  bool sheet_failed = false;
  if (o.sheet) {
    // The pictures just written, read back in file order: held one at a
    // time while drawing, so that a folder of large pictures fits in memory.
    std::vector<SheetPicture> sheet;
    for (size_t i = 0; i < count; ++i) {
      if (!drawn[i]) continue;  // it failed: an older picture of it is not this run's
      const std::string out = picture_path(i);
      try {
        sheet.push_back({names[i], thumbnail(read_png(out), kSheetThumbWidth)});
      } catch (const std::exception& e) {
        std::cerr << e.what() << "\n";
      }
    }
    try {
      write_png(contact_sheet(sheet, kSheetThumbWidth), *o.sheet);
      std::cerr << "umbra render: wrote the contact sheet " << *o.sheet << " (" << sheet.size() << " pictures)\n";
    } catch (const std::exception& e) {
      std::cerr << e.what() << "\n";
      sheet_failed = true;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  char elapsed[32];
  std::snprintf(elapsed, sizeof elapsed, "%.1f s", seconds);
  std::cerr << "umbra render: " << count << (count == 1 ? " file" : " files")
            << (o.shard ? " (shard " + std::to_string(o.shard->index) + "/" + std::to_string(o.shard->count) + " of " +
                              std::to_string(found.meshes.size()) + ")"
                        : "")
            << " in " << elapsed << ": " << written << (written == 1 ? " picture" : " pictures") << " in " << o.out_dir << ", "
            << count - written << " failed\n";
  return written == count && !sheet_failed ? 0 : 1;
}

}  // namespace umbra
