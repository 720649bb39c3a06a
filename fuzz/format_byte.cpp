#include "fuzz/format_byte.hpp"

#include <algorithm>
#include <string_view>
#include <utility>
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

// The byte each extension owns: the FNV-1a hash of its name (Fowler, Noll
// and Vo), folded to a byte, or the next free byte where another took it
// (in the order given, which is the formats' table's).
std::array<int, 256> owners(const std::vector<std::string_view>& extensions) {
  std::array<int, 256> owner;
  owner.fill(-1);
  for (size_t k = 0; k < extensions.size() && k < owner.size(); ++k) {
    uint32_t hash = 2166136261u;
    for (const char c : extensions[k]) hash = (hash ^ uint8_t(c)) * 16777619u;
    size_t byte = (hash ^ hash >> 8 ^ hash >> 16 ^ hash >> 24) & 0xFF;
    while (owner[byte] >= 0) byte = (byte + 1) % owner.size();
    owner[byte] = int(k);
  }
  return owner;
}

// A list of extensions, the byte each owns, and what each byte names: the
// extension of the nearest owned byte at or above it (round past 255 to 0).
struct Numbering {
  std::vector<std::string_view> extensions;
  std::array<int, 256> owner;
  std::array<std::string_view, 256> meanings;
};

Numbering numbering_of(std::vector<std::string_view> extensions) {
  Numbering n{std::move(extensions), {}, {}};
  n.owner = owners(n.extensions);
  int last = -1;
  for (int pass = 0; pass < 2; ++pass)
    for (int byte = 255; byte >= 0; --byte) {
      if (n.owner[size_t(byte)] >= 0) last = n.owner[size_t(byte)];
      if (last >= 0) n.meanings[size_t(byte)] = n.extensions[size_t(last)];
    }
  return n;
}

const Numbering& numbered(Readers readers) {
  static const Numbering umbras = numbering_of(extensions_of(Readers::kUmbras)), every = numbering_of(extensions_of(Readers::kEvery));
  return readers == Readers::kUmbras ? umbras : every;
}

}  // namespace

std::array<std::string_view, 256> byte_meanings(const std::vector<std::string_view>& extensions) {
  return numbering_of(extensions).meanings;
}

std::string mesh_format_name_of_byte(uint8_t byte, Readers readers) {
  // The name's extension picks the reader for content too broken to tell;
  // glTF's external buffers are looked for in a folder that does not exist.
  return "/nonexistent/fuzz" + std::string(numbered(readers).meanings[byte]);
}

std::optional<uint8_t> mesh_format_byte_of(const std::string& path, Readers readers) {
  const Numbering& numbering = numbered(readers);
  const std::vector<std::string_view>& extensions = numbering.extensions;
  // umbra's own readers are numbered by format: any of a format's extensions names it.
  const std::string id = mesh_format_of(path);
  const MeshFormat* format = mesh_format_by_id(id);
  const std::string extension = readers == Readers::kUmbras && format ? std::string(format->extensions.front()) : lowercase_extension(path);
  const auto found = std::find(extensions.begin(), extensions.end(), extension);
  if (found == extensions.end()) return std::nullopt;
  const std::array<int, 256>& owner = numbering.owner;
  return uint8_t(std::find(owner.begin(), owner.end(), int(found - extensions.begin())) - owner.begin());
}

}  // namespace umbra::fuzz
