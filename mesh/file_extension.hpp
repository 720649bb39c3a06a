#pragma once
// A file name's extension as the formats' tables hold theirs: lower case,
// dot first (".stl" for PART.STL), "" for none.

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace umbra {

inline std::string lowercase(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return text;
}

inline std::string lowercase_extension(const std::string& path) {
  return lowercase(std::filesystem::path(path).extension().string());
}

}  // namespace umbra
