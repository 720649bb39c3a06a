#pragma once
// How a picture is drawn, as the commands that draw take it: its size, the
// method, its samples, the GL; and what a failed render says.

#include <optional>
#include <string>

#include "render/headless_context.hpp"
#include "render/render_method.hpp"
#include "render/render_plan.hpp"
#include "tools/command_options.hpp"

namespace umbra {

constexpr int kLargestImage = kLargestPictureSide;  // along a side of the frame drawn, supersampled
// A UsageError when `samples` x `samples` supersampling makes a frame of
// `width` x `height` larger than kLargestImage along a side.
void require_drawable_size(int width, int height, int samples);

// Inside a catch block of `umbra render`: says why the render stopped (the
// exception being handled) on stderr, after `said_before` (its scene's
// warnings), and returns the exit status: 2 for an option the input rules
// out (UsageError, a frame larger than the GL draws for `settings`, a
// camera option the framing rules out), 1 for the rest.
int render_failure_status(const RenderSettings& settings, const std::string& said_before = "");
// The options of how a picture is drawn. Where what an option does differs
// between commands (a picture's size or a window's), the command says it in
// `does`; the rest say it here, once.
void add_size_option(CommandOptions& options, int& width, int& height, const std::string& does, bool* given = nullptr);  // --size WxH
void add_light_angle_option(CommandOptions& options, double& degrees, const std::string& does);  // --light-angle DEG
void add_segments_option(CommandOptions& options, int& segments);                                 // --segments N
void add_method_option(CommandOptions& options, RenderMethod& method, const std::string& does);   // --method M
void add_map_size_option(CommandOptions& options, int& texels);                                   // --map-size N
void add_antialias_option(CommandOptions& options, std::optional<int>& samples, const std::string& does);  // --antialias N
void add_gl_option(CommandOptions& options, HeadlessGl& gl);  // --gl auto|egl|osmesa
// --fps F, an animation's pace (unset: AnimationSettings' default).
void add_fps_option(CommandOptions& options, std::optional<double>& fps, const std::string& does);
// The platform --gl chose, where auto takes UMBRA_GL's: checked once, before
// any work, a UsageError as a bad --gl is.
HeadlessGl gl_with_environment(HeadlessGl chosen);

}  // namespace umbra
