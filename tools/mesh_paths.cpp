#include "tools/mesh_paths.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>

#include "mesh/file_extension.hpp"
#include "mesh/io/mapped_file.hpp"
#include "mesh/io/mesh_format.hpp"
#include "tools/command_line.hpp"

namespace umbra {
namespace {

// A folder's files that are meshes by content, or by name unless their
// content is plainly something else. Links are followed, to files and to
// folders, but a folder is searched once however many links lead to it (a
// link to a folder above it would lead round for ever); a link to nothing,
// and a second way into a folder, are passed over and said.
void meshes_in_folder(const std::string& folder, MeshPaths& out) {
  namespace fs = std::filesystem;
  std::vector<std::string> found;
  std::vector<std::pair<std::string, std::string>> passed_over;
  std::vector<std::string> unsupported;
  std::set<fs::path> searched;  // folders, links resolved
  std::error_code ec;
  searched.insert(fs::canonical(folder, ec));
  fs::recursive_directory_iterator it(folder, fs::directory_options::skip_permission_denied | fs::directory_options::follow_directory_symlink,
                                      ec),
      end;
  for (; !ec && it != end; it.increment(ec)) {
    std::error_code type_ec;
    const std::string path = it->path().string();
    if (it->is_symlink(type_ec) && !it->exists(type_ec)) {
      passed_over.emplace_back(path, "a link to nothing (" + fs::read_symlink(it->path(), type_ec).string() + ")");
      continue;
    }
    if (it->is_directory(type_ec)) {
      const fs::path real = fs::canonical(it->path(), type_ec);
      if (!searched.insert(real).second) {
        it.disable_recursion_pending();
        passed_over.emplace_back(path, "a link to the folder " + real.string() + ", searched once already");
      }
      continue;
    }
    if (!it->is_regular_file(type_ec)) {
      // A FIFO or a device with a mesh's name: never opened, but said.
      struct stat st {};
      if (!mesh_format_of(path).empty() && ::stat(path.c_str(), &st) == 0)
        passed_over.emplace_back(path, non_regular_kind(st.st_mode) + ", not a mesh file");
      continue;
    }
    if (!detect_mesh_format_of_file(path).empty()) {
      found.push_back(path);
    } else if (!mesh_format_of(path).empty()) {
      const std::string other = other_known_format_of_file(path);
      if (other.empty()) found.push_back(path);  // a mesh too broken to tell: its reader says why
      else passed_over.emplace_back(path, other + ", not a mesh");
    } else {
      unsupported.push_back(path);
    }
  }
  if (ec) throw UsageError("cannot search the folder \"" + folder + "\": " + ec.message());
  std::sort(found.begin(), found.end());
  std::sort(passed_over.begin(), passed_over.end());
  for (const std::string& path : found) out.names.push_back(fs::path(path).lexically_relative(folder).string()), out.roots.push_back(folder);
  out.meshes.insert(out.meshes.end(), found.begin(), found.end());
  out.passed_over.insert(out.passed_over.end(), passed_over.begin(), passed_over.end());
  std::sort(unsupported.begin(), unsupported.end());
  out.unsupported.insert(out.unsupported.end(), unsupported.begin(), unsupported.end());
}

}  // namespace

MeshPaths expand_mesh_paths(const std::vector<std::string>& arguments) {
  MeshPaths paths;
  for (const std::string& argument : arguments) {
    std::error_code ec;
    if (std::filesystem::is_directory(argument, ec)) meshes_in_folder(argument, paths);
    else
      paths.meshes.push_back(argument), paths.names.push_back(std::filesystem::path(argument).filename().string()),
          paths.roots.emplace_back();
  }
  return paths;
}

std::string unsupported_summary(const std::vector<std::string>& unsupported) {
  std::map<std::string, size_t> by_extension;
  for (const std::string& path : unsupported) {
    const std::string extension = lowercase_extension(path);
    ++by_extension[extension.empty() ? "no extension" : extension];
  }
  std::vector<std::pair<std::string, size_t>> counts(by_extension.begin(), by_extension.end());
  std::stable_sort(counts.begin(), counts.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  std::string line = "passed over " + std::to_string(unsupported.size()) + (unsupported.size() == 1 ? " file" : " files") +
                     " in no format umbra reads:";
  for (size_t i = 0; i < counts.size(); ++i) line += (i ? ", " : " ") + std::to_string(counts[i].second) + " " + counts[i].first;
  return line;
}

std::string unsupported_reason() { return "no format umbra reads (" + mesh_format_names() + ")"; }

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

std::optional<MeshPaths> found_mesh_paths(const std::vector<std::string>& arguments, const std::string& command) {
  try {
    MeshPaths found = expand_mesh_paths(arguments);
    if (found.meshes.empty())
      throw UsageError("no mesh files in " + arguments[0] + (arguments.size() > 1 ? " or the others" : "") +
                       (found.unsupported.empty() ? "" : " (" + unsupported_summary(found.unsupported) + ")"));
    return found;
  } catch (const UsageError& e) {
    std::cerr << "umbra " << command << ": " << e.what() << "\n";
    return std::nullopt;
  }
}

}  // namespace umbra
