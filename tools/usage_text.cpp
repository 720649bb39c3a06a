#include "tools/usage_text.hpp"

#include <algorithm>

#include "image/animation_file.hpp"
#include "image/picture_file.hpp"
#include "mesh/io/mesh_format.hpp"
#include "mesh/word_list.hpp"
#include "render/headless_context.hpp"
#include "render/render_method.hpp"

namespace umbra {
namespace {

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) text.replace(at, from.size(), to);
}

// How umbra bench sweeps the methods, from the method table: "auto, zfail,
// zpass and planar at each N; triangles at each N, in scenes with meshes;
// shadowmap at each map size; raycast, the reference itself".
std::string bench_sweeps() {
  const std::pair<BenchSweep, const char*> sweeps[] = {
      {BenchSweep::kSphereSegments, "at each N"},
      {BenchSweep::kSegmentsWithMeshes, "at each N, in scenes with meshes"},
      {BenchSweep::kMapSizes, "at each map size"},
      {BenchSweep::kReference, "the reference itself"},
  };
  std::vector<std::string> parts;
  for (const auto& [sweep, phrase] : sweeps) {
    std::vector<std::string> names;
    for (const RenderMethod m : all_methods())
      if (method_bench_sweep(m) == sweep) names.push_back(method_name(m));
    if (!names.empty())
      parts.push_back(word_list(names, "and") + (sweep == BenchSweep::kReference ? ", " : " ") + phrase);
  }
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? "" : "; ") + part;
  return text;
}

}  // namespace

std::string wrapped_words(const std::string& words, size_t first_column, size_t indent, size_t width) {
  std::string out;
  size_t column = first_column;
  for (size_t at = 0; at < words.size();) {
    const size_t end = std::min(words.find(' ', at), words.size());
    const std::string word = words.substr(at, end - at);
    if (column > first_column && column + 1 + word.size() > width) {
      out += "\n" + std::string(indent, ' ');
      column = indent;
    } else if (column > first_column) {
      out += ' ';
      ++column;
    }
    out += word;
    column += word.size();
    at = end + 1;
  }
  return out;
}

std::string value_rows(const std::vector<std::pair<std::string, std::string>>& rows) {
  constexpr size_t kNameColumn = 26, kWidth = 79;
  size_t longest = 0;
  for (const auto& row : rows) longest = std::max(longest, row.first.size());
  const size_t help_column = kNameColumn + longest + 2;
  std::string text;
  for (auto [name, help] : rows) {
    name.resize(longest + 2, ' ');
    text += std::string(kNameColumn, ' ') + name + wrapped_words(help, help_column, help_column, kWidth) + "\n";
  }
  return text;
}

std::string usage_text(std::string text, UsageStyle style) {
  constexpr size_t kWidth = 79;
  std::vector<std::pair<std::string, std::string>> methods, platforms;
  std::vector<std::string> interactive;
  for (const RenderMethod m : all_methods()) {
    if (is_interactive(m)) interactive.push_back(method_name(m));
    methods.emplace_back(method_name(m), method_help(m));
  }
  // A value list, as --help lays it out or as one line of Markdown.
  const auto rows = [style](const std::vector<std::pair<std::string, std::string>>& list) {
    if (style == UsageStyle::kTerminal) return value_rows(list);
    std::string lines;
    for (const auto& [name, help] : list) lines += (lines.empty() ? "" : "\n") + ("`" + name + "`: " + help);
    return lines;
  };
  replace_all(text, "{methods}\n", rows(methods));
  for (const HeadlessGlRow& row : kHeadlessGlTable) platforms.emplace_back(row.name, row.help);
  replace_all(text, "{gl platforms}\n", rows(platforms));
  replace_all(text, "{bench methods}", style == UsageStyle::kTerminal ? wrapped_words(bench_sweeps(), 0, 0, kWidth) : bench_sweeps());
  replace_all(text, "{interactive methods}", word_list(interactive));
  std::vector<std::string> inexact;  // whose frame antialiasing always draws whole
  for (const RenderMethod m : all_methods())
    if (!draws_exact_shadows(m)) inexact.push_back(method_name(m));
  replace_all(text, "{inexact methods}", word_list(inexact, "and"));
  replace_all(text, "{picture extensions}", picture_extensions());
  replace_all(text, "{animation formats}", animation_extensions());
  replace_all(text, "{animation names}", animation_extensions(false));
  replace_all(text, "{repair extensions}", mesh_format_extensions(true));
  return text;
}

}  // namespace umbra
