#pragma once
// The readers behind read_polygon_soup, one per format, each over the file's
// bytes. Each checks what its format requires and throws InputError naming the
// file and, where there is one, the line.

#include <string>
#include <string_view>
#include <vector>

#include "mesh/io/cad_module.hpp"
#include "mesh/io/polygon_soup.hpp"

namespace umbra {

PolygonSoup read_obj(std::string_view text, const std::string& path, const ReadOptions& maps = {});
// The same, read on every core in stretches of about `chunk_bytes` bytes or
// more (read_obj takes 1 MiB): the soup, and the first error, are the same
// however the file is split.
PolygonSoup read_obj(std::string_view text, const std::string& path, size_t chunk_bytes, const ReadOptions& maps = {});
PolygonSoup read_off(std::string_view text, const std::string& path);
PolygonSoup read_stl(std::string_view bytes, const std::string& path);  // ascii or binary
PolygonSoup read_ply(std::string_view bytes, const std::string& path);  // ascii or binary
// .gltf or .glb; external buffers (and images) beside `path`
PolygonSoup read_gltf(std::string_view bytes, const std::string& path, const ReadOptions& maps = {});
// Whether read_gltf hands these bytes to Assimp's glTF importers (glTF 1.0,
// Draco-compressed meshes), in a build with Assimp.
bool gltf_needs_assimp(std::string_view bytes);
PolygonSoup read_3mf(std::string_view bytes, const std::string& path);
// CAD exchange files through Open CASCADE, tessellated, in the module
// umbra-cad.so opened on first use (cad_module.hpp; built with Open
// CASCADE only: UMBRA_HAVE_OCCT). Throws InputError naming the file, and
// where the module cannot be opened, why.
PolygonSoup read_cad(std::string_view bytes, const std::string& path, CadFormat format, const CadTessellation& tessellation);

// The formats umbra does not parse itself, through Assimp (built with it
// only: UMBRA_HAVE_ASSIMP); the files it names are read only as `maps`
// lets texture maps be.
PolygonSoup read_assimp(std::string_view bytes, const std::string& path, const ReadOptions& maps);
// Assimp's extensions (".3ds", ".dae", ...) but those umbra reads itself
// and those too generic or holding no mesh (.xml, .raw, .prj, motion).
std::vector<std::string_view> assimp_extensions();
// The up axis by the convention of the tool that writes the file at `path`
// (by its name): +z for 3ds Max's, Blender's, AutoCAD's, IFC's and the
// Quake engines' formats, +y for the rest (Collada's importer turns its own
// files' up axis to +y).
std::string assimp_up_axis(const std::string& path);

// How many bytes (1 to 1023) follow the last triangle of `bytes` read as a
// binary STL with at least one triangle; 0 when the size is exact, when so
// many would follow that the bytes are no binary STL, or when the records do
// not look like STL's (a number that is not finite, a facet normal whose
// length is neither 0 nor about 1).
size_t binary_stl_trailing_bytes(std::string_view bytes);
// The most bytes a binary STL starting with `head` (84 bytes or more) may
// hold: its header, the triangles its count says, and the most trailing
// bytes the reader passes over.
size_t most_binary_stl_bytes(std::string_view head);

// Throws a located error when a polygon refers to a point the file lacks.
void require_corners_in_range(const PolygonSoup& soup);

}  // namespace umbra
