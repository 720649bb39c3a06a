#pragma once
// The commands' options, parsed by CLI11 (Debian's libcli11-dev): each option
// is defined once, in the functions below, and every command that takes it
// calls the same one; `--opt value` and `--opt=value` both work. Messages
// are umbra's own: "--size expects WIDTHxHEIGHT such as 800x600, got ...".

#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/headless_context.hpp"
#include "render/render_method.hpp"
#include "render/render_plan.hpp"
#include "scene/staged_scene.hpp"

namespace CLI {
class App;
}

namespace umbra {

// A mistake in how the command was called; printed with a hint to --help, exit 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One command's options. Values reach the command through the callbacks
// given here, which check them and throw UsageError with the message to show.
class CommandOptions {
 public:
  CommandOptions();
  ~CommandOptions();
  CommandOptions(const CommandOptions&) = delete;
  CommandOptions& operator=(const CommandOptions&) = delete;

  // An option with a value; `names` as CLI11 takes them: "-o,--output".
  void value(const std::string& names, std::function<void(const std::string& option, const std::string& text)> take);
  void flag(const std::string& names, bool& set);
  // The arguments that are not options, in order.
  void positionals(std::vector<std::string>& arguments);
  // Throws UsageError for an unknown option, a missing value or a value
  // its callback refuses. Everything after "--" is a positional argument.
  void parse(const std::vector<std::string>& argv);

 private:
  std::unique_ptr<CLI::App> app_;
  std::vector<std::string>* positionals_ = nullptr;
  std::vector<std::string> value_names_;  // to say "--size needs a value"
};

// A command's --help text with the lists that live in tables filled in
// (the mesh formats are umbra formats' own table):
// {repair extensions}, {picture extensions}, {animation formats},
// {interactive methods} ("auto, zfail, ... or planar")
// and {methods} (each method's name and help, one wrapped entry each, in
// --method's column of umbra render --help).
std::string usage_text(std::string text);
// An option's list of values for --help, a row each: the name from column
// 26, then its help wrapped in a column two spaces right of the longest name.
std::string value_rows(const std::vector<std::pair<std::string, std::string>>& rows);

// Runs `parse` over a command's arguments. On a usage error prints it with a
// hint to --help and returns 2; when the options ask for help prints `usage`
// and returns 0; otherwise returns nothing and the command goes on.
template <typename Options, typename Parse>
std::optional<int> parse_command_line(const char* command, const std::string& usage, const std::vector<std::string>& argv,
                                      Parse parse, Options& options) {
  try {
    options = parse(argv);
  } catch (const UsageError& e) {
    std::cerr << "umbra " << command << ": " << e.what() << "\n(see umbra " << command << " --help)\n";
    return 2;
  }
  if (options.help) {
    std::cout << usage;
    return 0;
  }
  return std::nullopt;
}

double parse_finite_number(const std::string& option, const std::string& text);
int parse_int_in(const std::string& option, const std::string& text, int lowest, int highest);
// One of method_names().
RenderMethod parse_method(const std::string& option, const std::string& text);
// "+x", "-x", "+y", "-y", "+z" or "-z" (is_up_axis).
std::string parse_up_axis(const std::string& option, const std::string& text);
// "WxH", each between 1 and `largest`.
void parse_size(const std::string& option, const std::string& text, int largest, int& width, int& height);

// The options that several commands take, each defined once.
constexpr double kLeastCameraZoom = 0.01, kMostCameraZoom = 100.0;  // --camera-zoom's range
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
void add_help_option(CommandOptions& options, bool& help);                            // -h, --help
void add_size_option(CommandOptions& options, int& width, int& height, bool* given = nullptr);               // --size WxH
void add_light_angle_option(CommandOptions& options, double& degrees);                // --light-angle DEG
void add_segments_option(CommandOptions& options, int& segments);                     // --segments N
void add_method_option(CommandOptions& options, RenderMethod& method);                // --method M
void add_map_size_option(CommandOptions& options, int& texels);                       // --map-size N
void add_antialias_option(CommandOptions& options, std::optional<int>& samples);       // --antialias N (1 to 4)
void add_output_option(CommandOptions& options, std::string& path);                   // -o, --output
void add_gl_option(CommandOptions& options, HeadlessGl& gl);                         // --gl auto|egl|osmesa
// The platform --gl chose, where auto takes UMBRA_GL's: checked once, before
// any work, a UsageError as a bad --gl is.
HeadlessGl gl_with_environment(HeadlessGl chosen);
// A colour as the options take it: #rrggbb, or a name (black, white, red, ...).
glm::dvec3 parse_color(const std::string& option, const std::string& text);
// How a mesh file on its own is staged: --up AXIS; the camera's
// --camera-azimuth, --camera-elevation, --camera-zoom, --fov, --eye and
// --target; the light's --light-azimuth, --light-elevation and --light;
// --floor COLOR|none|shadow-catcher, --color COLOR, --plain; the model's
// shading, --flat or --crease-angle DEG. The names of those given (the flags
// aside: note_staging_flags adds them once parsed) are added to `given`, for
// a command to refuse them where nothing is staged. Also
// --background COLOR|transparent, which a scene file takes too.
void add_staging_options(CommandOptions& options, StagingOptions& staging, std::vector<std::string>& given);
// Of those, the camera's orbit alone: --camera-azimuth, --camera-elevation
// and --camera-zoom (umbra check --picture takes them).
void add_camera_orbit_options(CommandOptions& options, StageView& view, std::vector<std::string>& given);
// Adds the staging flags that were given (--plain, --flat) to `given`.
void note_staging_flags(const StagingOptions& staging, std::vector<std::string>& given);
// `staging` for a picture of `settings`' size: framed for its shape.
StagingOptions staging_for(StagingOptions staging, const RenderSettings& settings);
// A UsageError for staging options that contradict each other: --light with
// --light-azimuth or --light-elevation, --eye at --target.
void require_consistent_staging(const StagingOptions& staging);
// A UsageError naming the first of `given` when `path` is not a mesh file
// (a scene has its own camera and lights).
void require_staged(const std::vector<std::string>& given, const std::string& path);
// How mesh files are read: --cad-deflection F and --cad-angle DEG (how
// finely STEP, IGES and BREP surfaces are cut into triangles); with `maps`,
// --any-texture-path too.
void add_reading_options(CommandOptions& options, ReadOptions& reading, bool maps);

// A UsageError when `path`, given to `option`, is not a picture's name that
// umbra writes (picture_file.hpp): .png, .jpg, .jpeg, or - for standard output.
void require_picture_name(const std::string& option, const std::string& path);

// Whether `a` and `b` name one file: the same words, or one file by two
// names (links, "./"), or, where one does not exist yet, the same path once
// made absolute and resolved as far as it exists.
bool same_file(const std::string& a, const std::string& b);
// A UsageError when the output `option` names would overwrite the input `input`.
void require_other_than_input(const std::string& option, const std::string& output, const std::string& input);

}  // namespace umbra
