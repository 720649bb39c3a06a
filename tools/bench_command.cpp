#include "tools/bench_command.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>
#include <optional>
#include <tuple>

#include "scene/scene_checks.hpp"
#include "scene/scene_parser.hpp"
#include "render/headless_context.hpp"
#include "image/mask_error.hpp"
#include "reference/ray_cast_render.hpp"
#include "render/render_plan.hpp"
#include "render/shadow_renderer.hpp"
#include "tools/bench_report.hpp"
#include "tools/command_line.hpp"
#include "tools/progress_bar.hpp"

namespace umbra {

const std::string kBenchUsage =
    R"(usage: umbra bench [SCENES...] [options]

Shows what accuracy costs in time. For each scene, method and sphere N, it
renders every light's shadow mask and counts the surface pixels whose class
(lit or unlit) differs from the ray-cast reference (exact shadow rays, true
spheres); and it times whole frames (the plan's volumes, every pass, until
the GL has finished): the median of --frames frames after 3 warm-up frames.
It prints a Markdown table on stdout (its last column: the frame time over
zfail's at the same N, or for raycast and shadowmap at the largest N) and a
progress bar on stderr.

With no SCENES, every scenes/*.scene under the current folder, or where
none is, every example scene installed with umbra (share/umbra/scenes).
The defaults measure a few points of each curve, in well under a minute on
a CPU for the bundled scenes; --full sweeps them all (about 2 minutes).

Methods, measured in the order umbra render --help lists them:
{bench methods}.
The reference is labelled "reference": it has no error of its own. A method
whose first frame takes over 250 ms is timed over 3 frames after that one.

options:
{options}
A bad scene is reported as FILE:LINE:COL: message before anything is
measured; nothing is written and the exit status is 1. A usage error exits
with 2.
)";

namespace {

struct BenchOptions {
  std::vector<std::string> scenes;
  int width = 400, height = 400;
  // A few points of each curve by default; with --full, the whole sweep.
  int frames = 5;
  std::vector<int> segments = {16, 64, 256};
  std::vector<int> map_sizes = {512, 2048};
  std::optional<std::string> csv, plot;
  HeadlessGl gl = HeadlessGl::kAuto;
};

constexpr int kWarmUpFrames = 3;
constexpr double kSlowFrameMs = 250.0;
constexpr int kSlowFrames = 3;

std::vector<int> parse_int_list(const std::string& option, const std::string& text, int lowest, int highest) {
  std::vector<int> list;
  size_t start = 0;
  while (start <= text.size()) {
    const size_t comma = std::min(text.find(',', start), text.size());
    list.push_back(parse_int_in(option, text.substr(start, comma - start), lowest, highest));
    start = comma + 1;
  }
  return list;
}

BenchOptions parse_bench_options(const std::vector<std::string>& argv) {
  BenchOptions o;
  CommandOptions options;
  // Each default said once: the few points of each curve, and --full's sweep.
  BenchOptions full_sweep;
  full_sweep.frames = 21, full_sweep.segments = {8, 16, 32, 64, 128, 256}, full_sweep.map_sizes = {256, 512, 1024, 2048, 4096};
  const auto list = [](const std::vector<int>& numbers) {
    std::string text;
    for (const int n : numbers) text += (text.empty() ? "" : ",") + std::to_string(n);
    return text;
  };
  static constexpr ValueRange kFrames{1, 1000}, kSegments{3, 4096}, kMapSizes{16, 8192};
  add_size_option(options, o.width, o.height, "image size (default " + std::to_string(o.width) + "x" + std::to_string(o.height) + ")");
  std::optional<int> frames;
  std::optional<std::vector<int>> segments, map_sizes;
  bool full = false;
  options.value("--frames",
                ranged({"K", "timed frames per measurement (default {default}; " + std::to_string(full_sweep.frames) +
                                 " with --full; {range})"},
                       kFrames, o.frames),
                [&](const std::string& n, const std::string& t) { frames = parse_int_in(n, t, kFrames); });
  options.value("--segments",
                ranged({"LIST", "the sphere N to try, comma-separated (default " + list(o.segments) + "; " + list(full_sweep.segments) +
                                    " with --full; each {range})"},
                       kSegments, 0),
                [&](const std::string& n, const std::string& t) {
                  segments = parse_int_list(n, t, int(kSegments.lowest), int(kSegments.highest));
                });
  options.value("--map-sizes",
                ranged({"LIST", "the shadow map sizes to try, comma-separated (default " + list(o.map_sizes) + "; " +
                                    list(full_sweep.map_sizes) + " with --full; each {range})"},
                       kMapSizes, 0),
                [&](const std::string& n, const std::string& t) {
                  map_sizes = parse_int_list(n, t, int(kMapSizes.lowest), int(kMapSizes.highest));
                });
  options.flag("--full", full, "the whole sweep, with more frames each");
  add_gl_option(options, o.gl);
  options.value("--csv", {"OUT.csv", "also write the rows as CSV"}, [&](const std::string&, const std::string& t) { o.csv = t; });
  options.value("--plot",
                {"OUT.png", "also plot error against frame time, a panel per scene and a curve per method (needs gnuplot); OUT.txt "
                            "plots as text"},
                [&](const std::string&, const std::string& t) { o.plot = t; });
  options.help_option();
  options.positionals(o.scenes);
  options.parse(argv);
  if (full) o.frames = full_sweep.frames, o.segments = full_sweep.segments, o.map_sizes = full_sweep.map_sizes;
  o.frames = frames.value_or(o.frames);
  o.segments = segments.value_or(o.segments);
  o.map_sizes = map_sizes.value_or(o.map_sizes);
  o.gl = gl_with_environment(o.gl);
  if (o.scenes.empty()) {
    // The source tree's, where umbra runs in one; else the installed ones.
    std::error_code ec;
    const std::filesystem::path installed =
        std::filesystem::read_symlink("/proc/self/exe", ec).parent_path() / UMBRA_SCENES_FROM_BINDIR;
    for (const std::filesystem::path& folder : {std::filesystem::path("scenes"), installed}) {
      for (const auto& entry : std::filesystem::directory_iterator(folder, ec))
        if (entry.path().extension() == ".scene") o.scenes.push_back(entry.path().string());
      if (!o.scenes.empty()) break;
    }
    std::sort(o.scenes.begin(), o.scenes.end());
    if (o.scenes.empty())
      throw UsageError("no scenes given, and no scenes/*.scene in the current folder or " + installed.lexically_normal().string());
  }
  if (o.plot) {
    const auto ext = std::filesystem::path(*o.plot).extension();
    if (ext != ".png" && ext != ".txt") throw UsageError("--plot writes OUT.png or OUT.txt, got \"" + *o.plot + "\"");
  }
  return o;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

template <typename Frame>
double frame_ms(Frame& frame) {
  const auto start = std::chrono::steady_clock::now();
  frame();
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The median of `frames` frames after warm-up ones; a slow method (its first
// frame over kSlowFrameMs) gets only kSlowFrames after that first one.
// Returns the number of frames timed too.
template <typename Frame>
std::pair<double, int> median_frame_ms(int frames, Frame frame) {
  int warm_up = kWarmUpFrames - 1;
  if (frame_ms(frame) > kSlowFrameMs) warm_up = 0, frames = std::min(frames, kSlowFrames);
  for (int i = 0; i < warm_up; ++i) frame();
  std::vector<double> ms;
  for (int i = 0; i < frames; ++i) ms.push_back(frame_ms(frame));
  return {median(ms), frames};
}

struct Measurement {
  RenderMethod method;
  int segments;  // 0: the scene has no sphere, N changes nothing
  int map_size = 0;
};

std::vector<Measurement> measurements_for(const Scene& scene, const BenchOptions& o) {
  const std::vector<int>& segments = o.segments;
  std::vector<Measurement> list;
  for (const RenderMethod m : all_methods()) {  // in the method table's order, each as the table says
    switch (method_bench_sweep(m)) {
      case BenchSweep::kReference:  // measured first, on its own
        break;
      case BenchSweep::kMapSizes:
        for (const int size : o.map_sizes) list.push_back({m, 0, size});
        break;
      case BenchSweep::kSegmentsWithMeshes:
        if (scene.meshes.empty()) break;
        [[fallthrough]];
      case BenchSweep::kSphereSegments:
        if (scene.spheres.empty()) list.push_back({m, 0});
        else
          for (const int n : segments) list.push_back({m, n});
        break;
    }
  }
  return list;
}

std::vector<BenchRow> bench_scene(const Scene& scene, const std::vector<MeshCaster>& meshes, const BenchOptions& o,
                                  ProgressBar& progress) {
  const std::string name = std::filesystem::path(scene.path).filename().string();
  std::vector<BenchRow> rows;
  const std::string reference_name = method_name(RenderMethod::kRaycast);
  progress.step(name + " " + reference_name + " (the reference)");
  RayCastFrame reference;  // the last timed frame is the reference
  BenchRow ray{name, reference_name};
  ray.reference = true;
  std::tie(ray.median_ms, ray.frames) =
      median_frame_ms(o.frames, [&] { reference = ray_cast_frame(scene, o.width, o.height); });
  for (const Image& mask : reference.masks) ray.surface_pixels += mask_error(mask, mask).surface_pixels;

  for (const Measurement& m : measurements_for(scene, o)) {
    BenchRow row{name, method_name(m.method), m.segments, m.map_size};
    progress.step(name + " " + row.method + " " + row.parameter());
    RenderSettings settings;
    settings.width = o.width;
    settings.height = o.height;
    settings.method = m.method;
    if (m.segments) settings.sphere_segments = m.segments;
    if (m.map_size) settings.shadow_map_size = m.map_size;
    RenderPlan plan = make_render_plan(scene, meshes, settings);
    ShadowRenderer renderer(scene, plan, DrawSending::kWhole);
    std::tie(row.median_ms, row.frames) = median_frame_ms(o.frames, [&] {
      update_render_plan(scene, meshes, plan);
      renderer.draw(false);
      renderer.finish();
    });
    MaskError error;
    for (size_t light = 0; light < scene.lights.size(); ++light)
      error += mask_error(reference.masks[light], renderer.render_mask(light));
    row.wrong_pixels = error.wrong_pixels;
    row.surface_pixels = error.surface_pixels;
    rows.push_back(row);
  }
  rows.push_back(ray);
  return rows;
}

}  // namespace

int run_bench_command(const std::vector<std::string>& argv) {
  BenchOptions options;
  if (const auto exit_status = parse_command_line("bench", kBenchUsage, argv, parse_bench_options, options))
    return *exit_status;
  try {
    if (options.plot && !gnuplot_available())
      throw std::runtime_error("--plot needs gnuplot, which is not installed (Debian: apt-get install gnuplot-nox)");
    // Every scene is read and checked before anything is measured.
    std::vector<Scene> scenes;
    int total = 0;
    for (const std::string& path : options.scenes) {
      scenes.push_back(parse_scene_file(path));
      require_lights_off_casters(scenes.back());
      total += 1 + int(measurements_for(scenes.back(), options).size());
    }
    std::vector<BenchRow> rows;
    const HeadlessContext context(options.width, options.height, options.gl);
    {
      ProgressBar progress{size_t(total)};
      for (const Scene& scene : scenes) {
        const std::vector<BenchRow> scene_rows = bench_scene(scene, prepare_mesh_casters(scene), options, progress);
        rows.insert(rows.end(), scene_rows.begin(), scene_rows.end());
      }
    }
    std::cout << "OpenGL: " << context.description() << "\n\n";
    write_markdown_table(std::cout, rows, options.width, options.height);
    if (options.csv) write_csv(rows, options.width, options.height, *options.csv);
    if (options.plot) write_plot(rows, *options.plot);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
}

}  // namespace umbra
