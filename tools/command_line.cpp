#include "tools/command_line.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <CLI/CLI.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "image/animation_file.hpp"
#include "image/picture_file.hpp"
#include "scene/scene_text.hpp"
#include "mesh/check/mesh_repair.hpp"
#include "mesh/io/mesh_format.hpp"
#include "mesh/word_list.hpp"
#include "render/frame_target.hpp"
#include "render/headless_context.hpp"
#include "render/render_method.hpp"
#include "scene/staged_scene.hpp"
#include "scene/up_axis.hpp"
#include "tools/nearest_word.hpp"

namespace umbra {
namespace {

// `words` wrapped to lines of at most `width` columns, every line after the
// first indented by `indent` spaces.
std::string wrapped(const std::string& words, size_t first_column, size_t indent, size_t width) {
  std::string out;
  size_t column = first_column;
  for (size_t at = 0; at < words.size();) {
    const size_t end = std::min(words.find(' ', at), words.size());
    const std::string word = words.substr(at, end - at);
    if (column > first_column && column + 1 + word.size() > width) {
      out += "\n" + std::string(indent, ' ');
      column = indent;
    } else if (column > first_column) {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
    at = end + 1;
  }
  return out;
}

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, from.size(), to);
}

// How umbra bench sweeps the methods, from the method table: "auto, zfail,
// zpass and planar at each N; triangles at each N, in scenes with meshes;
// shadowmap at each map size; raycast, the reference itself".
std::string bench_sweeps() {
  const std::pair<BenchSweep, const char*> sweeps[] = {
      {BenchSweep::kSphereSegments, "at each N"},
      {BenchSweep::kSegmentsWithMeshes, "at each N, in scenes with meshes"},
      {BenchSweep::kMapSizes, "at each map size"},
      {BenchSweep::kReference, "the reference itself"},
  };
  std::vector<std::string> parts;
  for (const auto& [sweep, phrase] : sweeps) {
    std::vector<std::string> names;
    for (const RenderMethod m : all_methods())
      if (method_bench_sweep(m) == sweep) names.push_back(method_name(m));
    if (!names.empty())
      parts.push_back(word_list(names, "and") + (sweep == BenchSweep::kReference ? ", " : " ") + phrase);
  }
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? "" : "; ") + part;
  return text;
}

}  // namespace

std::string value_rows(const std::vector<std::pair<std::string, std::string>>& rows) {
  constexpr size_t kNameColumn = 26, kWidth = 79;
  size_t longest = 0;
  for (const auto& row : rows) longest = std::max(longest, row.first.size());
  const size_t help_column = kNameColumn + longest + 2;
  std::string text;
  for (auto [name, help] : rows) {
    name.resize(longest + 2, ' ');
    text += std::string(kNameColumn, ' ') + name + wrapped(help, help_column, help_column, kWidth) + "\n";
  }
  return text;
}

std::string usage_text(std::string text) {
  constexpr size_t kWidth = 79;
  std::vector<std::pair<std::string, std::string>> methods, platforms;
  std::vector<std::string> interactive;
  for (const RenderMethod m : all_methods()) {
    if (is_interactive(m)) interactive.push_back(method_name(m));
    methods.emplace_back(method_name(m), method_help(m));
  }
  replace_all(text, "{methods}\n", value_rows(methods));
  for (const HeadlessGlRow& row : kHeadlessGlTable) platforms.emplace_back(row.name, row.help);
  replace_all(text, "{gl platforms}\n", value_rows(platforms));
  replace_all(text, "{bench methods}", wrapped(bench_sweeps(), 0, 0, kWidth));
  replace_all(text, "{interactive methods}", word_list(interactive));
  replace_all(text, "{picture extensions}", picture_extensions());
  replace_all(text, "{animation formats}", animation_extensions());
  replace_all(text, "{repair extensions}", mesh_format_extensions(true));
  replace_all(text, "{max hole edges}", std::to_string(kDefaultMaxHoleEdges));
  std::ostringstream deflection, angle;
  deflection << CadTessellation{}.relative_deflection;
  angle << std::round(glm::degrees(CadTessellation{}.angle) * 10.0) / 10.0;
  replace_all(text, "{cad deflection}", deflection.str());
  replace_all(text, "{cad angle}", angle.str());
  return text;
}

CommandOptions::CommandOptions() : app_(std::make_unique<CLI::App>()) {
  app_->set_help_flag();        // umbra prints its own help text
  app_->allow_extras(true);     // unknown options are reported below, in umbra's words
  app_->positionals_at_end(false);
}

CommandOptions::~CommandOptions() = default;

void CommandOptions::value(const std::string& names, std::function<void(const std::string&, const std::string&)> take) {
  CLI::Option* option = app_->add_option_function<std::string>(names, [](const std::string&) {});
  const std::string shown = option->get_name();  // the long name, as messages show it
  option->each([take = std::move(take), shown](const std::string& text) { take(shown, text); });
  option->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  for (const std::string& name : option->get_lnames()) value_names_.push_back("--" + name);
  for (const std::string& name : option->get_snames()) value_names_.push_back("-" + name);
}

void CommandOptions::flag(const std::string& names, bool& set) { app_->add_flag(names, set); }

void CommandOptions::positionals(std::vector<std::string>& arguments) {
  app_->add_option("arguments", arguments)->allow_extra_args();
  positionals_ = &arguments;
}

void CommandOptions::parse(const std::vector<std::string>& all) {
  // "--" ends the options, as POSIX utilities have it: whatever follows is
  // an argument, even "-name.obj".
  const auto end_of_options = std::find(all.begin(), all.end(), "--");
  const std::vector<std::string> argv(all.begin(), end_of_options);
  // CLI11 would say "1 required TEXT missing"; say which option lacks its value.
  if (!argv.empty() && std::find(value_names_.begin(), value_names_.end(), argv.back()) != value_names_.end())
    throw UsageError(argv.back() + " needs a value");
  std::vector<std::string> reversed(argv.rbegin(), argv.rend());  // CLI11 takes them from the back
  try {
    app_->parse(reversed);
  } catch (const CLI::ParseError& e) {
    throw UsageError(e.what());
  }
  for (const std::string& extra : app_->remaining()) {
    if (extra.size() < 2 || extra[0] != '-') continue;
    const std::string option = extra.substr(0, extra.find('='));
    std::vector<std::string> known;
    for (const CLI::Option* o : app_->get_options())
      for (const std::string& name : o->get_lnames()) known.push_back("--" + name);
    throw UsageError("unknown option " + option + did_you_mean(option, known));
  }
  if (end_of_options == all.end()) return;
  if (!positionals_) throw UsageError("takes no arguments, got \"" + (end_of_options + 1 == all.end() ? std::string("--") : *(end_of_options + 1)) + "\"");
  positionals_->insert(positionals_->end(), end_of_options + 1, all.end());
}

double parse_finite_number(const std::string& option, const std::string& text) {
  double value = 0.0;
  const char* first = text.c_str() + (!text.empty() && text[0] == '+');
  const char* last = text.c_str() + text.size();
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last || first == last || !std::isfinite(value))
    throw UsageError(option + " expects a number, got \"" + text + "\"");
  return value;
}

int parse_int_in(const std::string& option, const std::string& text, int lowest, int highest) {
  int value = 0;
  const char* last = text.c_str() + text.size();
  const auto [ptr, ec] = std::from_chars(text.c_str(), last, value);
  if (ec != std::errc() || ptr != last || text.empty() || value < lowest || value > highest)
    throw UsageError(option + " expects a whole number from " + std::to_string(lowest) + " to " +
                     std::to_string(highest) + ", got \"" + text + "\"");
  return value;
}

void parse_size(const std::string& option, const std::string& text, int largest, int& width, int& height) {
  const size_t x = text.find('x');
  if (x == std::string::npos) throw UsageError(option + " expects WIDTHxHEIGHT such as 800x600, got \"" + text + "\"");
  width = parse_int_in(option + " width", text.substr(0, x), 1, largest);
  height = parse_int_in(option + " height", text.substr(x + 1), 1, largest);
}

std::string parse_up_axis(const std::string& option, const std::string& text) {
  if (!is_up_axis(text)) throw UsageError(option + " must be +x, -x, +y, -y, +z or -z, got \"" + text + "\"");
  return text;
}

RenderMethod parse_method(const std::string& option, const std::string& text) {
  if (const auto method = method_from_name(text)) return *method;
  throw UsageError(option + " expects one of " + method_names() + ", got \"" + text + "\"");
}

void add_help_option(CommandOptions& options, bool& help) { options.flag("-h,--help", help); }

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

namespace {

// "X,Y,Z": three finite numbers.
glm::dvec3 parse_point(const std::string& option, const std::string& text) {
  glm::dvec3 p(0.0);
  size_t at = 0;
  for (int k = 0; k < 3; ++k) {
    const size_t comma = k < 2 ? text.find(',', at) : text.size();
    if (comma == std::string::npos || (k == 2 && text.find(',', at) != std::string::npos))
      throw UsageError(option + " expects X,Y,Z such as 0,-3,1.5, got \"" + text + "\"");
    p[k] = parse_finite_number(option, text.substr(at, comma - at));
    at = comma + 1;
  }
  return p;
}

// A number of degrees from `lowest` to `highest`.
double parse_degrees_in(const std::string& option, const std::string& text, double lowest, double highest) {
  const double v = parse_finite_number(option, text);
  if (v > highest || v < lowest) {
    std::ostringstream range;
    range << lowest << " to " << highest;
    throw UsageError(option + " expects degrees from " + range.str() + ", got \"" + text + "\"");
  }
  return v;
}

// The colour names --background, --floor and --color take: CSS's basic
// sixteen (W3C, CSS Color Module Level 3, 2011), grey and its spelling,
// cyan, magenta and orange.
struct NamedColor {
  const char* name;
  uint8_t r, g, b;
};
constexpr NamedColor kColorNames[] = {
    {"black", 0, 0, 0},       {"silver", 192, 192, 192}, {"gray", 128, 128, 128},  {"grey", 128, 128, 128},
    {"white", 255, 255, 255}, {"maroon", 128, 0, 0},     {"red", 255, 0, 0},       {"purple", 128, 0, 128},
    {"fuchsia", 255, 0, 255}, {"magenta", 255, 0, 255},  {"green", 0, 128, 0},     {"lime", 0, 255, 0},
    {"olive", 128, 128, 0},   {"yellow", 255, 255, 0},   {"navy", 0, 0, 128},      {"blue", 0, 0, 255},
    {"teal", 0, 128, 128},    {"aqua", 0, 255, 255},     {"cyan", 0, 255, 255},    {"orange", 255, 165, 0},
};

}  // namespace

glm::dvec3 parse_color(const std::string& option, const std::string& text) {
  for (const NamedColor& c : kColorNames)
    if (text == c.name) return glm::dvec3(c.r, c.g, c.b) / 255.0;
  const auto hex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
  if (text.size() == 7 && text[0] == '#' && std::all_of(text.begin() + 1, text.end(), hex)) {
    glm::dvec3 rgb;
    for (int k = 0; k < 3; ++k) rgb[k] = double(std::stoi(text.substr(1 + 2 * size_t(k), 2), nullptr, 16)) / 255.0;
    return rgb;
  }
  std::vector<std::string> names;
  for (const NamedColor& c : kColorNames) names.push_back(c.name);
  throw UsageError(option + " expects a colour, #rrggbb or a name (" + word_list(names) + "), got \"" + text + "\"" +
                   did_you_mean(text, names));
}

namespace {

// An option whose value `take` checks and keeps, its name then noted in `given`.
void add_noted(CommandOptions& options, std::vector<std::string>& given, const std::string& name,
               std::function<void(const std::string&, const std::string&)> take) {
  options.value(name, [&given, take = std::move(take)](const std::string& o, const std::string& t) {
    take(o, t);
    given.push_back(o);
  });
}

}  // namespace

void add_camera_orbit_options(CommandOptions& options, StageView& v, std::vector<std::string>& given) {
  const auto add = [&](const std::string& name, std::function<void(const std::string&, const std::string&)> take) {
    add_noted(options, given, name, std::move(take));
  };
  add("--camera-azimuth", [&](const std::string& o, const std::string& t) { v.camera_azimuth_deg = parse_finite_number(o, t); });
  // Short of the poles, where the floor's up would be the view's direction.
  add("--camera-elevation", [&](const std::string& o, const std::string& t) {
    v.camera_elevation_deg = parse_degrees_in(o, t, -89.9, 89.9);
  });
  add("--camera-zoom", [&](const std::string& o, const std::string& t) {
    v.camera_zoom = parse_finite_number(o, t);
    // Past these the eye meets the model's middle, or the model is a speck.
    if (!(v.camera_zoom >= kLeastCameraZoom && v.camera_zoom <= kMostCameraZoom))
      throw UsageError(o + " expects a factor from " + number_text(kLeastCameraZoom) + " to " + number_text(kMostCameraZoom) + ", got \"" +
                       t + "\"");
  });
}

void add_staging_options(CommandOptions& options, StagingOptions& staging, std::vector<std::string>& given) {
  StageView& v = staging.view;
  const auto add = [&](const std::string& name, std::function<void(const std::string&, const std::string&)> take) {
    add_noted(options, given, name, std::move(take));
  };
  add("--up", [&](const std::string& o, const std::string& t) { staging.up = parse_up_axis(o, t); });
  add_camera_orbit_options(options, v, given);
  add("--fov", [&](const std::string& o, const std::string& t) { v.fov_deg = parse_degrees_in(o, t, 1.0, 170.0); });
  options.flag("--orthographic", v.orthographic);
  add("--eye", [&](const std::string& o, const std::string& t) { v.eye = parse_point(o, t); });
  add("--target", [&](const std::string& o, const std::string& t) { v.target = parse_point(o, t); });
  add("--light-azimuth", [&](const std::string& o, const std::string& t) { v.light_azimuth_deg = parse_finite_number(o, t); });
  add("--light-elevation", [&](const std::string& o, const std::string& t) {
    v.light_elevation_deg = parse_degrees_in(o, t, -90.0, 90.0);
  });
  add("--light", [&](const std::string& o, const std::string& t) { v.light = parse_point(o, t); });
  add("--floor", [&](const std::string& o, const std::string& t) {
    staging.no_floor = t == "none";
    staging.floor_catches_shadow = t == "shadow-catcher";
    if (!staging.no_floor && !staging.floor_catches_shadow) staging.floor_color = parse_color(o, t);
  });
  add("--color", [&](const std::string& o, const std::string& t) { staging.model_color = parse_color(o, t); });
  options.flag("--plain", staging.plain_model);
  options.flag("--flat", staging.flat);
  add("--crease-angle", [&](const std::string& o, const std::string& t) {
    staging.crease_deg = parse_degrees_in(o, t, 0.0, 180.0);
    staging.crease_given = true;
  });
  // Not a staging option only: a scene's own background gives way to it.
  options.value("--background", [&](const std::string& o, const std::string& t) {
    staging.background = t == "transparent" ? Background{glm::dvec3(0.0), true} : Background{parse_color(o, t), false};
  });
}

void note_staging_flags(const StagingOptions& staging, std::vector<std::string>& given) {
  if (staging.plain_model) given.push_back("--plain");
  if (staging.flat) given.push_back("--flat");
  if (staging.view.orthographic) given.push_back("--orthographic");
}

StagingOptions staging_for(StagingOptions staging, const RenderSettings& settings) {
  staging.frame_aspect = double(settings.width) / settings.height;
  staging.frame_pixels = size_t(settings.width) * size_t(settings.height);
  staging.width = settings.width, staging.height = settings.height;
  return staging;
}

void require_consistent_staging(const StagingOptions& staging) {
  const StageView& v = staging.view;
  if (v.light && (v.light_azimuth_deg || v.light_elevation_deg))
    throw UsageError("--light places the light outright; --light-azimuth and --light-elevation place it by angles: give one or the other");
  if (v.eye && v.target && *v.eye == *v.target) throw UsageError("--eye and --target are the same point: the camera would look nowhere");
  if (v.orthographic && v.fov_deg != StageView{}.fov_deg)
    throw UsageError("--fov is a perspective's lens; an --orthographic camera has none (its framing sets how much it sees)");
  if (v.eye && v.camera_zoom != 1.0)
    throw UsageError("--camera-zoom scales the framing's distance, which --eye replaces: give one or the other");
  if (v.eye && v.target && glm::length(glm::cross(*v.target - *v.eye, glm::dvec3(0, 0, 1))) == 0.0)
    throw UsageError("--eye is straight above or below --target: the staged camera keeps +z up, so it cannot look along it");
}

void require_staged(const std::vector<std::string>& given, const std::string& path) {
  if (given.empty() || is_mesh_file(path)) return;
  throw UsageError(given.front() + " is for a mesh file on its own, which umbra stages; \"" + path +
                   "\" is not one (a scene has its own camera and lights)");
}

void add_reading_options(CommandOptions& options, ReadOptions& reading, bool maps) {
  if (maps) options.flag("--any-texture-path", reading.anywhere);
  options.value("--cad-deflection", [&](const std::string& o, const std::string& t) {
    const double fraction = parse_finite_number(o, t);
    // Finer than a millionth of the model makes meshes of billions of
    // triangles; coarser than a tenth, no recognisable shape.
    if (!(fraction >= 1e-6 && fraction <= 0.1))
      throw UsageError(o + " expects a fraction of the model's size from 1e-06 to 0.1, got \"" + t + "\"");
    reading.cad.relative_deflection = fraction;
  });
  options.value("--cad-angle", [&](const std::string& o, const std::string& t) {
    reading.cad.angle = glm::radians(parse_degrees_in(o, t, 1.0, 90.0));
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

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec, ea, eb;
  if (a == b || std::filesystem::equivalent(a, b, ec)) return true;
  // Names of files that need not exist yet (a picture about to be drawn):
  // the same once made absolute and resolved as far as they exist.
  const std::filesystem::path ca = std::filesystem::weakly_canonical(std::filesystem::absolute(a, ea), ea);
  const std::filesystem::path cb = std::filesystem::weakly_canonical(std::filesystem::absolute(b, eb), eb);
  return !ea && !eb && ca == cb;
}

void require_other_than_input(const std::string& option, const std::string& output, const std::string& input) {
  if (input == "-") return;  // standard input, read whole before anything is written
  if (same_file(output, input)) throw UsageError(option + " would overwrite its input \"" + input + "\"; name another file");
}

void require_picture_name(const std::string& option, const std::string& path) {
  if (picture_format_of(path)) return;
  const std::string extension = std::filesystem::path(path).extension().string();
  // An animation's name, for a picture: the option that makes one is missing.
  if (animation_format_of(path))
    throw UsageError(option + " " + path + " names an animation, which --turntable N makes (or --views N); a picture is a " +
                     picture_extensions() + " file");
  throw UsageError(option + " " + path + (extension.empty() ? " has no extension" : ": umbra does not write " + extension + " pictures") +
                   "; name a " + picture_extensions() + " file, or - for PNG on standard output");
}

void add_output_option(CommandOptions& options, std::string& path) {
  options.value("-o,--output", [&](const std::string&, const std::string& t) { path = t; });
}

}  // namespace umbra
