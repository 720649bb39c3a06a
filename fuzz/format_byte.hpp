#pragma once
// The mesh fuzzer's first byte: which format's name the rest of its input
// is read under, numbered as mesh_formats() lists umbra's own readers.

#include <cstdint>
#include <optional>
#include <string>

namespace umbra::fuzz {

// A file name with the extension of the format numbered `byte` modulo the
// number of formats, in a folder that does not exist.
std::string mesh_format_name_of_byte(uint8_t byte);
// The byte that names the format of `path`'s extension; none for another.
std::optional<uint8_t> mesh_format_byte_of(const std::string& path);

}  // namespace umbra::fuzz
