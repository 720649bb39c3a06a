#pragma once
// The commands' --help texts: the lists that live in tables (methods,
// formats, platforms) filled in, and value lists laid out in columns.

#include <string>
#include <utility>
#include <vector>

namespace umbra {

// A command's --help text with the lists that live in tables filled in
// (the mesh formats are umbra formats' own table):
// {repair extensions}, {picture extensions}, {animation formats},
// {interactive methods} ("auto, zfail, ... or planar")
// and {methods} (each method's name and help, one wrapped entry each, in
// --method's column of umbra render --help).
std::string usage_text(std::string text);
// An option's list of values for --help, a row each: the name from column
// 26, then its help wrapped in a column two spaces right of the longest name.
std::string value_rows(const std::vector<std::pair<std::string, std::string>>& rows);

}  // namespace umbra
