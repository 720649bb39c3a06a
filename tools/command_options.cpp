#include "tools/command_options.hpp"

#include <algorithm>

#include <CLI/CLI.hpp>

#include "tools/nearest_word.hpp"

namespace umbra {

CommandOptions::CommandOptions() : app_(std::make_unique<CLI::App>()) {
  app_->set_help_flag();        // umbra prints its own help text
  app_->allow_extras(true);     // unknown options are reported below, in umbra's words
  app_->positionals_at_end(false);
}

CommandOptions::~CommandOptions() = default;

void CommandOptions::value(const std::string& names, std::function<void(const std::string&, const std::string&)> take) {
  CLI::Option* option = app_->add_option_function<std::string>(names, [](const std::string&) {});
  for (const std::string& name : option->get_lnames()) long_names_.push_back("--" + name);
  const std::string shown = option->get_name();  // the long name, as messages show it
  option->each([take = std::move(take), shown](const std::string& text) { take(shown, text); });
  option->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  for (const std::string& name : option->get_lnames()) value_names_.push_back("--" + name);
  for (const std::string& name : option->get_snames()) value_names_.push_back("-" + name);
}

void CommandOptions::flag(const std::string& names, bool& set) {
  for (const std::string& name : app_->add_flag(names, set)->get_lnames()) long_names_.push_back("--" + name);
}

void CommandOptions::positionals(std::vector<std::string>& arguments) {
  app_->add_option("arguments", arguments)->allow_extra_args();
  positionals_ = &arguments;
}

void CommandOptions::parse(const std::vector<std::string>& all) {
  // "--" ends the options, as POSIX utilities have it: whatever follows is
  // an argument, even "-name.obj".
  const auto end_of_options = std::find(all.begin(), all.end(), "--");
  const std::vector<std::string> argv(all.begin(), end_of_options);
  if (std::find(argv.begin(), argv.end(), "--list-options") != argv.end()) throw OptionList{long_names_};
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

void add_help_option(CommandOptions& options, bool& help) { options.flag("-h,--help", help); }

void add_output_option(CommandOptions& options, std::string& path) {
  options.value("-o,--output", [&](const std::string&, const std::string& t) { path = t; });
}

}  // namespace umbra
