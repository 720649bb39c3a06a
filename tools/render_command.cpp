#include "tools/render_command.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <thread>

#include "mesh/file_extension.hpp"
#include "scene/scene_checks.hpp"
#include "scene/scene_parser.hpp"
#include "scene/staged_scene.hpp"
#include "tools/batch_render.hpp"
#include "render/headless_context.hpp"
#include "image/image.hpp"
#include "image/partial_file.hpp"
#include "image/picture_file.hpp"
#include "render/render_plan.hpp"
#include "tools/command_line.hpp"
#include "tools/freed_memory_reuse.hpp"
#include "tools/huge_page_malloc.hpp"
#include "tools/picture_choices.hpp"
#include "tools/picture_drawing.hpp"
#include "tools/progress_bar.hpp"
#include "tools/standard_input.hpp"
#include "tools/view_set_files.hpp"

namespace umbra {

const std::string kRenderUsage =
    R"(usage: umbra render MESH -o OUT.png [options]
       umbra render SCENE -o OUT.png [options]
       umbra render MESH|PATH... --views N [--passes LIST] -o OUTDIR [options]
       umbra render MESH --cameras transforms.json [--passes LIST] -o OUTDIR
       umbra render PATH --turntable N [--orbit light] -o OUT.mp4|OUTDIR/
       umbra render PATH... -o OUTDIR [--jobs N] [--shard K/N] [options]
       umbra render - -o OUT.png [options]   (a mesh on standard input)

Draws a picture with exact hard shadows from stencil shadow volumes (Crow
1977; Heidmann 1991), headless (EGL or OSMesa), and writes OUT.png. The
sources cited here are listed in docs/references.md.

A mesh file (in any format umbra formats lists) is staged on its own: stood
on a floor in its up axis, lit by one light above and to the left, seen from
a raised three-quarter view that frames it and its shadow. --explain prints
that scene as text to save and edit.

Several files, or a folder (searched for mesh files by their content, as
umbra check searches it), render to one picture each in OUTDIR: a file found
in a folder to OUTDIR/its path in that folder.png, a file named on its own
to OUTDIR/its name.png; files that would share a name take as many of their
folders' names as tell them apart. Files are drawn in worker processes: a
file that fails, crashes or runs out of memory is reported and the rest go
on. Ctrl-C stops the workers, says how many files were not drawn and exits
130; --skip-existing then resumes. A model's texture
maps are read only from inside the folder named (see --any-texture-path).

options:
{options}
Errors in SCENE are printed as FILE:LINE:COL: message; nothing is written
and the exit status is 1, as for a mesh file that cannot be read or has no
faces. A usage error, or a file that is plainly neither a scene nor a mesh
(an image, an archive, binary data), exits with 2. With several files, the
exit status is 1 when any failed.
)";

namespace {

// Whether `path` ends as a picture's name does (.png, .jpg, ...), case aside.
bool is_picture_name(const std::string& path) {
  const std::string extension = lowercase_extension(path);
  for (const char* picture : {".png", ".jpg", ".jpeg", ".webp", ".bmp", ".tif", ".tiff"})
    if (extension == picture) return true;
  return false;
}

// Whether `path` is this process's standard output: "-", or a name of the
// file or pipe it goes to (/dev/stdout, /proc/self/fd/1), where the picture's
// bytes leave no room for words.
bool writes_standard_output(const std::string& path) {
  if (path == "-") return true;
  struct stat out {}, named {};
  return ::fstat(STDOUT_FILENO, &out) == 0 && ::stat(path.c_str(), &named) == 0 && out.st_dev == named.st_dev &&
         out.st_ino == named.st_ino;
}

struct RenderOptions : PictureChoices {
  std::string scene_path;
  std::optional<BatchRenderOptions> batch;  // several files or a folder
  std::string output;
  std::optional<std::string> mask;
  PictureOptions picture;
  bool jpeg_quality_given = false;
  bool explain = false;
  std::optional<std::string> save_scene;  // for a mesh file: where to write the staged scene
  std::optional<ViewSetRequest> views;    // --views, --views-on, --passes, --turntable: many views into the folder -o names
  std::optional<AnimationRequest> animation;  // or into one animation, as -o's name asks
  ReadOptions reading;  // --any-texture-path, --cad-deflection, --cad-angle
};

RenderOptions parse_render_options(const std::vector<std::string>& argv) {
  RenderOptions o;
  std::vector<std::string> scenes;
  CommandOptions options;
  add_output_option(options, o.output,
                    {"OUT", "the image to write, or with several files the folder to write their pictures in (required): its name's "
                            "ending says the format, {picture extensions}; - writes PNG to standard output"});
  std::optional<int> quality;
  static constexpr ValueRange kQuality{1, 100};
  options.value("--quality,--jpeg-quality",
                ranged({"N", "for a .jpg output: {range} (default {default}); for a .webp animation: lossy at that quality (default "
                             "lossless); --jpeg-quality is its older name"},
                       kQuality, o.picture.jpeg_quality),
                [&](const std::string& n, const std::string& t) {
                  quality = parse_int_in(n, t, kQuality);
                  o.picture.jpeg_quality = *quality;
                  o.jpeg_quality_given = true;
                });
  add_picture_choices(options, o);
  options.value("--mask", {"MASK.png", "also write light 1's shadow mask: 8-bit grey, 128 where no surface is seen, 255 where the visible "
                                       "point faces light 1 and is outside its shadow, 0 elsewhere"},
                [&](const std::string&, const std::string& t) { o.mask = t; });
  add_reading_options(options, o.reading, true);
  options.value("--save-scene",
                {"FILE", "for a MESH: also write the scene umbra stages for it, the options' camera, light, floor and background "
                         "included, naming the mesh by its path from FILE's folder: umbra render FILE then draws the same picture"},
                [&](const std::string&, const std::string& t) { o.save_scene = t; });
  options.flag("--explain", o.explain,
               "print the render plan (camera, lights, each caster's volume, how each light's volumes are counted and how far they "
               "reach, the GL, the pages malloc takes) to stdout, after the staged scene's text for a MESH");

  options.paragraph("");
  std::vector<std::string> view_options;  // those named, for messages
  ViewSetRequest views;
  add_noted_value(options, view_options, "--views",
                {"N", "draw N views of a MESH into the folder -o names, round the model at the camera's elevation from its azimuth "
                      "on, evenly spaced; the light holds still. Writes NNN.png per view and transforms.json: each view's camera "
                      "pose and intrinsics in the mesh file's own coordinates and units (docs/rendering.md, \"Many views\"); with "
                      "several files or a folder, each model's views into OUTDIR/its picture's name/, with --jobs, --timeout, "
                      "--skip-existing, --json and --shard"},
                [&](const std::string& n, const std::string& t) {
                  views.count = parse_int_in(n, t, 1, 100000);
                });
  add_noted_value(options, view_options, "--views-on",
                {"SPREAD", "ring (default) or sphere: views evenly over the whole sphere of directions (a Fibonacci lattice), each "
                           "framing the model alone, without a floor unless --floor is given"},
                [&](const std::string& n, const std::string& t) {
                  views.spread = parse_view_spread(n, t);
                });
  add_noted_value(options, view_options, "--cameras",
                {"FILE", "instead of --views, draw the views a transforms.json names (its frames' umbra_camera, else their "
                         "transform_matrix and the intrinsics: square pixels, centred), at its w x h unless --size is given; the file "
                         "--views wrote redraws the same pictures"},
                [&](const std::string&, const std::string& t) { views.cameras = t; });
  add_noted_value(options, view_options, "--passes",
                {"LIST", "with --views or --cameras, each view's data too, comma-separated: depth (NNN.depth.exr, float, along the "
                         "view axis in the file's units, +inf off the model), normal (NNN.normal.exr, float RGB, the file's axes), "
                         "object (NNN.object.png, 255 on the model), shadow (NNN.shadow.png, as --mask; NNN.shadowK.png per light "
                         "where there are several)"},
                [&](const std::string& n, const std::string& t) {
                  views.passes = parse_data_passes(n, t);
                });

  options.paragraph("");
  std::optional<Turning> orbit;
  add_noted_value(options, view_options, "--turntable",
                {"N", "N frames of a motion, the model turning 360/N degrees a frame about its up axis (counter-clockwise seen from "
                      "above) under a studio that holds still, from the camera's azimuth on, framed to hold it all the way round; a "
                      "SCENE turns its own camera and lights. -o names an animation, {animation formats}, or a folder (ending in /) "
                      "for NNN.png frames and transforms.json, as --views writes them (with --passes); --cameras of it draws them "
                      "again"},
                [&](const std::string& n, const std::string& t) {
                  views.count = parse_int_in(n, t, 1, 100000);
                  views.turning = Turning::kModel;
                });
  options.value("--orbit",
                {"WHAT", "with --turntable: model (default), or light: the camera and model hold still and every light orbits the z "
                         "axis, its shadow sweeping"},
                [&](const std::string& n, const std::string& t) {
                  Turning turning = Turning::kNone;
                  if (!parse_turning(t, turning)) throw UsageError(n + " takes model or light, got \"" + t + "\"");
                  orbit = turning;
                });
  std::optional<double> fps;
  add_fps_option(options, fps, "an animation's frames a second");
  std::optional<AnimationFormat> format;  // several files' animations
  options.value("--format",
                {"EXT", "with --turntable and several files: each file's frames as one animation, OUTDIR/its name.EXT: "
                        "{animation names} (without: each file's frames into OUTDIR/its name/)"},
                [&](const std::string& n, const std::string& t) {
                  format = animation_format_of("animation." + t);
                  if (!format) throw UsageError(n + " takes " + animation_extensions(false) + ", got \"" + t + "\"");
                });

  options.paragraph("");
  std::optional<size_t> jobs;
  std::optional<Shard> shard;
  std::optional<std::string> sheet;
  double timeout_s = 0.0;
  bool skip_existing = false, json = false;
  options.value("--jobs",
                {"N", "with several files: draw N at a time, each in its own GL context, using at most N threads in all (default: "
                      "one per core)"},
                [&](const std::string& n, const std::string& t) { jobs = size_t(parse_int_in(n, t, 1, 4096)); });
  options.value("--shard",
                {"K/N", "with several files: draw only part K (counting from 0) of N disjoint parts, as umbra check --shard splits "
                        "them"},
                [&](const std::string& n, const std::string& t) { shard = parse_shard(n, t); });
  options.value("--sheet",
                {"SHEET.png", "with several files: also one picture of this run's pictures (with --views, each model's first view), "
                              "each shrunk to at most 200 pixels wide and labelled with its file's name (.png or .jpg; never an "
                              "input's or a picture's name)"},
                [&](const std::string& n, const std::string& t) {
                  require_picture_name(n, t);
                  if (t == "-") throw UsageError(n + " needs a file: standard output holds --json's lines");
                  sheet = t;
                });
  options.value("--timeout",
                {"SECONDS", "with several files: stop a file's render after this long (its worker is stopped and replaced), report "
                            "it as timed out and go on"},
                [&](const std::string& n, const std::string& t) {
                  timeout_s = parse_finite_number(n, t);
                  if (!(timeout_s > 0.0)) throw UsageError(n + " must be a number of seconds above 0, got \"" + t + "\"");
                });
  options.flag("--skip-existing", skip_existing,
               "with several files: draw only the files whose picture is missing or older than the file, so that a run stopped part "
               "way resumes where it stopped");
  options.flag("--json", json,
               "with several files: one line of JSON per file on stdout: path, picture, status (drawn, skipped, failed, timed out, "
               "crashed, stopped or passed over), kind (of a failure: malformed, unreadable, timeout, out-of-memory, ...), seconds, "
               "triangles and error");
  options.help_option();
  options.positionals(scenes);
  options.parse(argv);
  if (!scenes.empty()) o.scene_path = scenes[0];
  settle_picture_choices(o);
  if (o.scene_path.empty()) throw UsageError("no scene or mesh file given");
  std::error_code ec;
  if (o.scene_path == "-" && ::isatty(STDIN_FILENO))
    throw UsageError("- reads standard input, which is a terminal here: pipe a file in, as in umbra render - -o out.png < model.stl");
  if (scenes.size() > 1 && std::count(scenes.begin(), scenes.end(), "-"))
    throw UsageError("- (standard input) is one file: render it on its own");
  if (o.save_scene && o.scene_path == "-")
    throw UsageError("--save-scene names the mesh's file, and standard input has none: save the mesh to a file first");
  const bool several = scenes.size() > 1 || std::filesystem::is_directory(o.scene_path, ec);
  const auto batch = [&](std::optional<ViewSetRequest> views) {
    return BatchRenderOptions{scenes, o.output, o.settings, o.staging, o.gl, o.antialias, o.antialias_all, o.show_volumes,
                              o.size_given, jobs.value_or(std::max(1u, std::thread::hardware_concurrency())), shard, sheet,
                              o.reading, timeout_s, skip_existing, json, std::move(views), std::nullopt};
  };
  const bool turntable = views.turning != Turning::kNone;
  if (orbit && !turntable) throw UsageError("--orbit says what --turntable turns: give --turntable N");
  if (turntable) views.turning = orbit.value_or(Turning::kModel);
  // -o's name: an animation, or a folder of each picture's files.
  const bool folder_named = !o.output.empty() && (o.output.back() == '/' || std::filesystem::is_directory(o.output, ec));
  if (format && !(several && turntable))
    throw UsageError("--format says which animation --turntable makes of each of several files; -o names one file's");
  std::optional<AnimationFormat> animation = format;
  if (!animation && !folder_named) animation = animation_format_of(o.output);
  if (fps && !animation) throw UsageError("--fps is an animation's pace: name one with -o (" + animation_extensions() + ")");
  if (!view_options.empty()) {
    const std::string& named = view_options.front();
    o.views = views;
    // A motion turns a scene's own camera and lights; views stand round a staged model.
    if (!several && o.scene_path != "-" && !turntable) require_staged({named}, o.scene_path);  // standard input's once read
    if (o.output.empty())
      throw UsageError(turntable ? "no output given (-o OUT" + std::string(animation_row(AnimationFormat::kMp4).extension) +
                                       " or OUTDIR/): --turntable writes its frames there"
                                 : "no output folder given (-o OUTDIR): " + named + " writes each view's files there");
    if (turntable && !folder_named && !animation && !std::filesystem::path(o.output).extension().empty())
      throw UsageError("-o " + o.output + ": --turntable writes " + animation_extensions() +
                       ", or each frame's files into a folder (a name ending in /)");
    if (animation) {
      const AnimationFormatRow& row = animation_row(*animation);
      if (const std::string why = animation_unavailable(*animation); !why.empty()) throw UsageError(why);
      if (!views.passes.empty())
        throw UsageError("--passes writes each picture's data files, which " + std::string(row.name) + " has no room for: name a folder");
      if (o.staging.background && o.staging.background->transparent && !row.alpha)
        throw UsageError("--background transparent needs an alpha channel, which " + std::string(row.name) + " has not: name a .webp");
      if (quality && !row.quality) throw UsageError("--quality is for a .jpg or .webp; " + std::string(row.name) + " takes none");
      if (several && !format)
        throw UsageError("-o " + o.output + " names one animation; several files make one each: name a folder, with --format " +
                         std::string(row.extension + 1));
      if (format && sheet) throw UsageError("--sheet shows pictures; --format makes animations");
      if (!several) require_other_than_input("-o", o.output, o.scene_path);
      o.animation = AnimationRequest{*animation, fps.value_or(30.0), quality};
    } else if (quality) {
      throw UsageError("--quality is for a .jpg picture or a .webp animation; " + named + " writes PNG pictures into a folder");
    }
    if ((!animation || format) && std::filesystem::exists(o.output, ec) && !std::filesystem::is_directory(o.output, ec))
      throw UsageError("-o " + o.output + " is a file; " + named + " writes each view's files in a folder: name a folder");
    if ((!animation || format) && (is_picture_name(o.output) || animation_format_of(o.output)))
      throw UsageError("-o " + o.output + " names a picture, but " + named + " writes each view's files in a folder: name a folder");
    leave_floor_out_of_sphere(o.staging, o.staging_given, views.spread);
    const auto named_too = [&](const char* option) { return std::count(view_options.begin(), view_options.end(), option) > 0; };
    if (views.cameras && (named_too("--views") || named_too("--views-on")))
      throw UsageError("--cameras draws the views its file names; --views and --views-on place views of their own: give one or the other");
    if (turntable && (named_too("--views") || named_too("--views-on") || named_too("--cameras")))
      throw UsageError("--turntable draws a motion's frames; --views, --views-on and --cameras place views of their own: give one or "
                       "the other");
    const auto refuse = [&](bool given, const std::string& option, const std::string& why) {
      if (given) throw UsageError(option + " is not for " + named + why);
    };
    const std::string framed = " (the views stand round the model, where the framing puts them)";
    refuse(o.mask.has_value(), "--mask", " (--passes shadow draws each view's mask)");
    refuse(o.save_scene.has_value(), "--save-scene", "");
    refuse(o.explain, "--explain", "");
    refuse(o.staging.view.eye.has_value() && !turntable, "--eye", framed);
    refuse(o.staging.view.target.has_value() && !turntable, "--target", framed);
    refuse(sheet.has_value() && !several, "--sheet", " of one file (it shows several files' first views)");
    if (!several)
      for (const auto& [given, name] : {std::pair{shard.has_value(), "--shard"}, {timeout_s > 0.0, "--timeout"},
                                        {skip_existing, "--skip-existing"}, {json, "--json"}})
        if (given) throw UsageError(std::string(name) + " is for several files or a folder; \"" + o.scene_path + "\" is one");
    if (several) o.batch = batch(views), o.batch->animation = o.animation;
  } else if (several) {
    if (o.output.empty()) throw UsageError("no output folder given (-o OUTDIR)");
    if (std::filesystem::exists(o.output, ec) && !std::filesystem::is_directory(o.output, ec))
      throw UsageError("-o " + o.output + " is a file; several inputs make one picture each, in a folder: name a folder");
    if (!std::filesystem::exists(o.output, ec) && o.output.back() != '/' && is_picture_name(o.output))
      throw UsageError("-o " + o.output + " names a picture, but several inputs make one picture each, in a folder: name a "
                       "folder (\"" + o.output + "/\" makes one of that name)");
    if (o.mask) throw UsageError("--mask writes one scene's mask; with several files there is none to choose");
    if (o.explain) throw UsageError("--explain prints one scene's plan; with several files, ask for one of them");
    if (o.save_scene) throw UsageError("--save-scene saves one mesh file's staged scene; with several files, ask for one of them");
    o.batch = batch(std::nullopt);
  } else {
    if (shard) throw UsageError("--shard splits several files; \"" + o.scene_path + "\" is one");
    if (sheet) throw UsageError("--sheet shows several files; \"" + o.scene_path + "\" is one");
    for (const auto& [given, name] : {std::pair{timeout_s > 0.0, "--timeout"}, {skip_existing, "--skip-existing"}, {json, "--json"}})
      if (given) throw UsageError(std::string(name) + " is for several files or a folder; \"" + o.scene_path + "\" is one");
    if (o.output.empty()) throw UsageError("no output image given (-o OUT.png)");
    require_other_than_input("-o", o.output, o.scene_path);
    require_picture_name("-o", o.output);
    if (o.staging.background && o.staging.background->transparent && !picture_format_keeps_alpha(*picture_format_of(o.output)))
      throw UsageError("--background transparent needs an alpha channel, which a " +
                       std::string(format_row(*picture_format_of(o.output)).name) + " picture has not: name a .png");
    if (o.jpeg_quality_given && picture_format_of(o.output) != PictureFormat::kJpeg)
      throw UsageError("--quality is for a JPEG picture, or a WebP animation (--turntable); -o " + o.output + " is neither");
    if (writes_standard_output(o.output) && o.explain)
      throw UsageError("--explain prints to standard output, where -o " + o.output + " writes the picture: name a file with -o");
    if (writes_standard_output(o.output) && ::isatty(STDOUT_FILENO))
      throw UsageError("-o " + o.output + " writes the picture's bytes to standard output, which is a terminal here: "
                       "redirect it (> out.png) or name a file");
    if (o.mask) {
      // A mask is exact, pixel by pixel: only a lossless PNG keeps it.
      if (picture_format_of(*o.mask) != PictureFormat::kPng || *o.mask == "-")
        throw UsageError("--mask writes a PNG file (a mask must stay exact), got \"" + *o.mask + "\"");
      require_other_than_input("--mask", *o.mask, o.scene_path);
    }
  }
  if (o.mask && same_file(*o.mask, o.output)) throw UsageError("--mask and -o name the same file");
  // A folder's files may differ in their default, and a file in its spheres
  // and triangles (antialiased_pixels); each is checked again as drawn.
  const std::optional<int> samples = !o.batch ? o.antialias.value_or(default_antialias(o.scene_path)) : o.antialias;
  if (samples && antialiased_pixels(o.antialias_all, o.show_volumes, o.settings) == AntialiasedPixels::kAll)
    require_drawable_size(o.settings.width, o.settings.height, *samples);
  if (!o.batch && o.scene_path != "-") require_staged(o.staging_given, o.scene_path);  // standard input's once read
  if (o.save_scene && !o.batch) {
    require_staged({"--save-scene"}, o.scene_path);
    require_other_than_input("--save-scene", *o.save_scene, o.scene_path);
    if (same_file(*o.save_scene, o.output) || (o.mask && same_file(*o.save_scene, *o.mask)))
      throw UsageError("--save-scene names a file another output writes");
  }
  const RenderMethod m = o.settings.method;
  if (o.show_volumes && !counts_volumes(m))
    throw UsageError(std::string("--show-volumes needs shadow volumes; --method ") + method_name(m) + " has none");
  return o;
}

// Writes the staged scene's `text` to `path`, naming the mesh by its path
// from `path`'s folder where the two share a folder below the root (a
// project's scenes beside its models), else absolutely (a model under
// /usr/share), so that the scene draws the same picture from any folder.
void save_staged_scene(const std::string& text, const std::string& mesh_path, const PartialFile& into) {
  namespace fs = std::filesystem;
  const std::string& path = into.path();
  const fs::path mesh = fs::weakly_canonical(fs::absolute(mesh_path));
  const fs::path folder = fs::weakly_canonical(fs::absolute(path)).parent_path();
  const auto [from_mesh, from_folder] = std::mismatch(mesh.begin(), mesh.end(), folder.begin(), folder.end());
  const bool share_a_folder = std::distance(mesh.begin(), from_mesh) > 1;  // more than the root
  const fs::path named = share_a_folder ? mesh.lexically_relative(folder) : mesh;
  const std::string written = named.generic_string();
  if (written.find_first_of("\"\n\r") != std::string::npos)
    throw InputError({mesh_path}, "a scene cannot name this file (a double quote or a line break in its path): rename it to save its scene");
  // The mesh statement is the staged text's one line that starts "mesh \"".
  const size_t start = text.find("\nmesh \"") + 1, name_end = text.find('"', start + 6);
  const std::string saved = text.substr(0, start) + "mesh \"" + written + text.substr(name_end);
  std::ofstream out(into.temporary_path());
  out << saved;
  out.close();
  if (!out) throw InputError({path}, "cannot write the scene");
}

// A run's output files, each made as its temporary file before anything is
// drawn, so that a folder that does not exist or a file that cannot be
// written stops the run at once; renamed into place together once all are
// written, so that a failure leaves every file as it was before the run.
struct RenderOutputs {
  std::optional<PartialFile> picture, mask, scene;  // no picture file for -o - (standard output)
  explicit RenderOutputs(const RenderOptions& o) {
    if (o.output != "-") picture.emplace(o.output, "the image");
    if (o.mask) mask.emplace(*o.mask, "the mask");
    if (o.save_scene) scene.emplace(*o.save_scene, "the scene");
  }
  void commit() {
    for (std::optional<PartialFile>* file : {&picture, &mask, &scene})
      if (*file) (*file)->commit();
  }
};

}  // namespace

int run_render_command(const std::vector<std::string>& argv) {
  RenderOptions options;
  if (const auto exit_status = parse_command_line("render", kRenderUsage, argv, parse_render_options, options))
    return *exit_status;
  if (options.batch) return run_batch_render(*options.batch);
  // "-": the mesh (or scene) on standard input, copied to a file for the readers.
  const bool standard_input = options.scene_path == "-";
  std::optional<StandardInputFile> input;
  try {
    input.emplace(options.scene_path);
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  options.scene_path = input->path();
  if (const std::optional<InputError> error = neither_scene_nor_mesh(options.scene_path)) {
    std::cerr << error->what() << "\n";
    return 2;
  }
  // The staging options, and views, ask standard input for a mesh, which only its content can say.
  if (standard_input && !is_mesh_file(options.scene_path)) {
    std::vector<std::string> given = options.staging_given;
    if (options.views && options.views->turning == Turning::kNone)
      given.insert(given.begin(), options.views->cameras ? "--cameras" : "--views");
    if (!given.empty()) {
      std::cerr << "umbra render: " << given.front() << " is for a mesh file on its own, which umbra stages; standard input holds "
                << "a scene (a scene has its own camera and lights)\n(see umbra render --help)\n";
      return 2;
    }
  }
  if (options.views)
    return write_view_set(options.scene_path, options.output, options, *options.views, options.animation, options.reading,
                          standard_input ? "standard input" : options.scene_path);
  keep_freed_memory_for_reuse();
  try {
    RenderOutputs outputs(options);
    // Loading, planning and drawing: three steps, the first per mesh file.
    std::optional<ProgressBar> progress(std::in_place, 3);
    std::string staged;
    Scene scene = parse_scene_or_mesh_file(options.scene_path, [&](size_t loaded, size_t total, const std::string& path) {
      progress->update(0, "loading mesh " + std::to_string(loaded + 1) + " of " + std::to_string(total) + ": " + path);
    }, &staged, staging_for(options.staging, options.settings), options.reading);
    progress->clear();
    set_picture_size(options.settings, options.size_given, scene);
    set_picture_samples(options.settings, options.antialias, options.antialias_all, options.show_volumes, scene);
    require_drawable_size(options.settings.width, options.settings.height, options.settings.frame_samples());
    if (options.explain && !staged.empty())
      std::cout << "staged scene for " << options.scene_path << " (--save-scene FILE saves it to render or edit):\n"
                << staged << "\n";
    for (const Warning& w : scene.warnings) std::cerr << w.where.str() << ": warning: " << w.message << "\n";
    progress->update(1, "planning shadow volumes");
    require_lights_off_casters(scene);
    require_caught_shadows_kept(scene, options.settings.method);

    if (options.explain && options.settings.method == RenderMethod::kRaycast)
      progress->clear(), std::cout << "render plan for " << scene.path << "\n  method: raycast, eye rays and an exact "
                << "shadow ray per light (CPU, double precision)\n  image: " << image_phrase(options.settings)
                << "\n  memory: " << malloc_pages_description(current_malloc_environment()) << "\n";
    std::optional<HeadlessContext> context;
    DrawnPicture drawn = draw_picture(scene, options.settings, {options.show_volumes, options.mask.has_value(), false}, context,
                                      options.gl, [&](const RenderPlan& plan, const HeadlessContext& made) {
      progress->update(2, "drawing");
      if (!options.explain) return;
      progress.reset();
      print_render_plan(std::cout, scene, plan);
      std::cout << "  OpenGL: " << made.description() << "\n";
      std::cout << "  memory: " << malloc_pages_description(current_malloc_environment()) << "\n";
    });
    const Image& image = drawn.image;
    const std::optional<Image>& mask = drawn.mask;

    progress.reset();
    if (outputs.picture) write_picture_into(image, *outputs.picture, options.picture);
    if (mask) write_picture_into(*mask, *outputs.mask);
    if (outputs.scene) save_staged_scene(staged, options.scene_path, *outputs.scene);
    if (!outputs.picture) write_picture(image, "-", options.picture);
    outputs.commit();
    // With -o - (or /dev/stdout), standard output holds the picture alone.
    std::ostream& said = writes_standard_output(options.output) ? std::cerr : std::cout;
    said << "wrote " << (options.output == "-" ? "the picture to standard output" : options.output) << " (" << image.width
         << "x" << image.height << ")";
    if (mask) said << " and mask " << *options.mask;
    if (options.save_scene) said << ", and saved its scene to " << *options.save_scene;
    said << "\n";
    return 0;
  } catch (const std::exception&) {
    return render_failure_status(options.settings);
  }
}

}  // namespace umbra
