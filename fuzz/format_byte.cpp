#include "fuzz/format_byte.hpp"

#include <algorithm>
#include <string_view>
#include <vector>

#include "mesh/file_extension.hpp"
#include "mesh/io/mesh_format.hpp"

namespace umbra::fuzz {
namespace {

// The extensions a byte numbers: umbra's own readers' first (numbered alike
// whatever libraries a build has), or every built format's every one.
std::vector<std::string_view> extensions_of(Readers readers) {
  std::vector<std::string_view> extensions;
  for (const MeshFormat& f : mesh_formats()) {
    if (readers == Readers::kUmbras && f.fuzzed) extensions.push_back(f.extensions.front());
    if (readers == Readers::kEvery && f.built) extensions.insert(extensions.end(), f.extensions.begin(), f.extensions.end());
  }
  return extensions;
}

const std::vector<std::string_view>& numbered(Readers readers) {
  static const std::vector<std::string_view> umbras = extensions_of(Readers::kUmbras), every = extensions_of(Readers::kEvery);
  return readers == Readers::kUmbras ? umbras : every;
}

}  // namespace

std::string mesh_format_name_of_byte(uint8_t byte, Readers readers) {
  // The name's extension picks the reader for content too broken to tell;
  // glTF's external buffers are looked for in a folder that does not exist.
  const std::vector<std::string_view>& extensions = numbered(readers);
  return "/nonexistent/fuzz" + std::string(extensions[byte % extensions.size()]);
}

std::optional<uint8_t> mesh_format_byte_of(const std::string& path, Readers readers) {
  const std::vector<std::string_view>& extensions = numbered(readers);
  // umbra's own readers are numbered by format: any of a format's extensions names it.
  const std::string id = mesh_format_of(path);
  const MeshFormat* format = mesh_format_by_id(id);
  const std::string extension = readers == Readers::kUmbras && format ? std::string(format->extensions.front()) : lowercase_extension(path);
  const auto found = std::find(extensions.begin(), extensions.end(), extension);
  if (found == extensions.end()) return std::nullopt;
  return uint8_t(found - extensions.begin());
}

}  // namespace umbra::fuzz
