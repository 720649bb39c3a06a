#pragma once
// The CAD reader's module (umbra-cad.so, cad_reader.cpp), opened when a
// STEP, IGES or BREP file is read: what it and umbra share.

#include <cstddef>
#include <string>

#include "mesh/io/polygon_soup.hpp"

namespace umbra {

enum class CadFormat { kStep, kIges, kBrep };
inline const char* cad_format_name(CadFormat format) {
  return format == CadFormat::kStep ? "STEP" : format == CadFormat::kIges ? "IGES" : "BREP";
}

// The module's one entry: the file's shape tessellated as `tessellation`
// says into `soup` and 1, or 0 with `error` saying why. STEP and BREP are
// read from `bytes`, IGES from the file at `path`.
using ReadCadEntry = int (*)(const char* bytes, size_t size, const char* path, int format, const CadTessellation* tessellation,
                             PolygonSoup* soup, std::string* error);
constexpr const char* kReadCadEntry = "umbra_read_cad";
constexpr const char* kCadModule = "umbra-cad.so";

}  // namespace umbra
