#include "tools/command_options.hpp"

#include <algorithm>

#include <CLI/CLI.hpp>

#include "tools/nearest_word.hpp"
#include "tools/usage_text.hpp"

namespace umbra {

CommandOptions::CommandOptions() : app_(std::make_unique<CLI::App>()) {
  app_->set_help_flag();        // umbra prints its own help text
  app_->allow_extras(true);     // unknown options are reported below, in umbra's words
  app_->positionals_at_end(false);
}

CommandOptions::~CommandOptions() = default;

namespace {

// "-o, --output" of CLI11's "-o,--output,--older-name": the short names and
// the first long one.
std::string shown_names(const CLI::Option& option) {
  std::string names;
  for (const std::string& name : option.get_snames()) names += "-" + name + ", ";
  return names + "--" + option.get_lnames().front();
}

}  // namespace

void CommandOptions::value(const std::string& names, const OptionHelp& help,
                           std::function<void(const std::string&, const std::string&)> take) {
  // "--quality,--jpeg-quality": the long names after the first are older
  // names, each parsed as an option of its own so that messages name the
  // one typed; --help shows the first.
  std::vector<std::string> spellings(1);
  for (size_t at = 0; at <= names.size();) {
    const size_t end = std::min(names.find(',', at), names.size());
    const std::string name = names.substr(at, end - at);
    const bool older = name.rfind("--", 0) == 0 && spellings.front().find("--") != std::string::npos;
    if (older) spellings.push_back(name);
    else spellings.front() += (spellings.front().empty() ? "" : ",") + name;
    at = end + 1;
  }
  for (const std::string& spelling : spellings) {
    CLI::Option* option = app_->add_option_function<std::string>(spelling, [](const std::string&) {});
    for (const std::string& name : option->get_lnames()) long_names_.push_back("--" + name);
    if (&spelling == &spellings.front()) rows_.push_back({shown_names(*option), help});
    const std::string shown = option->get_name();  // the long name, as messages show it
    option->each([take, shown](const std::string& text) { take(shown, text); });
    option->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    for (const std::string& name : option->get_lnames()) value_names_.push_back("--" + name);
    for (const std::string& name : option->get_snames()) value_names_.push_back("-" + name);
  }
}

void CommandOptions::flag(const std::string& names, bool& set, const std::string& does) {
  const CLI::Option* option = app_->add_flag(names, set);
  for (const std::string& name : option->get_lnames()) long_names_.push_back("--" + name);
  rows_.push_back({shown_names(*option), {"", does}});
}

void CommandOptions::help_option() {
  flag("-h,--help", help_given_, "show this help");
  takes_help_ = true;
}

void CommandOptions::paragraph(const std::string& text) { rows_.push_back({"", {"", text}, true}); }

std::string CommandOptions::help_text() const {
  // The help column: where an option's text starts, beside names of up to
  // kNamesWidth characters (longer ones take a line of their own).
  constexpr size_t kColumn = 24, kNamesWidth = kColumn - 4, kWidth = 79;
  std::string text;
  for (const Row& row : rows_) {
    const std::string expanded = usage_text(row.help.does);
    const size_t newline = expanded.find('\n');
    const std::string first = expanded.substr(0, newline), rest = newline == std::string::npos ? "" : expanded.substr(newline + 1);
    if (row.paragraph) {
      text += "\n" + (first.empty() ? "" : "  " + wrapped_words(first, 2, 2, kWidth) + "\n") + rest;
      continue;
    }
    std::string names = "  " + row.names + (row.help.value.empty() ? "" : " " + row.help.value);
    if (names.size() > kNamesWidth + 2) names += "\n" + std::string(kColumn, ' ');
    else names.resize(kColumn, ' ');
    text += names + wrapped_words(first, kColumn, kColumn, kWidth) + "\n" + rest;
  }
  return text;
}

std::string CommandOptions::markdown() const {
  // A table cell holds no newline and no bare "|".
  const auto cell = [](std::string words) {
    std::string out;
    for (const char c : words) out += c == '\n' ? std::string("<br>") : c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
  };
  std::string text;
  bool in_table = false;
  for (const Row& row : rows_) {
    const std::string expanded = usage_text(row.help.does, UsageStyle::kMarkdown);
    if (row.paragraph) {
      text += (in_table ? "\n" : "") + (expanded.empty() ? "" : expanded + "\n\n");
      in_table = false;
      continue;
    }
    if (!in_table) text += "| option | what it does |\n|---|---|\n";
    in_table = true;
    const std::string names = row.names + (row.help.value.empty() ? "" : " " + row.help.value);
    text += "| `" + cell(names) + "` | " + cell(expanded) + " |\n";
  }
  return text;
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
  if (std::find(argv.begin(), argv.end(), "--list-options") != argv.end()) {
    std::string names;
    for (const std::string& name : long_names_) names += name + "\n";
    throw OptionList{names};
  }
  if (std::find(argv.begin(), argv.end(), "--list-options=markdown") != argv.end()) throw OptionList{markdown()};
  if (takes_help_ && (std::find(argv.begin(), argv.end(), "--help") != argv.end() || std::find(argv.begin(), argv.end(), "-h") != argv.end()))
    throw HelpRequest{help_text()};
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

void add_output_option(CommandOptions& options, std::string& path, const OptionHelp& help) {
  options.value("-o,--output", help, [&](const std::string&, const std::string& t) { path = t; });
}

void add_noted_value(CommandOptions& options, std::vector<std::string>& given, const std::string& names, const OptionHelp& help,
                     std::function<void(const std::string&, const std::string&)> take) {
  options.value(names, help, [&given, take = std::move(take)](const std::string& o, const std::string& t) {
    take(o, t);
    given.push_back(o);
  });
}

std::string command_help(const std::string& usage, const std::string& options) {
  std::string text = usage;
  const size_t at = text.find("{options}");
  if (at != std::string::npos) text.replace(at, 9, options);
  return usage_text(text);
}

}  // namespace umbra
