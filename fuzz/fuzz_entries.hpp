#pragma once
// What the fuzzers drive, shared with the regression test that replays every
// input they ever crashed on (fuzz/regressions/). Each returns normally for
// any bytes: a valid input is processed, a bad one ends in InputError, which
// is caught here. Anything else (a crash, a sanitizer report, another
// exception) is a bug.

#include <cstddef>
#include <cstdint>

namespace umbra::fuzz {

// The bytes as a scene file (in a folder that does not exist, so `mesh`
// statements fail to open their file), then its render plan for every light
// as the renderer would make it, all on the CPU.
void scene_input(const uint8_t* data, size_t size);

// The first byte picks the format by its name (format_byte.hpp; the
// content decides where it can), the rest is the file;
// then the check's analysis, and the mesh's shadow volume from a few fixed
// lights, which must have no boundary and only finite vertices (or true
// directions at infinity): a volume that breaks either throws
// std::logic_error, which the fuzzer reports as a crash.
// Content that goes to a library's reader (Assimp, Open CASCADE) returns
// at once: their bugs are theirs, and CI runs this fuzzer.
void mesh_input(const uint8_t* data, size_t size);

// The same through every reader this build has, Assimp's importers and Open
// CASCADE's included, the first byte naming any extension of any format
// (format_byte.hpp). Not run by CI (./build.sh fuzz-libraries).
void library_input(const uint8_t* data, size_t size);

// The bytes as a transforms.json (umbra render --cameras), its cameras for a
// staged tetrahedron; each camera it accepts must give finite, unit pixel
// rays at its picture's corners, or std::logic_error.
void cameras_input(const uint8_t* data, size_t size);

}  // namespace umbra::fuzz
