#include "tools/view_command.hpp"

#include <sys/stat.h>

#include <array>
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "scene/mesh_loader.hpp"
#include "scene/scene_checks.hpp"
#include "scene/scene_parser.hpp"
#include "scene/staged_scene.hpp"
#include "image/animation_file.hpp"
#include "image/image.hpp"
#include "image/partial_file.hpp"
#include "image/picture_file.hpp"
#include "render/render_plan.hpp"
#include "render/shadow_renderer.hpp"
#include "render/text_overlay.hpp"
#include "render/window_context.hpp"
#include "scene/scene_text.hpp"
#include "tools/command_line.hpp"
#include "tools/encoding_thread.hpp"
#include "tools/freed_memory_reuse.hpp"
#include "tools/progress_bar.hpp"

namespace umbra {

const std::string kViewUsage =
    R"(usage: umbra view SCENE [options]
       umbra view MESH [options]

Opens SCENE in a window and renders it as `umbra render` does, with the light
orbiting the z axis. A mesh file is staged on its own as `umbra render MESH`
stages it. The scene (or mesh) is reloaded when its file changes; an error
keeps the last good scene and shows in the window and on the terminal. An
overlay shows the method, the frame time, the volume sizes and the keys.

keys:
  space         pause or resume the light
  left, right   step the light by 5 degrees
  up, down      double or halve the light's speed
  v             show or hide the shadow volumes
  ] and [       double or halve the sphere segments N (3 to 4096)
  m             switch method:
                {interactive methods}
                (see umbra render --help)
  r             return to the scene's camera
  s             return to the default view (eye (0, 0, 3.4), looking down -z)
  c             record what the window shows (without the overlay), or
                stop recording and write the file: --record's, or
                umbra-view.mp4 (umbra-view.webp where MP4 is not built);
                a second recording adds -2 to the name, and so on
  o             show or hide the overlay
  h             print this help on the terminal
  q, escape     quit
mouse: drag to orbit the camera around its target, scroll to zoom

options:
{options})";

namespace {

struct ViewOptions {
  std::string scene_path;
  StagingOptions staging;  // for a mesh file on its own
  std::vector<std::string> staging_given;
  ReadOptions reading;  // --any-texture-path, --cad-deflection, --cad-angle
  RenderSettings settings;
  std::optional<int> antialias;  // a still view's samples per side; unset: the scene's (default_antialias)
  double light_angle_deg = 0.0;
  double speed_deg_per_s = 30.0;
  bool paused = false;
  int frames = 0;  // 0: until the window is closed
  std::optional<std::string> screenshot;
  bool overlay_in_screenshot = false;
  std::optional<std::string> record;  // where recordings go, the first from the first frame
  std::optional<double> fps;  // a recording's; unset: AnimationSettings' default
};

ViewOptions parse_view_options(const std::vector<std::string>& argv) {
  ViewOptions o;
  std::vector<std::string> scenes;
  CommandOptions options;
  add_size_option(options, o.settings.width, o.settings.height,
                  "window size (default " + std::to_string(o.settings.width) + "x" + std::to_string(o.settings.height) + ")");
  add_method_option(options, o.settings.method, "{interactive methods} (default auto; see umbra render --help)");
  add_map_size_option(options, o.settings.shadow_map_size);
  add_light_angle_option(options, o.light_angle_deg, "start with the lights rotated by DEG (default 0)");
  options.value("--speed", {"DEG", "degrees per second the light turns (default " + number_text(o.speed_deg_per_s) + ")"},
                [&](const std::string& n, const std::string& t) { o.speed_deg_per_s = parse_finite_number(n, t); });
  options.flag("--paused", o.paused, "start with the light paused");
  add_segments_option(options, o.settings.sphere_segments);
  add_antialias_option(options, o.antialias,
                       "N x N samples per pixel ({range}) for a view that stands still: while the light or the camera moves, each "
                       "frame is one sample a pixel; once the view has not changed for a quarter of a second (in a --frames run, "
                       "from the next frame), it is drawn once more with N x N samples at every pixel, averaged (as umbra render "
                       "--antialias-all draws it), then shown as it is until something changes (--frames draws every frame). "
                       "Default as umbra render's: " +
                           std::to_string(kStagedAntialias) + " for a MESH, the scene's antialias statement (else 1) for a SCENE");
  options.value("--frames",
                {"N", "draw N frames, then exit, printing the median and the worst time a frame took; the light then advances by "
                      "SPEED/60 degrees per frame, so a run is reproducible"},
                [&](const std::string& n, const std::string& t) { o.frames = parse_int_in(n, t, 1, 1 << 30); });
  options.value("--screenshot",
                {"OUT.png", "with --frames: write the last frame to OUT.png (without the overlay, so that it is the headless "
                            "render's frame)"},
                [&](const std::string&, const std::string& t) { o.screenshot = t; });
  options.flag("--overlay-in-screenshot", o.overlay_in_screenshot, "include the overlay in the screenshot");
  options.value("--record",
                {"OUT", "record from the first frame into OUT: {animation formats}, as umbra render --turntable writes them, at "
                        "--fps frames a second by the clock (with --frames, every frame drawn, until the last); c stops it"},
                [&](const std::string& n, const std::string& t) {
                  const std::optional<AnimationFormat> format = animation_format_of(t);
                  if (!format) throw UsageError(n + " records into " + animation_extensions() + ", got \"" + t + "\"");
                  if (const std::string why = animation_unavailable(*format); !why.empty()) throw UsageError(why);
                  o.record = t;
                });
  add_fps_option(options, o.fps, "a recording's frames a second");
  add_staging_options(options, o.staging, o.staging_given);
  add_reading_options(options, o.reading, true);
  options.help_option();
  options.positionals(scenes);
  options.parse(argv);
  if (scenes.size() > 1) throw UsageError("one scene at a time (got \"" + scenes[0] + "\" and \"" + scenes[1] + "\")");
  if (!scenes.empty()) o.scene_path = scenes[0];
  if (o.scene_path.empty()) throw UsageError("no scene or mesh file given");
  if (o.screenshot && o.frames == 0) throw UsageError("--screenshot needs --frames N");
  if (o.screenshot) require_picture_name("--screenshot", *o.screenshot);
  require_consistent_staging(o.staging);
  note_staging_flags(o.staging, o.staging_given);
  require_staged(o.staging_given, o.scene_path);
  if (!is_interactive(o.settings.method))
    throw UsageError(std::string("--method ") + method_name(o.settings.method) + " is not interactive; use umbra render --method " +
                     method_name(o.settings.method));
  return o;
}

// What tells an edited scene file apart: its modification time, size and
// inode. Two writes within one tick of the file system's clock share a time,
// but an editor's rename changes the inode and an append the size.
std::optional<std::array<long, 4>> file_signature(const std::string& path) {
  struct stat info {};
  if (stat(path.c_str(), &info) != 0) return std::nullopt;
  return std::array<long, 4>{long(info.st_mtim.tv_sec), long(info.st_mtim.tv_nsec), long(info.st_size), long(info.st_ino)};
}

// Everything that depends on the scene file, rebuilt when it changes.
struct LoadedScene {
  Scene file;                        // as parsed, lights unrotated
  Scene frame;                       // lights rotated for the frame, camera as orbited
  std::vector<MeshCaster> meshes;
  std::unique_ptr<RenderPlan> plan;
  std::unique_ptr<ShadowRenderer> renderer;
  int still_samples = 1;  // per side, for a view that stands still
  int generation = 0;     // how many loads made it
};

// How long a view must stay unchanged before it is drawn with its samples.
constexpr double kSettleSeconds = 0.25;

// What a frame shows: where it stays the last frame's, the view stands still.
struct ViewState {
  Camera camera;
  double light_angle_deg = 0.0;
  RenderSettings settings;  // one sample
  bool show_volumes = false;
  int generation = 0;
  bool operator==(const ViewState&) const = default;
};

// Turns `camera` about its target: yaw about its up vector, pitch about its right.
void orbit(Camera& camera, double yaw_deg, double pitch_deg) {
  glm::dvec3 offset = camera.eye - camera.target;
  const glm::dvec3 up = glm::normalize(camera.up);
  const auto rotate = [](const glm::dvec3& v, const glm::dvec3& axis, double deg) {
    const double a = glm::radians(deg);
    return v * std::cos(a) + glm::cross(axis, v) * std::sin(a) + axis * glm::dot(axis, v) * (1.0 - std::cos(a));
  };
  offset = rotate(offset, up, yaw_deg);
  const glm::dvec3 right = glm::cross(glm::normalize(offset), up);
  if (glm::length(right) > 1e-9) {
    const glm::dvec3 turned = rotate(offset, glm::normalize(right), pitch_deg);
    // Stop short of the poles, where the up vector would flip.
    if (std::abs(glm::dot(glm::normalize(turned), up)) < 0.99) offset = turned;
  }
  camera.eye = camera.target + offset;
}

// Comes `factor` times closer: a perspective camera's eye toward its
// target; an orthographic camera, whose picture no distance changes, sees
// `factor` times less.
void zoom(Camera& camera, double factor) {
  if (camera.orthographic()) camera.ortho_height /= factor;
  else camera.eye = camera.target + (camera.eye - camera.target) / factor;
}

// What the window shows, written as an animation: from the key c to the
// next, or from the first frame with --record. Frames are added by the
// clock, `fps` a second (a view that stands still is added again), each
// encoded on a thread of its own; the file appears whole when finished.
class Recording {
 public:
  Recording(const std::string& path, int width, int height, double fps, double now)
      : file_(path, "the recording", PartialFile::Ending::kKeepExtension), width_(width), height_(height), fps_(fps), started_(now) {
    writer_ = open_animation(*animation_format_of(path), file_.temporary_path(), path, {width, height, fps, std::nullopt});
    encoding_.emplace(*writer_);
  }
  // The frames the clock asks for by `now`: one at the start, then one each 1/fps.
  size_t due(double now) const { return size_t(std::floor((now - started_) * fps_)) + 1; }
  size_t frames() const { return frames_; }
  bool fits(int width, int height) const { return width == width_ && height == height_; }
  const std::string& path() const { return file_.path(); }
  void add(Image frame) {
    encoding_->add(std::move(frame));
    ++frames_;
  }
  // The file written whole; what to say of it.
  std::string finish() {
    encoding_->finish();
    file_.commit();
    return "wrote " + file_.path() + " (" + std::to_string(frames_) + " frames at " + std::to_string(width_) + "x" +
           std::to_string(height_) + ")";
  }

 private:
  PartialFile file_;  // removed, unless committed
  int width_, height_;
  double fps_, started_;
  size_t frames_ = 0;
  std::unique_ptr<AnimationWriter> writer_;
  std::optional<EncodingThread> encoding_;  // after the writer it uses: stopped first
};

// Where recording `k` (from 1) of a session goes: `base`, then NAME-2.EXT, NAME-3.EXT, ...
std::string recording_path(const std::string& base, int k) {
  if (k == 1) return base;
  const std::filesystem::path path(base);
  return (path.parent_path() / (path.stem().string() + "-" + std::to_string(k) + path.extension().string())).string();
}

// What the overlay shows: the frame, the volumes, a message (an error), the keys.
std::vector<std::string> status_lines(const std::string& path, const RenderPlan& plan, double frame_ms, double angle,
                                      bool paused, double speed, const std::string& message) {
  const int samples = plan.settings.antialias;
  char line[256];
  std::vector<std::string> lines = {path};
  const LightPlan& light = plan.lights[0];
  const int segments = plan.settings.sphere_segments;
  const RenderMethod method = plan.settings.method;
  std::snprintf(line, sizeof line, "method %s (light 1 %s)   frame time %.1f ms at %d x %d samples", method_name(method),
                !counts_volumes(method) ? method_technique(method) : light.count == DepthCount::kWhereDepthPasses ? "z-pass" : "z-fail", frame_ms,
                samples, samples);
  lines.push_back(line);
  std::snprintf(line, sizeof line, "light 1 at %.1f deg, %s%.3g deg/s   sphere N = %d", std::fmod(angle, 360.0),
                paused ? "paused, " : "", speed, segments);
  lines.push_back(line);
  std::snprintf(line, sizeof line, "light 1 volumes: %d side quads, %d near-cap and %d far-cap triangles", light.side_quads,
                light.light_cap_triangles, light.dark_cap_triangles);
  lines.push_back(line);
  if (!message.empty()) lines.push_back(message);
  lines.push_back("space pause  left/right step  up/down speed  v volumes  [ ] N");
  lines.push_back("drag orbit  scroll zoom  r scene camera  s default view  c record  o overlay  h help  q quit");
  return lines;
}

}  // namespace

int run_view_command(const std::vector<std::string>& argv) {
  ViewOptions options;
  if (const auto exit_status = parse_command_line("view", kViewUsage, argv, parse_view_options, options))
    return *exit_status;
  keep_freed_memory_for_reuse();

  // The window (and its GL context) is declared first so that it is destroyed
  // last, after the renderer's GL objects.
  std::unique_ptr<WindowContext> window;
  LoadedScene scene;
  std::optional<Camera> orbited;  // the user's camera, kept across reloads
  // Lights are checked at `angle`, where the next frame will draw them.
  const auto load = [&](double angle) {
    std::optional<ProgressBar> progress(std::in_place, 2);  // loading, then preparing the shadows
    Scene parsed = parse_scene_or_mesh_file(options.scene_path, [&](size_t loaded, size_t total, const std::string& path) {
      progress->update(0, "loading mesh " + std::to_string(loaded + 1) + " of " + std::to_string(total) + ": " + path);
    }, nullptr, staging_for(options.staging, options.settings), options.reading);
    progress->clear();
    for (const Warning& w : parsed.warnings) std::cerr << w.where.str() << ": warning: " << w.message << "\n";
    // The camera moves, so the picture would be asked about back faces at
    // every new view: one search now instead (mesh_loader.hpp).
    if (std::any_of(parsed.meshes.begin(), parsed.meshes.end(),
                    [](const Mesh& m) { return m.back_faces == BackFaces::kHiddenUnlessSeen; })) {
      progress->update(1, "searching the meshes for faces that cross");
      settle_back_faces_by_search(parsed);
    }
    progress->update(1, "preparing shadow volumes");
    Scene check = parsed;
    rotate_lights_about_z(check, angle);
    require_lights_off_casters(check);
    // The window shows the frame as drawn, which a catcher's share of light
    // is not: only a picture's read-back resolves it (pixel_mean.hpp).
    for (const Material& m : parsed.materials)
      if (m.shadow_catcher)
        throw InputError({parsed.path}, "material \"" + m.name + "\" is a shadow catcher, which umbra view's window cannot "
                                        "show: use umbra render");
    scene.file = std::move(parsed);
    scene.frame = scene.file;
    if (orbited) scene.frame.camera = *orbited;  // a reload keeps the user's view
    scene.meshes = prepare_mesh_casters(scene.frame);
    scene.plan = std::make_unique<RenderPlan>(make_render_plan(scene.frame, scene.meshes, options.settings));
    scene.renderer = std::make_unique<ShadowRenderer>(scene.frame, *scene.plan, DrawSending::kWhole);
    scene.still_samples = options.antialias.value_or(scene.file.antialias.value_or(1));
    ++scene.generation;
    progress.reset();
  };

  if (const std::optional<InputError> error = neither_scene_nor_mesh(options.scene_path)) {
    std::cerr << error->what() << "\n";
    return 2;
  }
  try {
    window = std::make_unique<WindowContext>(options.settings.width, options.settings.height,
                                             "umbra view - " + options.scene_path);
    load(options.light_angle_deg);
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }

  std::unique_ptr<TextOverlay> overlay;
  try {
    overlay = std::make_unique<TextOverlay>(*window);
  } catch (const std::exception& e) {
    std::cerr << "umbra view: " << e.what() << "; going on without the overlay\n";
  }
  bool paused = options.paused, show_volumes = false, show_overlay = true;
  double speed = options.speed_deg_per_s, angle = options.light_angle_deg;
  double good_angle = angle;  // the last angle with every light outside every sphere
  std::string light_error;    // why the light stopped, while it stays stopped
  std::string error;  // the last reload error, shown in the title until the next good load
  // Recordings: the one under way, how many this session made, and whether c asked to start or stop one.
  std::optional<Recording> recording;
  int recordings = 0;
  bool toggle_recording = options.record.has_value();  // --record starts one at the first frame
  const std::string record_base =
      options.record.value_or(animation_row(AnimationFormat::kMp4).built ? "umbra-view.mp4" : "umbra-view.webp");
  const auto stop_recording = [&] {
    try {
      std::cout << recording->finish() << "\n";
    } catch (const std::exception& e) {
      std::cerr << "umbra view: the recording failed: " << e.what() << "\n";
    }
    recording.reset();
  };
  using Key = WindowContext::Key;
  window->on_key = [&](Key key) {
    switch (key) {
      case Key::kSpace: paused = !paused; break;
      case Key::kRight: angle += 5.0; break;
      case Key::kLeft: angle -= 5.0; break;
      case Key::kUp: speed *= 2.0; break;
      case Key::kDown: speed /= 2.0; break;
      case Key::kV: show_volumes = !show_volumes; break;
      case Key::kRightBracket: options.settings.sphere_segments = std::min(4096, options.settings.sphere_segments * 2); break;
      case Key::kLeftBracket: options.settings.sphere_segments = std::max(3, options.settings.sphere_segments / 2); break;
      case Key::kM: options.settings.method = next_interactive_method(options.settings.method); break;
      case Key::kR: orbited.reset(); scene.frame.camera = scene.file.camera; break;
      case Key::kS: orbited = spec_camera(); scene.frame.camera = *orbited; break;
      case Key::kC: toggle_recording = true; break;
      case Key::kO: show_overlay = !show_overlay; break;
      case Key::kH: std::cout << help_of(kViewUsage, parse_view_options); break;
      case Key::kQ: case Key::kEscape: window->close(); break;
      case Key::kOther: break;
    }
  };
  window->on_drag = [&](double dx, double dy) {
    orbit(scene.frame.camera, -0.3 * dx, -0.3 * dy);
    orbited = scene.frame.camera;
  };
  window->on_scroll = [&](double steps) {
    zoom(scene.frame.camera, std::pow(0.9, -steps));
    orbited = scene.frame.camera;
  };

  auto file_time = file_signature(options.scene_path);
  double last_time = window->time_seconds();
  std::optional<ViewState> drawn_state;  // what the last frame drawn shows
  double changed_at = 0.0;               // when the view last changed (window time)
  int drawn_samples = 1;                 // and its samples per side
  double frame_ms = 0.0;                 // as the overlay shows it
  bool drew_before = false;
  std::vector<double> frame_times_ms;  // with --frames: each frame's plan, drawing and buffer swap
  for (int frame = 1; !window->should_close(); ++frame) {
    // Reload when the file changed; keep the last good scene on an error.
    if (const auto now = file_signature(options.scene_path); now && now != file_time) {
      file_time = now;
      try {
        load(angle);
        error.clear();
      } catch (const std::exception& e) {
        error = e.what();
        std::cerr << error << "\n";
      }
    }
    const double now = window->time_seconds();
    // A light orbiting into a sphere stops where it was, paused, with the error shown.
    const auto place_lights = [&] {
      scene.frame.lights = scene.file.lights;
      rotate_lights_about_z(scene.frame, angle);
      require_lights_off_casters(scene.frame);
    };
    try {
      place_lights();
      good_angle = angle;
      light_error.clear();
    } catch (const InputError& e) {
      light_error = e.what();
      paused = true;
      angle = good_angle;
      place_lights();
    }
    int width = 0, height = 0;
    window->framebuffer_size(width, height);
    const bool last_frame = options.frames > 0 && frame == options.frames;
    const bool shows = width > 0 && height > 0;
    bool drew = false;
    if (shows) {
      // Every setting as the keys left it, at the window's size: the plan is
      // remade only when one of them differs from what it was made for.
      RenderSettings settings = options.settings;
      settings.width = width;
      settings.height = height;
      // A view that moves is drawn one sample a pixel. Once frames would be
      // drawn as the last was for kSettleSeconds (a pause in a drag is no
      // stop), the view stands still: it is drawn once more with its samples
      // at every pixel, then shown as it is. A scripted run (--frames) takes
      // its samples at once, and draws every frame, to time it.
      const ViewState state{scene.frame.camera, angle, settings, show_volumes, scene.generation};
      const bool same = drawn_state && *drawn_state == state;
      if (!same) changed_at = now;
      const bool still = same && (options.frames > 0 || now - changed_at >= kSettleSeconds);
      const int samples = still ? scene.still_samples : 1;
      if (!same || drawn_samples != samples || options.frames > 0) {
        const auto draw_at = [&](int samples_per_side) {
          settings.antialias = samples_per_side;
          settings.antialiased = AntialiasedPixels::kAll;
          scene.plan->settings = settings;
          // A moved light's volumes are made while the GL draws the first pass.
          update_render_view(scene.frame, *scene.plan);
          scene.renderer->draw(show_volumes, [&] { update_render_lights(scene.frame, scene.meshes, *scene.plan); });
          drawn_samples = samples_per_side;
        };
        try {
          draw_at(samples);
        } catch (const std::runtime_error& e) {
          if (samples == 1) throw;
          // A frame N x N times larger than the GL can make: still views stay one sample.
          std::cerr << "umbra view: " << e.what() << "; still views stay at one sample\n";
          scene.still_samples = 1;
          draw_at(1);
        }
        drawn_state = state;
        drew = true;
      }
    }
    // The interval since the previous frame: drawing, the buffer swap and the
    // wait for it; the overlay keeps the last one that followed a drawn frame.
    if (drew_before) frame_ms = 1000.0 * (now - last_time);
    drew_before = drew;
    // The frame as drawn (never the overlay) into the recording: each frame
    // of a scripted run, else as many as the clock asks for.
    if (toggle_recording && shows) {
      toggle_recording = false;
      if (recording) {
        stop_recording();
      } else {
        try {
          recording.emplace(recording_path(record_base, ++recordings), width, height, options.fps.value_or(AnimationSettings{}.fps), now);
          std::cout << "recording to " << recording->path() << " (c stops)\n";
        } catch (const std::exception& e) {
          std::cerr << "umbra view: cannot record: " << e.what() << "\n";
        }
      }
    }
    if (recording && !recording->fits(width, height)) {
      std::cerr << "umbra view: the window changed size, which a recording cannot: stopped\n";
      stop_recording();
    }
    try {
      // One read-back, however many frames the clock asks for (a view that stands still is added again).
      const size_t due = !recording ? 0 : options.frames > 0 ? size_t(frame) : recording->due(now);
      if (recording && recording->frames() < due) {
        const Image shown = scene.renderer->read_image();
        while (recording->frames() < due) recording->add(shown);
      }
    } catch (const std::exception& e) {
      std::cerr << "umbra view: the recording failed: " << e.what() << "\n";
      recording.reset();
    }

    const auto draw_overlay = [&] {
      if (overlay && show_overlay)
        overlay->draw(status_lines(options.scene_path, *scene.plan, frame_ms, angle, paused, speed,
                                   !error.empty()         ? "ERROR (showing the last good scene): " + error
                                   : !light_error.empty() ? "light stopped: " + light_error
                                   : recording            ? "recording to " + recording->path() + ": " +
                                                                std::to_string(recording->frames()) + " frames (c stops)"
                                                          : std::string()));
    };
    if (last_frame) {
      if (recording) stop_recording();
      if (options.screenshot) {
        if (options.overlay_in_screenshot) draw_overlay();  // into the frame, drawn this time and still bound
        try {
          write_picture(scene.renderer->read_image(), *options.screenshot);
        } catch (const std::exception& e) {
          std::cerr << e.what() << "\n";
          return 1;
        }
        std::cout << "wrote " << *options.screenshot << " (frame " << frame << ", light at " << angle << " deg)\n";
      }
      break;
    }
    if (shows) {
      scene.renderer->show();  // leaves the window bound
      draw_overlay();          // over the frame as shown, untoned
    }
    window->swap_buffers();
    if (options.frames > 0) frame_times_ms.push_back(1000.0 * (window->time_seconds() - now));
    // A window that shows a view standing still waits for something to do
    // (a key, the mouse; the view to settle; or half a second, to see
    // whether the file changed).
    if (!drew && paused && options.frames == 0 && !recording)
      window->wait_events(drawn_samples == scene.still_samples ? 0.5 : std::max(0.0, kSettleSeconds - (now - changed_at)));
    else window->poll_events();
    // Scripted runs advance by a fixed 1/60 s a frame, interactive ones by the clock.
    const double dt = options.frames > 0 ? 1.0 / 60.0 : now - last_time;
    last_time = now;
    if (!paused) angle += speed * dt;
  }
  if (recording) stop_recording();  // the window closed while it recorded
  if (!frame_times_ms.empty()) {
    std::vector<double> sorted = frame_times_ms;
    std::sort(sorted.begin(), sorted.end());
    const size_t n = sorted.size();
    const double median = n % 2 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
    char line[160];
    std::snprintf(line, sizeof line, "%zu frames (all but the last): median %.1f ms, worst %.1f ms a frame (plan, drawing and swap)\n",
                  n, median, sorted.back());
    std::cout << line;
  }
  return 0;
}

}  // namespace umbra
