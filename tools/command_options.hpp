#pragma once
// One command's options, parsed by CLI11 (Debian's libcli11-dev): `--opt
// value` and `--opt=value` both work, and messages are umbra's own ("--size
// expects WIDTHxHEIGHT such as 800x600, got ..."). The options themselves are
// defined once each, in render_options.hpp, staging_options.hpp and
// output_paths.hpp, and every command that takes one calls the same function.

#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

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

  // With --list-options among its arguments, parse throws OptionList: the
  // long names of the options defined here, in order (what `umbra COMMAND
  // --list-options` prints, for shell completion, and for the tests that
  // hold each command's --help and docs to its parser).

 private:
  std::unique_ptr<CLI::App> app_;
  std::vector<std::string> long_names_;
  std::vector<std::string>* positionals_ = nullptr;
  std::vector<std::string> value_names_;  // to say "--size needs a value"
};

// What CommandOptions::parse throws for --list-options.
struct OptionList {
  std::vector<std::string> names;
};

// Runs `parse` over a command's arguments. On a usage error prints it with a
// hint to --help and returns 2; when the options ask for help prints `usage`
// and returns 0, and for --list-options its options' names, one a line;
// otherwise returns nothing and the command goes on.
template <typename Options, typename Parse>
std::optional<int> parse_command_line(const char* command, const std::string& usage, const std::vector<std::string>& argv,
                                      Parse parse, Options& options) {
  try {
    options = parse(argv);
  } catch (const UsageError& e) {
    std::cerr << "umbra " << command << ": " << e.what() << "\n(see umbra " << command << " --help)\n";
    return 2;
  } catch (const OptionList& list) {
    for (const std::string& name : list.names) std::cout << name << "\n";
    return 0;
  }
  if (options.help) {
    std::cout << usage;
    return 0;
  }
  return std::nullopt;
}

void add_help_option(CommandOptions& options, bool& help);            // -h, --help
void add_output_option(CommandOptions& options, std::string& path);   // -o, --output

}  // namespace umbra
