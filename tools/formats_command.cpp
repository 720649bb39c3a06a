#include "tools/formats_command.hpp"

#include <iostream>

#include "mesh/io/mesh_format.hpp"
#include "tools/command_line.hpp"

namespace umbra {
namespace {

const std::string kFormatsUsage = R"(usage: umbra formats

Lists every mesh format umbra reads: its extensions, whether a file is told
to be in it by its content (whatever its name) or by its name, what reads
it, and whether this build was built with that reader's library.

options:
{options})";

constexpr size_t kNameWidth = 18, kExtensionsWidth = 30;

}  // namespace

std::string formats_table() {
  std::string text = "format            extensions                    told by  read by\n";
  for (const MeshFormat& f : mesh_formats()) {
    // Extensions wrapped in their column, the rest on the first line.
    std::vector<std::string> lines(1);
    for (const std::string_view e : f.extensions) {
      if (!lines.back().empty() && lines.back().size() + 1 + e.size() > kExtensionsWidth - 2) lines.emplace_back();
      lines.back() += (lines.back().empty() ? "" : " ") + std::string(e);
    }
    std::string first = std::string(f.name);
    first.resize(kNameWidth, ' ');
    std::string extensions = lines[0];
    extensions.resize(kExtensionsWidth, ' ');
    std::string told = told_by_name_alone(f) ? "name" : "content";
    told.resize(9, ' ');
    text += first + extensions + told + std::string(f.reader) + (f.built ? "" : " (not built in)") + "\n";
    for (size_t k = 1; k < lines.size(); ++k) text += std::string(kNameWidth, ' ') + lines[k] + "\n";
  }
  return text;
}

int run_formats_command(const std::vector<std::string>& argv) {
  struct FormatsOptions {
  } options;
  const auto parse = [](const std::vector<std::string>& words) {
    CommandOptions command;
    command.help_option();
    command.parse(words);
    return FormatsOptions{};
  };
  if (const auto exit_status = parse_command_line("formats", kFormatsUsage, argv, parse, options)) return *exit_status;
  std::cout << formats_table();
  return 0;
}

}  // namespace umbra
