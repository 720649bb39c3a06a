#include "tools/render_options.hpp"

#include <algorithm>
#include <iostream>

#include "image/animation_file.hpp"
#include "render/frame_target.hpp"
#include "scene/scene_text.hpp"
#include "scene/staged_scene.hpp"
#include "tools/option_values.hpp"

namespace umbra {

namespace {

constexpr ValueRange kSegments{3, 4096}, kMapSize{16, 8192}, kAntialias{1, 4}, kFps{1, 240};

}  // namespace

void add_size_option(CommandOptions& options, int& width, int& height, const std::string& does, bool* given) {
  options.value("--size", {"WxH", does}, [&width, &height, given](const std::string& o, const std::string& t) {
    parse_size(o, t, kLargestImage, width, height);
    if (given) *given = true;
  });
}

void add_light_angle_option(CommandOptions& options, double& degrees, const std::string& does) {
  options.value("--light-angle", {"DEG", does}, [&](const std::string& o, const std::string& t) { degrees = parse_finite_number(o, t); });
}

void add_segments_option(CommandOptions& options, int& segments) {
  options.value("--segments",
                ranged({"N", "sides of the N-gon that stands for a sphere's tangent circle in its shadow volume (default {default}, "
                             "{range})"},
                       kSegments, segments),
                [&](const std::string& o, const std::string& t) { segments = parse_int_in(o, t, kSegments); });
}

void add_method_option(CommandOptions& options, RenderMethod& method, const std::string& does) {
  options.value("--method", {"M", does}, [&](const std::string& o, const std::string& t) { method = parse_method(o, t); });
}

void add_gl_option(CommandOptions& options, HeadlessGl& gl) {
  options.value("--gl", {"G", "the headless OpenGL to draw with (default auto, or the UMBRA_GL environment variable's):\n{gl platforms}\n"},
                [&](const std::string& o, const std::string& t) {
                  const auto named = headless_gl_from_name(t);
                  if (!named) throw UsageError(o + " expects " + headless_gl_names() + ", got \"" + t + "\"");
                  gl = *named;
                });
}

HeadlessGl gl_with_environment(HeadlessGl chosen) {
  if (chosen != HeadlessGl::kAuto) return chosen;
  try {
    return headless_gl_from_environment();
  } catch (const std::runtime_error& e) {
    throw UsageError(e.what());
  }
}

void add_map_size_option(CommandOptions& options, int& texels) {
  options.value("--map-size",
                ranged({"N", "texels along a side of each shadow map cube face (default {default}, {range}; for --method shadowmap)"},
                       kMapSize, texels),
                [&](const std::string& o, const std::string& t) { texels = parse_int_in(o, t, kMapSize); });
}

void add_antialias_option(CommandOptions& options, std::optional<int>& samples, const std::string& does) {
  options.value("--antialias", ranged({"N", does}, kAntialias, 1),
                [&](const std::string& o, const std::string& t) { samples = parse_int_in(o, t, kAntialias); });
}

void add_fps_option(CommandOptions& options, std::optional<double>& fps, const std::string& does) {
  options.value("--fps",
                ranged({"F", does + ", {range} (default {default}; a GIF keeps whole hundredths of a second)"}, kFps,
                       AnimationSettings{}.fps),
                [&](const std::string& n, const std::string& t) {
                  fps = parse_finite_number(n, t);
                  if (!(*fps >= kFps.lowest && *fps <= kFps.highest))
                    throw UsageError(n + " must be from " + number_text(kFps.lowest) + " to " + number_text(kFps.highest) +
                                     " frames a second, got \"" + t + "\"");
                });
}

int render_failure_status(const RenderSettings& settings, const std::string& said_before) {
  std::cerr << said_before;
  try {
    throw;
  } catch (const UsageError& e) {  // an option that the file's content rules out (require_drawable_size)
    std::cerr << "umbra render: " << e.what() << "\n(see umbra render --help)\n";
  } catch (const FrameTooLarge& e) {  // the options' size and samples, more than this GL can draw
    std::cerr << "umbra render: --size " << settings.width << "x" << settings.height << " at " << settings.frame_samples() << " x "
              << settings.frame_samples() << " samples (--antialias): " << e.what()
              << "; make --size or --antialias smaller\n(see umbra render --help)\n";
  } catch (const StagingChoiceError& e) {  // a camera option that this model's framing rules out
    std::cerr << "umbra render: " << e.what() << "\n(see umbra render --help)\n";
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 2;
}

void require_drawable_size(int width, int height, int samples) {
  if (std::max(width, height) * samples <= kLargestImage) return;
  const std::string size = std::to_string(width) + "x" + std::to_string(height);
  throw UsageError("--size " + size + " at " + std::to_string(samples) + " x " + std::to_string(samples) + " samples (--antialias " +
                   std::to_string(samples) + ") is a frame of " + std::to_string(width * samples) + "x" + std::to_string(height * samples) +
                   ", more than the " + std::to_string(kLargestImage) + " along a side umbra draws: make --size or --antialias smaller");
}

}  // namespace umbra
