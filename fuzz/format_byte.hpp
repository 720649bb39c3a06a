#pragma once
// The mesh fuzzers' first byte: which format's name the rest of their input
// is read under. mesh_fuzzer numbers umbra's own readers as mesh_formats()
// lists them; library_fuzzer numbers every extension of every format this
// build reads, the libraries' too (Assimp picks its importer by the name).

#include <cstdint>
#include <optional>
#include <string>

namespace umbra::fuzz {

enum class Readers { kUmbras, kEvery };

// A file name with the extension numbered `byte` modulo the number of
// extensions, in a folder that does not exist.
std::string mesh_format_name_of_byte(uint8_t byte, Readers readers = Readers::kUmbras);
// The byte that names `path`'s extension; none for another.
std::optional<uint8_t> mesh_format_byte_of(const std::string& path, Readers readers = Readers::kUmbras);

}  // namespace umbra::fuzz
