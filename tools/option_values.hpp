#pragma once
// The values options take, each checked as one kind: a finite number, a
// whole number in a range, degrees, WIDTHxHEIGHT, X,Y,Z, an up axis, a
// method, a colour. Each throws UsageError naming the option and the text.

#include <string>

#include <glm/vec3.hpp>

#include "render/render_method.hpp"
#include "tools/command_options.hpp"

namespace umbra {

double parse_finite_number(const std::string& option, const std::string& text);
int parse_int_in(const std::string& option, const std::string& text, int lowest, int highest);
// A number of degrees from `lowest` to `highest`.
double parse_degrees_in(const std::string& option, const std::string& text, double lowest, double highest);
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

}  // namespace umbra
