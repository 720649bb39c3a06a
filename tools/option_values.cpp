#include "tools/option_values.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

#include "mesh/word_list.hpp"
#include "scene/scene_text.hpp"
#include "scene/up_axis.hpp"
#include "tools/nearest_word.hpp"

namespace umbra {

OptionHelp ranged(OptionHelp help, ValueRange range, double value) {
  const auto replace = [&help](const std::string& from, const std::string& to) {
    const size_t at = help.does.find(from);
    if (at != std::string::npos) help.does.replace(at, from.size(), to);
  };
  replace("{range}", number_text(range.lowest) + " to " + number_text(range.highest));
  replace("{default}", number_text(value));
  return help;
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

double parse_degrees_in(const std::string& option, const std::string& text, double lowest, double highest) {
  const double v = parse_finite_number(option, text);
  if (v > highest || v < lowest) {
    std::ostringstream range;
    range << lowest << " to " << highest;
    throw UsageError(option + " expects degrees from " + range.str() + ", got \"" + text + "\"");
  }
  return v;
}

namespace {

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

std::vector<std::string> color_names() {
  std::vector<std::string> names;
  for (const NamedColor& c : kColorNames) names.push_back(c.name);
  return names;
}

glm::dvec3 parse_color(const std::string& option, const std::string& text) {
  for (const NamedColor& c : kColorNames)
    if (text == c.name) return glm::dvec3(c.r, c.g, c.b) / 255.0;
  const auto hex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
  if (text.size() == 7 && text[0] == '#' && std::all_of(text.begin() + 1, text.end(), hex)) {
    glm::dvec3 rgb;
    for (int k = 0; k < 3; ++k) rgb[k] = double(std::stoi(text.substr(1 + 2 * size_t(k), 2), nullptr, 16)) / 255.0;
    return rgb;
  }
  const std::vector<std::string> names = color_names();
  throw UsageError(option + " expects a colour, #rrggbb or a name (" + word_list(names) + "), got \"" + text + "\"" +
                   did_you_mean(text, names));
}

}  // namespace umbra
