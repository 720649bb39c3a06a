#pragma once
// Small helpers for reading command-line arguments with clear errors.

#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "render/render_method.hpp"

namespace umbra {

// A mistake in how the command was called; printed with a hint to --help, exit 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Walks the arguments of one command.
class Arguments {
 public:
  explicit Arguments(std::vector<std::string> args) : args_(std::move(args)) {}
  bool done() const { return next_ >= args_.size(); }
  const std::string& take() { return args_[next_++]; }
  // The value after option `option`; UsageError when there is none.
  const std::string& value_of(const std::string& option);

 private:
  std::vector<std::string> args_;
  size_t next_ = 0;
};

// Runs `parse` over a command's arguments. On a usage error prints it with a
// hint to --help and returns 2; when the options ask for help prints `usage`
// and returns 0; otherwise returns nothing and the command goes on.
template <typename Options, typename Parse>
std::optional<int> parse_command_line(const char* command, const char* usage, const std::vector<std::string>& argv,
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
// "WxH", each between 1 and `largest`.
void parse_size(const std::string& option, const std::string& text, int largest, int& width, int& height);

}  // namespace umbra
