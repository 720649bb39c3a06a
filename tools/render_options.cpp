#include "tools/render_options.hpp"

#include <algorithm>
#include <iostream>

#include "render/frame_target.hpp"
#include "scene/staged_scene.hpp"
#include "tools/option_values.hpp"

namespace umbra {

void add_size_option(CommandOptions& options, int& width, int& height, bool* given) {
  options.value("--size", [&width, &height, given](const std::string& o, const std::string& t) {
    parse_size(o, t, kLargestImage, width, height);
    if (given) *given = true;
  });
}

void add_light_angle_option(CommandOptions& options, double& degrees) {
  options.value("--light-angle", [&](const std::string& o, const std::string& t) { degrees = parse_finite_number(o, t); });
}

void add_segments_option(CommandOptions& options, int& segments) {
  options.value("--segments", [&](const std::string& o, const std::string& t) { segments = parse_int_in(o, t, 3, 4096); });
}

void add_method_option(CommandOptions& options, RenderMethod& method) {
  options.value("--method", [&](const std::string& o, const std::string& t) { method = parse_method(o, t); });
}

void add_gl_option(CommandOptions& options, HeadlessGl& gl) {
  options.value("--gl", [&](const std::string& o, const std::string& t) {
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
  options.value("--map-size", [&](const std::string& o, const std::string& t) { texels = parse_int_in(o, t, 16, 8192); });
}

void add_antialias_option(CommandOptions& options, std::optional<int>& samples) {
  options.value("--antialias", [&](const std::string& o, const std::string& t) { samples = parse_int_in(o, t, 1, 4); });
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
