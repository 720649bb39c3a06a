#include "tools/picture_names.hpp"

#include <algorithm>
#include <filesystem>
#include <map>

namespace umbra {

std::vector<std::string> distinct_picture_names(const std::vector<std::string>& paths, std::vector<std::string> names,
                                                const std::vector<std::string>& roots) {
  namespace fs = std::filesystem;
  // The folder each name is relative to, walked up one step each time a
  // name meets another.
  std::vector<fs::path> above(paths.size());
  for (size_t i = 0; i < paths.size(); ++i) {
    std::error_code ec;
    above[i] = fs::absolute(roots[i].empty() ? fs::path(paths[i]).parent_path() : fs::path(roots[i]), ec).lexically_normal();
  }
  for (bool lengthened = true; lengthened;) {
    lengthened = false;
    std::map<std::string, std::vector<size_t>> by_name;
    for (size_t i = 0; i < names.size(); ++i) by_name[names[i]].push_back(i);
    for (const auto& [name, files] : by_name) {
      if (files.size() < 2) continue;
      // Files alike in name and folder are one file, named twice.
      if (std::all_of(files.begin(), files.end(), [&](size_t i) { return above[i] == above[files[0]]; })) continue;
      for (const size_t i : files) {
        fs::path folder = above[i];
        while (!folder.empty() && folder.filename().empty() && folder != folder.root_path()) folder = folder.parent_path();  // "a/b/"
        if (folder.filename().empty()) continue;  // at the root: nothing left to tell it by
        names[i] = (fs::path(folder.filename()) / names[i]).string();
        above[i] = folder.parent_path();
        lengthened = true;
      }
    }
  }
  // The same file named twice: numbered in order.
  std::map<std::string, int> seen;
  for (std::string& name : names)
    if (const int count = ++seen[name]; count > 1) name += " (" + std::to_string(count) + ")";
  return names;
}

}  // namespace umbra
