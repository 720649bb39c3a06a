#include "tools/command_line.hpp"

#include <charconv>
#include <cmath>

namespace umbra {

const std::string& Arguments::value_of(const std::string& option) {
  if (done()) throw UsageError(option + " needs a value");
  return take();
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

RenderMethod parse_method(const std::string& option, const std::string& text) {
  if (const auto method = method_from_name(text)) return *method;
  throw UsageError(option + " expects one of " + method_names() + ", got \"" + text + "\"");
}

}  // namespace umbra
