#include "fuzz/format_byte.hpp"

#include <vector>

#include "mesh/io/mesh_format.hpp"

namespace umbra::fuzz {
namespace {

// umbra's own readers (MeshFormat::fuzzed), numbered alike whatever
// libraries a build has.
std::vector<MeshFormat> fuzzed_formats() {
  std::vector<MeshFormat> formats;
  for (const MeshFormat& f : mesh_formats())
    if (f.fuzzed) formats.push_back(f);
  return formats;
}

}  // namespace

std::string mesh_format_name_of_byte(uint8_t byte) {
  // The name's extension picks the reader for content too broken to tell;
  // glTF's external buffers are looked for in a folder that does not exist.
  static const std::vector<MeshFormat> formats = fuzzed_formats();
  return "/nonexistent/fuzz" + std::string(formats[byte % formats.size()].extensions.front());
}

std::optional<uint8_t> mesh_format_byte_of(const std::string& path) {
  const std::string id = mesh_format_of(path);
  static const std::vector<MeshFormat> formats = fuzzed_formats();
  for (size_t k = 0; k < formats.size(); ++k)
    if (formats[k].id == id) return uint8_t(k);
  return std::nullopt;
}

}  // namespace umbra::fuzz
