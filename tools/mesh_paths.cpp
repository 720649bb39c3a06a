#include "tools/mesh_paths.hpp"

#include <algorithm>
#include <filesystem>

#include "mesh/io/mesh_format.hpp"
#include "tools/command_line.hpp"

namespace umbra {
namespace {

// Unreadable and without a mesh extension: not one of the meshes.
bool has_mesh_name_or_content(const std::filesystem::path& path) {
  return !mesh_format_of(path.string()).empty() || !detect_mesh_format_of_file(path.string()).empty();
}

std::vector<std::string> meshes_in_folder(const std::string& folder) {
  namespace fs = std::filesystem;
  std::vector<std::string> found;
  std::error_code ec;
  fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec), end;
  for (; !ec && it != end; it.increment(ec)) {
    std::error_code type_ec;
    if (it->is_regular_file(type_ec) && has_mesh_name_or_content(it->path())) found.push_back(it->path().string());
  }
  if (ec) throw UsageError("cannot search the folder \"" + folder + "\": " + ec.message());
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace

std::vector<std::string> expand_mesh_paths(const std::vector<std::string>& arguments) {
  std::vector<std::string> paths;
  for (const std::string& argument : arguments) {
    std::error_code ec;
    if (!std::filesystem::is_directory(argument, ec)) {
      paths.push_back(argument);
      continue;
    }
    const std::vector<std::string> found = meshes_in_folder(argument);
    paths.insert(paths.end(), found.begin(), found.end());
  }
  return paths;
}

Shard parse_shard(const std::string& option, const std::string& text) {
  const size_t slash = text.find('/');
  if (slash == std::string::npos) throw UsageError(option + " expects K/N such as 0/4 (the first of four parts), got \"" + text + "\"");
  Shard shard;
  shard.count = size_t(parse_int_in(option + " count N", text.substr(slash + 1), 1, 1000000));
  shard.index = size_t(parse_int_in(option + " index K", text.substr(0, slash), 0, 1000000));
  if (shard.index >= shard.count)
    throw UsageError(option + " counts parts from 0: K must be below N, got \"" + text + "\"");
  return shard;
}

std::vector<std::string> shard_of(const std::vector<std::string>& paths, const Shard& shard) {
  const size_t first = paths.size() * shard.index / shard.count;
  const size_t end = paths.size() * (shard.index + 1) / shard.count;
  return {paths.begin() + std::ptrdiff_t(first), paths.begin() + std::ptrdiff_t(end)};
}

}  // namespace umbra
