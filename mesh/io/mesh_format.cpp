#include "mesh/io/mesh_format.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <filesystem>

#include "mesh/file_extension.hpp"
#include "mesh/input_error.hpp"
#include "mesh/io/mapped_file.hpp"
#include "mesh/io/mesh_readers.hpp"
#include "mesh/io/mesh_writers.hpp"
#include "mesh/io/text_scanner.hpp"
#include "mesh/word_list.hpp"

namespace umbra {
namespace {

constexpr size_t kSniffBytes = 1 << 16;  // how far into a text file its first statements are looked for

bool starts_with(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }

bool is_binary_stl(std::string_view bytes) {
  if (bytes.size() < 84) return false;
  uint32_t count = 0;
  for (int i = 3; i >= 0; --i) count = (count << 8) | static_cast<unsigned char>(bytes[80 + size_t(i)]);
  return bytes.size() == 84 + size_t(count) * 50 || binary_stl_trailing_bytes(bytes) > 0;
}

// glTF's JSON: an object with an "asset" member (the one member glTF requires).
bool is_gltf_json(std::string_view head) {
  const size_t first = head.find_first_not_of(" \t\r\n\xef\xbb\xbf");
  return first != std::string_view::npos && head[first] == '{' && head.find("\"asset\"") != std::string_view::npos;
}

// A zip archive (3MF is one) whose part names include a .model part, looked
// for in the local headers at the start and the central directory at the end.
bool is_zip(std::string_view bytes) { return starts_with(bytes, "PK\x03\x04"); }
bool has_model_part(std::string_view bytes) {
  const auto has = [](std::string_view part) { return part.find(".model") != std::string_view::npos; };
  return has(bytes.substr(0, kSniffBytes)) || has(bytes.substr(bytes.size() - std::min(bytes.size(), kSniffBytes)));
}

// The first field of each line, skipping blank lines, up to `max_lines`.
template <typename Visit>
void first_fields(std::string_view head, size_t max_lines, Visit&& visit) {
  TextScanner scanner(head, "");
  for (size_t lines = 0; lines < max_lines && scanner.next_line();) {
    const std::string_view field = scanner.field();
    if (field.empty()) continue;
    ++lines;
    if (!visit(field)) return;
  }
}

bool is_off(std::string_view head) {
  bool off = false;
  first_fields(head, 1000, [&](std::string_view field) {
    if (field.front() == '#') return true;
    off = field.size() >= 3 && field.substr(field.size() - 3) == "OFF" && field.find_first_not_of("CNST4n") == field.size() - 3;
    return false;
  });
  return off;
}

bool is_ascii_stl(std::string_view head) {
  bool solid = false, facet = false;
  first_fields(head, 3, [&](std::string_view field) {
    if (!solid) return solid = is_word(field, "solid");
    facet = is_word(field, "facet") || is_word(field, "endsolid");
    return !facet;
  });
  return facet;
}

// OBJ: a vertex with a number or a face with a vertex index, with only OBJ
// statements and comments before it (NFF's "v" alone on its line, a
// viewpoint, is not OBJ's).
bool is_obj(std::string_view head) {
  static const std::string_view kStatements[] = {
      "v",    "vt",   "vn",   "vp",   "f",     "l",     "p",     "o",      "g",     "s",     "mg",     "mtllib", "usemtl",
      "maplib", "usemap", "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp",
      "end",  "con",  "bevel", "c_interp", "d_interp", "lod", "shadow_obj", "trace_obj", "ctech", "stech", "call", "csh"};
  const auto starts_a_number = [](std::string_view field) {
    double value = 0.0;
    return !field.empty() && std::from_chars(field.data(), field.data() + field.size(), value).ec == std::errc();
  };
  // Three or more corners, each a vertex index that is not 0 (OBJ counts
  // from 1 or from -1), with texture and normal indices after slashes; NFF's
  // fill colour "f 1 0 0" is not a face.
  const auto is_face = [](TextScanner& scanner) {
    size_t corners = 0;
    for (std::string_view corner = scanner.field(); !corner.empty(); corner = scanner.field(), ++corners) {
      const std::string_view vertex = corner.substr(0, corner.find('/'));
      if (vertex.empty()) return false;
      const std::string_view digits = vertex.substr(vertex.front() == '-' ? 1 : 0);
      if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos ||
          digits.find_first_not_of('0') == std::string_view::npos)
        return false;
    }
    return corners >= 3;
  };
  TextScanner scanner(head, "");
  for (size_t lines = 0; lines < 100000 && scanner.next_line();) {
    const std::string_view field = scanner.field();
    if (field.empty() || field.front() == '#') continue;
    ++lines;
    if (std::find(std::begin(kStatements), std::end(kStatements), field) == std::end(kStatements)) return false;
    if (field == "v") return starts_a_number(scanner.field());
    if (field == "f") return is_face(scanner);
  }
  return false;
}

bool never(std::string_view) { return false; }

// STEP's physical file ("ISO-10303-21;" first), but not IFC's, which is
// written the same way with a schema of its own (Assimp's, by name).
bool is_step(std::string_view bytes) {
  const size_t first = bytes.find_first_not_of(" \t\r\n\xef\xbb\xbf");
  if (first == std::string_view::npos || bytes.substr(first, 13) != "ISO-10303-21;") return false;
  const std::string_view head = bytes.substr(0, kSniffBytes);
  const size_t schema = head.find("FILE_SCHEMA");
  return schema == std::string_view::npos || head.substr(schema, 80).find("IFC") == std::string_view::npos;
}

// IGES: 80-column records, each ending in its section's letter and its
// number ("S0000001", "G0000001"): one of the first lines is such a record
// (the first may have lost its leading blanks to the comment skipping).
bool is_iges(std::string_view head) {
  for (int line = 0; line < 3 && !head.empty(); ++line) {
    const size_t end = std::min(head.find('\n'), head.size());
    std::string_view record = head.substr(0, end);
    if (!record.empty() && record.back() == '\r') record.remove_suffix(1);
    if (record.size() == 80 && (record[72] == 'S' || record[72] == 'G') &&
        record.substr(73).find_first_not_of("0123456789") == std::string_view::npos)
      return true;
    head.remove_prefix(std::min(end + 1, head.size()));
  }
  return false;
}

// Open CASCADE's own BREP text, as Draw's and BRepTools' writers start it.
bool is_brep(std::string_view head) {
  return starts_with(head, "DBRep_DrawableShape") || starts_with(head, "CASCADE Topology V");
}

// A CAD file's reader, or where this umbra was built without Open CASCADE,
// the message that says how to build it in.
template <CadFormat kFormat>
PolygonSoup cad_reader(std::string_view bytes, const std::string& path, const ReadOptions& options) {
#ifdef UMBRA_HAVE_OCCT
  return read_cad(bytes, path, kFormat, options.cad);
#else
  (void)bytes, (void)options;
  throw InputError({path, 0, 0},
                   std::string(cad_format_name(kFormat)) + " files need Open CASCADE, which this umbra was built without: "
                                                           "./build.sh installs libocct-data-exchange-dev and builds it in",
                   InputProblem::kUnsupportedFormat);
#endif
}

// `bytes` past the comment lines ('#', as OBJ, OFF and scenes write them)
// and blank lines at its start, however many: what follows tells a text
// format, and a file that opens with 64 KiB of comments is still an OBJ.
std::string_view after_leading_comments(std::string_view bytes) {
  size_t at = 0;
  for (;;) {
    at = bytes.find_first_not_of(" \t\r\n", at);
    if (at == std::string_view::npos) return {};
    if (bytes[at] != '#') return bytes.substr(at);
    at = bytes.find('\n', at);
    if (at == std::string_view::npos) return {};
  }
}

// A reader of a format whose files hold no texture maps that umbra draws.
template <PolygonSoup (*reader)(std::string_view, const std::string&)>
PolygonSoup without_maps(std::string_view bytes, const std::string& path, const ReadOptions&) {
  return reader(bytes, path);
}

}  // namespace

#ifdef UMBRA_HAVE_OCCT
constexpr bool kOpenCascadeBuilt = true;
#else
constexpr bool kOpenCascadeBuilt = false;
#endif

const std::vector<MeshFormat>& mesh_formats() {
  static const std::vector<MeshFormat> formats{
      {"obj", "OBJ", {".obj"}, never, is_obj, [](std::string_view b, const std::string& p, const ReadOptions& t) { return read_obj(b, p, t); },
       write_obj_file, "+y", nullptr, true, "umbra, with its .mtl"},
      {"off", "OFF", {".off"}, never, is_off, without_maps<read_off>, write_off_file, "+y"},
      {"ply", "PLY", {".ply"}, [](std::string_view b) { return starts_with(b, "ply\n") || starts_with(b, "ply\r"); }, never,
       without_maps<read_ply>, write_ply_file, "+y"},
      {"stl", "STL", {".stl"}, is_binary_stl, is_ascii_stl, without_maps<read_stl>, write_stl_file, "+z"},
      {"gltf", "glTF", {".gltf", ".glb"}, [](std::string_view b) { return starts_with(b, "glTF"); }, is_gltf_json, read_gltf,
       nullptr, "+y", nullptr, true, "tinygltf (1.0: Assimp)"},
      {"3mf", "3MF", {".3mf"}, [](std::string_view b) { return is_zip(b) && has_model_part(b); }, never, without_maps<read_3mf>,
       write_3mf_file, "+z", nullptr, true, "lib3mf"},
      // CAD exchange files, through Open CASCADE; Z up, as CAD tools model.
      {"step", "STEP", {".step", ".stp"}, is_step, never, cad_reader<CadFormat::kStep>, nullptr, "+z", nullptr, false,
       "Open CASCADE", kOpenCascadeBuilt},
      {"iges", "IGES", {".iges", ".igs"}, never, is_iges, cad_reader<CadFormat::kIges>, nullptr, "+z", nullptr, false,
       "Open CASCADE", kOpenCascadeBuilt},
      {"brep", "BREP", {".brep", ".brp"}, never, is_brep, cad_reader<CadFormat::kBrep>, nullptr, "+z", nullptr, false,
       "Open CASCADE", kOpenCascadeBuilt},
#ifdef UMBRA_HAVE_ASSIMP
      // Told by name alone (the importers' own tests would open every file
      // of a folder): after umbra's own readers, whose errors are located.
      {"assimp", "Assimp's formats", assimp_extensions(), never, never, read_assimp, nullptr, "+y", assimp_up_axis, false,
       "Assimp's importers"},
#endif
  };
  return formats;
}

const MeshFormat* mesh_format_by_id(std::string_view id) {
  for (const MeshFormat& f : mesh_formats())
    if (f.id == id) return &f;
  return nullptr;
}

std::string mesh_format_names() {
  std::vector<std::string_view> names;
  for (const MeshFormat& f : mesh_formats()) names.push_back(f.name);
  return word_list(names);
}

std::string mesh_format_extensions(bool repair_writes_only) {
  std::vector<std::string_view> extensions;
  for (const MeshFormat& f : mesh_formats())
    if (f.write || !repair_writes_only) extensions.insert(extensions.end(), f.extensions.begin(), f.extensions.end());
  return word_list(extensions);
}

std::string detect_mesh_format(std::string_view bytes) {
  if (starts_with(bytes, "\xef\xbb\xbf")) bytes.remove_prefix(3);  // a UTF-8 byte-order mark
  for (const MeshFormat& f : mesh_formats())
    if (f.has_signature(bytes)) return std::string(f.id);
  if (!looks_like_text(bytes.substr(0, kSniffBytes))) return "";
  const std::string_view head = after_leading_comments(bytes).substr(0, kSniffBytes);
  if (!looks_like_text(head)) return "";
  for (const MeshFormat& f : mesh_formats())
    if (f.has_text(head)) return std::string(f.id);
  return "";
}

std::string detect_mesh_format(std::string_view bytes, const std::string& path) {
  if (std::string format = detect_mesh_format(bytes); !format.empty()) return format;
  // A format told by name alone, unless the content is plainly a picture
  // or a document: markup, UTF-16 text and archives are what some of them
  // are made of.
  const MeshFormat* named = mesh_format_by_id(mesh_format_of(path));
  if (!named || !told_by_name_alone(*named)) return "";
  const std::string other = other_known_format(bytes);
  const bool picture = starts_with(other, "a JPEG") || starts_with(other, "a PNG") || starts_with(other, "a PDF");
  return picture ? "" : std::string(named->id);
}

bool told_by_name_alone(const MeshFormat& format) { return format.has_signature == never && format.has_text == never; }

std::string detect_mesh_format_of_file(const std::string& path) {
  try {
    return detect_mesh_format(MappedFile(path).bytes(), path);
  } catch (const InputError&) {
    return "";
  }
}

std::string up_axis_of_file(const std::string& path) {
  const MeshFormat* format = mesh_format_by_id(detect_mesh_format_of_file(path));
  if (!format) return "+y";
  return format->up_by_name ? format->up_by_name(path) : std::string(format->up);
}

std::string mesh_format_of(const std::string& path) {
  const std::string ext = lowercase_extension(path);
  for (const MeshFormat& f : mesh_formats())
    for (const std::string_view e : f.extensions)
      if (e == ext) return std::string(f.id);
  return "";
}

std::string other_known_format(std::string_view bytes) {
  if (starts_with(bytes, "\xff\xfe") || starts_with(bytes, "\xfe\xff")) return "UTF-16 text";
  if (is_zip(bytes)) return "a zip archive without a 3D model part";
  if (starts_with(bytes, "\xff\xd8\xff")) return "a JPEG image";
  if (starts_with(bytes, "\x89PNG")) return "a PNG image";
  if (starts_with(bytes, "%PDF")) return "a PDF document";
  if (starts_with(bytes, "<?xml") || starts_with(bytes, "<COLLADA")) return "an XML document";
  return "";
}

std::string other_known_format_of_file(const std::string& path) {
  try {
    return other_known_format(MappedFile(path).bytes());
  } catch (const InputError&) {
    return "";
  }
}

std::optional<size_t> most_bytes_of_input(std::string_view head) {
  if (head.size() < 84 || is_zip(head) || looks_like_text(head.substr(0, kSniffBytes))) return std::nullopt;
  for (const MeshFormat& f : mesh_formats())
    if (f.id != "stl" && f.has_signature(head)) return std::nullopt;
  return most_binary_stl_bytes(head);
}

bool looks_like_text(std::string_view head) {
  return std::none_of(head.begin(), head.end(), [](char ch) {
    const auto c = static_cast<unsigned char>(ch);
    return c == 0 || (c < 0x20 && c != '\n' && c != '\r' && c != '\t' && c != '\f' && c != '\v');
  });
}

std::string blank_content(std::string_view bytes) {
  if (bytes.find_first_not_of(" \t\r\n\f\v") != std::string_view::npos) return "";
  return bytes.empty() ? "the file is empty" : "the file holds only blank lines";
}

std::string describe_content(std::string_view bytes) {
  if (const std::string blank = blank_content(bytes); !blank.empty()) return blank;
  if (const std::string other = other_known_format(bytes); !other.empty()) return other;
  const std::string_view head = bytes.substr(0, kSniffBytes);
  if (!looks_like_text(head)) return "binary data";
  std::string_view first;
  first_fields(head, 1, [&](std::string_view field) {
    first = field;
    return false;
  });
  if (first.empty()) return "blank lines for its first 64 KiB";
  return "text starting with " + quote_field(first);
}

}  // namespace umbra
