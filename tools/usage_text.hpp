#pragma once
// The commands' --help texts: the lists that live in tables (methods,
// formats, platforms) filled in, and value lists laid out in columns.

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace umbra {

// A command's --help text with the lists that live in tables filled in
// (the mesh formats are umbra formats' own table):
// {repair extensions}, {picture extensions}, {animation formats},
// {interactive methods} ("auto, zfail, ... or planar"), {inexact methods}
// (those whose shadows are not the reference's: "shadowmap, planar and zpass")
// and {methods} (each method's name and help, one wrapped entry each, in
// --method's column of umbra render --help).
// In kMarkdown, for docs/options.md, a value list is one line of
// "`name`: help" entries.
enum class UsageStyle { kTerminal, kMarkdown };
std::string usage_text(std::string text, UsageStyle style = UsageStyle::kTerminal);
// `words` wrapped to lines of at most `width` columns, starting at column
// `first_column`, every line after the first indented by `indent` spaces.
std::string wrapped_words(const std::string& words, size_t first_column, size_t indent, size_t width);
// An option's list of values for --help, a row each: the name from column
// 26, then its help wrapped in a column two spaces right of the longest name.
std::string value_rows(const std::vector<std::pair<std::string, std::string>>& rows);

}  // namespace umbra
