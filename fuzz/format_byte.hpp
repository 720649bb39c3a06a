#pragma once
// The mesh fuzzers' first byte: which format's name the rest of their input
// is read under. mesh_fuzzer names umbra's own readers (a format by its first
// extension); library_fuzzer every extension of every format this build
// reads, the libraries' too (Assimp picks its importer by the name).
//
// Each extension owns the byte its name hashes to (or the next free one, where
// another owns that), and the bytes below it down to the next owned one: a
// row added to the formats' table takes its own byte and a share of the bytes
// below it, and every other byte keeps its meaning, as a fuzzer's corpus and
// its regressions need.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace umbra::fuzz {

enum class Readers { kUmbras, kEvery };

// What each byte names, of `extensions` (distinct, at most 256; at least one).
std::array<std::string_view, 256> byte_meanings(const std::vector<std::string_view>& extensions);

// A file name with the extension byte `byte` names, in a folder that does not exist.
std::string mesh_format_name_of_byte(uint8_t byte, Readers readers = Readers::kUmbras);
// The byte that names `path`'s extension (its own byte); none for another.
std::optional<uint8_t> mesh_format_byte_of(const std::string& path, Readers readers = Readers::kUmbras);

}  // namespace umbra::fuzz
