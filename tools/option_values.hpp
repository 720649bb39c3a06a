#pragma once
// The values options take, each checked as one kind: a finite number, a
// whole number in a range, degrees, WIDTHxHEIGHT, X,Y,Z, an up axis, a
// method, a colour. Each throws UsageError naming the option and the text.

#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "render/render_method.hpp"
#include "tools/command_options.hpp"

namespace umbra {

// The numbers an option takes, said once: its parse checks them and its
// help says them (ranged).
struct ValueRange {
  double lowest, highest;
};
// `help` with "{range}" in what it does written "LOWEST to HIGHEST", and
// "{default}" as `value` (the field's value before parsing: its default).
OptionHelp ranged(OptionHelp help, ValueRange range, double value);

double parse_finite_number(const std::string& option, const std::string& text);
int parse_int_in(const std::string& option, const std::string& text, int lowest, int highest);
// A number of degrees from `lowest` to `highest`.
double parse_degrees_in(const std::string& option, const std::string& text, double lowest, double highest);
inline double parse_degrees_in(const std::string& option, const std::string& text, ValueRange range) {
  return parse_degrees_in(option, text, range.lowest, range.highest);
}
inline int parse_int_in(const std::string& option, const std::string& text, ValueRange range) {
  return parse_int_in(option, text, int(range.lowest), int(range.highest));
}
// "WxH", each between 1 and `largest`.
void parse_size(const std::string& option, const std::string& text, int largest, int& width, int& height);
// "X,Y,Z": three finite numbers.
glm::dvec3 parse_point(const std::string& option, const std::string& text);
// "+x", "-x", "+y", "-y", "+z" or "-z" (is_up_axis).
std::string parse_up_axis(const std::string& option, const std::string& text);
// One of method_names().
RenderMethod parse_method(const std::string& option, const std::string& text);
// A colour as the options take it: #rrggbb, or a name (black, white, red, ...).
glm::dvec3 parse_color(const std::string& option, const std::string& text);
// The names parse_color takes, in its table's order.
std::vector<std::string> color_names();

}  // namespace umbra
