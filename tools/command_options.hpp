#pragma once
// One command's options, parsed by CLI11 (Debian's libcli11-dev): `--opt
// value` and `--opt=value` both work, and messages are umbra's own ("--size
// expects WIDTHxHEIGHT such as 800x600, got ..."). Each option is defined
// once, with what --help says of it, in render_options.hpp,
// staging_options.hpp or the command's own parse function, and every command
// that takes one calls the same function: the parser, the options of
// --help (and so the man page), --list-options, docs/options.md and
// Python's keywords all come from that one definition.

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

// What --help says of an option: the name of its value ("DEG", "X,Y,Z") and
// what it does. `does` is wrapped to the help's width up to its first
// newline, and names the tables' lists as usage_text takes them
// ("{picture extensions}"); what follows a newline is kept as it is (a
// value list: "{methods}").
struct OptionHelp {
  std::string value;
  std::string does;
};

// One command's options. Values reach the command through the callbacks
// given here, which check them and throw UsageError with the message to show.
class CommandOptions {
 public:
  CommandOptions();
  ~CommandOptions();
  CommandOptions(const CommandOptions&) = delete;
  CommandOptions& operator=(const CommandOptions&) = delete;

  // An option with a value; `names` as CLI11 takes them: "-o,--output"
  // (--help shows the first long name; the others are older names that
  // still work).
  void value(const std::string& names, const OptionHelp& help,
             std::function<void(const std::string& option, const std::string& text)> take);
  void flag(const std::string& names, bool& set, const std::string& does);
  // A paragraph of --help before the options defined next (what a group of
  // them shares); "" for an empty line alone.
  void paragraph(const std::string& text);
  // -h, --help: parse then throws HelpRequest.
  void help_option();
  // The arguments that are not options, in order.
  void positionals(std::vector<std::string>& arguments);
  // Throws UsageError for an unknown option, a missing value or a value
  // its callback refuses. Everything after "--" is a positional argument.
  void parse(const std::vector<std::string>& argv);

  // With --list-options among its arguments, parse throws OptionList: the
  // long names of the options defined here, in order (what `umbra COMMAND
  // --list-options` prints, for shell completion); with
  // --list-options=markdown, their table for docs/options.md.

  // The options' part of --help, in the order they were defined: each
  // option's names and value, and what it does in a column beside them.
  std::string help_text() const;
  // The same as a Markdown table (a paragraph between tables).
  std::string markdown() const;

 private:
  struct Row {
    std::string names;  // as --help shows them: "-o, --output"
    OptionHelp help;
    bool paragraph = false;
  };
  std::unique_ptr<CLI::App> app_;
  std::vector<std::string> long_names_;
  std::vector<Row> rows_;
  bool takes_help_ = false, help_given_ = false;
  std::vector<std::string>* positionals_ = nullptr;
  std::vector<std::string> value_names_;  // to say "--size needs a value"
};

// What CommandOptions::parse throws for --list-options: the text to print.
struct OptionList {
  std::string text;
};
// What it throws for -h or --help: the options' part of --help.
struct HelpRequest {
  std::string options;
};

// A command's --help: `usage` with its "{options}" replaced by the
// options' help and the tables' lists filled in (usage_text).
std::string command_help(const std::string& usage, const std::string& options);

// The --help that `parse` (a command's parse function) makes of `usage`.
template <typename Parse>
std::string help_of(const std::string& usage, Parse parse) {
  try {
    parse(std::vector<std::string>{"--help"});
  } catch (const HelpRequest& help) {
    return command_help(usage, help.options);
  }
  return usage;
}

// Runs `parse` over a command's arguments. On a usage error prints it with a
// hint to --help and returns 2; when the options ask for help prints
// `usage` (command_help) and returns 0, and for --list-options the list;
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
    std::cout << list.text;
    return 0;
  } catch (const HelpRequest& help) {
    std::cout << command_help(usage, help.options);
    return 0;
  }
  return std::nullopt;
}

void add_output_option(CommandOptions& options, std::string& path, const OptionHelp& help);  // -o, --output
// An option whose value `take` checks and keeps, its name then noted in
// `given`, for messages that name the options given (the first of them, or
// whether one was).
void add_noted_value(CommandOptions& options, std::vector<std::string>& given, const std::string& names, const OptionHelp& help,
                     std::function<void(const std::string& option, const std::string& text)> take);

}  // namespace umbra
