#pragma once
// Which mesh format a file is in: by its content first (PLY, OFF and GLB
// magic, a zip with a .model part for 3MF, binary STL's size, ascii STL's
// "solid ... facet", glTF's JSON "asset", OBJ's statements), with
// the file name's extension as the fallback for content too broken to tell.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "mesh/io/mesh_writers.hpp"
#include "mesh/io/polygon_soup.hpp"

namespace umbra {

// One row per format umbra reads. Detection, the readers' dispatch, the
// usage and error texts, --repair's outputs, the fuzzers' format byte and
// the tests all iterate this table: adding a format is a reader, a row, a
// test and the docs (docs/design.md).
struct MeshFormat {
  std::string_view id;                       // "obj": what detect_mesh_format returns
  std::string_view name;                     // "OBJ", as messages list it
  std::vector<std::string_view> extensions;  // lower case, dot first: the name's fallback
  // Plainly this format by a signature that binary data can carry (a magic
  // number, a size); tried for every row before any text test.
  bool (*has_signature)(std::string_view bytes);
  // Plainly this format as text: the file's first 64 KiB, known to be text.
  bool (*has_text)(std::string_view head);
  PolygonSoup (*read)(std::string_view bytes, const std::string& path, const ReadOptions& maps);
  MeshWriter write;  // how --repair writes it (mesh_writers.hpp); null where it cannot
  // The axis that points up by the format's convention, which a model staged
  // on its own stands on: glTF +Y and 3MF +Z by their specifications, STL +Z
  // as printing and CAD tools write it, OBJ, PLY and OFF +Y as most
  // exporters write them.
  std::string_view up;
  // Where one row holds formats of several conventions (Assimp's), the up
  // axis of the file at `path` by its name; null where `up` says it.
  std::string (*up_by_name)(const std::string& path) = nullptr;
  // Read by umbra's own code (and tinygltf and lib3mf under it), which the
  // mesh fuzzer covers; not Assimp's importers nor Open CASCADE, whose
  // crashes are theirs and cost only their file in a folder run.
  bool fuzzed = true;
  // What reads it, as `umbra formats` says (at most 24 characters).
  std::string_view reader = "umbra";
  // Whether this build reads it (its library found when it was built).
  bool built = true;
};

// Every format, in the order messages list them and the fuzzers number them.
const std::vector<MeshFormat>& mesh_formats();
// The row with this id; nullptr for none.
const MeshFormat* mesh_format_by_id(std::string_view id);
// "OBJ, OFF, PLY, STL, glTF or 3MF": the names of every format.
std::string mesh_format_names();
// ".obj, .off, .ply, .stl, .gltf, .glb or .3mf": every extension, or those
// of the formats --repair writes.
std::string mesh_format_extensions(bool repair_writes_only = false);

// The id of the format `bytes` (a whole file) plainly are, by signature
// first, then as text; "" when they are none, or too broken to say.
std::string detect_mesh_format(std::string_view bytes);

// The same, then by `path`'s name for a format told by name alone (Assimp's:
// told_by_name_alone), unless the bytes are plainly something else (an
// image, a PDF; markup, UTF-16 text and zip archives are what some of them are).
std::string detect_mesh_format(std::string_view bytes, const std::string& path);
// Whether `format` has no test of content, and is told by name alone.
bool told_by_name_alone(const MeshFormat& format);

// The same for the file at `path`, read by memory mapping; "" too when it
// cannot be read (whoever reads it next says why).
std::string detect_mesh_format_of_file(const std::string& path);

// The up axis the file at `path` has by its format's convention
// (MeshFormat::up), or "+y" where its format cannot be told.
std::string up_axis_of_file(const std::string& path);

// The id of the format whose extension `path` has (any case), or "".
std::string mesh_format_of(const std::string& path);

// What `bytes` are when they are plainly some other format (UTF-16 text, a zip
// archive with no 3D model part, a JPEG or PNG image, a PDF, an XML document
// such as COLLADA), or "".
std::string other_known_format(std::string_view bytes);

// The same for the file at `path`; "" too when it cannot be read.
std::string other_known_format_of_file(const std::string& path);

// The most bytes a scene or mesh file that starts with `head` (its first 64
// KiB, or all of it) can hold, where its start bounds it: a binary file with
// none of the formats' signatures can only be a binary STL, whose count says
// its size. None where it may run to any length (text, PLY, glTF, 3MF).
std::optional<size_t> most_bytes_of_input(std::string_view head);

// Text: no NUL and no control bytes but whitespace in `head`.
bool looks_like_text(std::string_view head);

// "the file is empty" or "the file holds only blank lines", where `bytes`
// hold no statement at all (of any format, a scene's too); else "".
std::string blank_content(std::string_view bytes);

// What `bytes` look like, for the message when they are no mesh format:
// blank_content's words, "binary data", "UTF-16 text", "text starting with
// \"...\"".
std::string describe_content(std::string_view bytes);

}  // namespace umbra
