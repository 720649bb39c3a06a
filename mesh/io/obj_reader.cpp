// Wavefront OBJ: `v x y z [w]` points and `f i j k ...` polygons whose corners
// are `v`, `v/vt`, `v//vn` or `v/vt/vn`, counted from 1, or from the end when
// negative; `usemtl` gives the faces after it a material of the `mtllib`
// files beside the OBJ (Kd, Ks, Ns, and map_Kd with the faces' `vt` texture
// coordinates); the corners' `vn` normals are kept for a picture. Groups and
// other texture maps are skipped. Large files are read in stretches of lines
// on every core.
#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <utility>
#include <vector>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <glm/common.hpp>

#include "mesh/io/mapped_file.hpp"
#include "mesh/io/mesh_readers.hpp"
#include "mesh/io/text_scanner.hpp"
#include "mesh/io/texture_file.hpp"

namespace umbra {
namespace {

// The point index (from 0) of one face corner such as "7/3/2" or "-1//4".
uint32_t corner_index(TextScanner& scanner, std::string_view corner, size_t points_so_far) {
  const std::string_view vertex = corner.substr(0, corner.find('/'));
  int64_t value = 0;
  const char* first = vertex.data();
  const char* last = vertex.data() + vertex.size();
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec != std::errc() || ptr != last || vertex.empty())
    scanner.fail("expected a vertex index (as in \"f 1 2 3\" or \"f 1/1/1 2/2/2 3/3/3\"), got " + quote_field(corner));
  if (value == 0) scanner.fail("vertex indices count from 1 (or from -1 backwards); 0 is not an index");
  const int64_t index = value > 0 ? value - 1 : int64_t(points_so_far) + value;
  if (index < 0)
    scanner.fail("relative vertex index " + std::to_string(value) + " points before the first vertex (only " +
                 std::to_string(points_so_far) + " defined so far)");
  if (index >= int64_t(std::numeric_limits<uint32_t>::max()))
    scanner.fail("vertex index " + std::to_string(value) + " is out of range");
  return uint32_t(index);
}

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

// What a face corner may name besides its point, by its place after the
// point's index: its texture coordinates (`vt`, "7/3") and its normal
// (`vn`, "7/3/2" or "7//2").
struct CornerAttribute {
  const char* keyword;
  int field;  // 1 or 2: after the first or the second slash
  const char* what;
};
constexpr CornerAttribute kTextureCoordinates{"vt", 1, "texture coordinates"};
constexpr CornerAttribute kNormals{"vn", 2, "normals"};

// The attribute's index (from 0) in a corner such as "7/3/2" or "-1/-1";
// kNone when the corner names none ("7", "7//2" for `vt`), and (with
// `unreadable` set) for an index that is no number or points before the
// first. They are no reason to refuse a mesh: the reader says so once.
uint32_t corner_attribute_index(std::string_view corner, const CornerAttribute& attribute, size_t so_far, bool& unreadable) {
  std::string_view rest = corner;
  for (int k = 0; k < attribute.field; ++k) {
    const size_t slash = rest.find('/');
    if (slash == std::string_view::npos) return kNone;
    rest = rest.substr(slash + 1);
  }
  const std::string_view text = rest.substr(0, rest.find('/'));
  if (text.empty()) return kNone;
  int64_t value = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  const int64_t index = value > 0 ? value - 1 : int64_t(so_far) + value;
  unreadable = ec != std::errc() || ptr != text.data() + text.size() || value == 0 || index < 0 || index >= int64_t(kNone);
  return unreadable ? kNone : uint32_t(index);
}

// The file a map statement names ("map_Kd -s 1 1 1 wood.png", "map_Kd my
// wood.png", or Windows' "map_Kd .\wood.png"), beside the library.
std::string map_path(std::string_view rest, const std::filesystem::path& folder) {
  const size_t first = rest.find_first_not_of(" \t"), last = rest.find_last_not_of(" \t");
  if (first == std::string_view::npos) return "";
  std::string name(rest.substr(first, last - first + 1));
  if (name[0] == '-') name = name.substr(name.find_last_of(" \t") + 1);  // options first: the name is last
  std::error_code error;
  const std::filesystem::path as_written = (folder / name).lexically_normal();
  if (std::filesystem::is_regular_file(as_written, error)) return as_written.string();
  std::replace(name.begin(), name.end(), '\\', '/');
  return (folder / name).lexically_normal().string();
}

// A map statement's options (MTL's -clamp, -s, -o, -blendu, ...), which
// come before its file's name.
struct MapOptions {
  bool clamp = false;     // -clamp on
  std::string unapplied;  // the first option read but not applied, as written ("-s 2 2 1")
};
MapOptions map_options(std::string_view rest) {
  std::vector<std::string> words;
  std::string word;
  for (const char c : rest) {
    if (c == ' ' || c == '\t') {
      if (!word.empty()) words.push_back(word), word.clear();
    } else {
      word += c;
    }
  }
  if (!word.empty()) words.push_back(word);
  // "-s", not "-0.5", which is a value.
  const auto is_option = [](const std::string& w) {
    return w.size() > 1 && w[0] == '-' && !std::isdigit(static_cast<unsigned char>(w[1])) && w[1] != '.';
  };
  MapOptions options;
  // Each option and the values that follow it, up to the next option; the
  // last word is the file's name.
  for (size_t k = 0; k + 1 < words.size();) {
    if (!is_option(words[k])) {
      ++k;
      continue;
    }
    size_t next = k + 1;
    while (next + 1 < words.size() && !is_option(words[next])) ++next;
    std::string written = words[k];
    for (size_t v = k + 1; v < next; ++v) written += " " + words[v];
    // A scale of 1 and an offset or turbulence of 0 change nothing.
    const auto all_are = [&](double value) {
      for (size_t v = k + 1; v < next; ++v)
        if (std::strtod(words[v].c_str(), nullptr) != value) return false;
      return next > k + 1;
    };
    const bool identity = (words[k] == "-s" && all_are(1.0)) || ((words[k] == "-o" || words[k] == "-t") && all_are(0.0));
    if (words[k] == "-clamp") options.clamp = next > k + 1 && words[k + 1] == "on";
    else if (!identity && options.unapplied.empty()) options.unapplied = written;
    k = next;
  }
  return options;
}

// The rest of the line without the blanks round it: a material's name may hold spaces.
std::string rest_as_name(const TextScanner& scanner) {
  std::string_view rest = scanner.rest_of_line();
  const size_t first = rest.find_first_not_of(" \t"), last = rest.find_last_not_of(" \t");
  return first == std::string_view::npos ? "" : std::string(rest.substr(first, last - first + 1));
}

// The materials of one .mtl file (Wavefront's material library) into `soup`,
// by name into `named`. Kd, Ks, Ns and map_Kd are kept; other maps are noted once.
void read_material_library(const std::string& path, int line, PolygonSoup& soup, std::map<std::string, int>& named,
                           ModelFiles* maps) {
  std::error_code exists_error;
  if (!std::filesystem::exists(path, exists_error)) {
    soup.warn(line, "material library \"" + path + "\" not found: its materials are left out");
    return;
  }
  // A regular file (a FIFO is never waited for); and where its maps would
  // be drawn (`maps`), read from where they are: inside the model's folder.
  std::string refusal;
  struct stat there {};
  if (::stat(path.c_str(), &there) == 0 && !S_ISREG(there.st_mode))
    refusal = "is not a regular file (" + non_regular_kind(there.st_mode) + ")";
  else if (maps)
    refusal = maps->refusal(path);
  if (!refusal.empty()) {
    soup.warn(line, "material library \"" + path + "\" " + refusal + ": its materials are left out");
    return;
  }
  const MappedFile file(path);
  TextScanner scanner(file.bytes(), path);
  SoupMaterial* current = nullptr;
  const size_t first_material = soup.materials.size();
  std::set<std::string> matte;  // materials whose illumination model (illum 0 or 1) has no highlight
  bool noted_maps = false;
  // A statement that cannot be read (a decimal comma, say) is passed over:
  // colours are no reason to refuse a mesh, but the warning says so.
  size_t unread = 0;
  std::string first_unread;
  while (scanner.next_line()) {
    try {
      const std::string_view keyword = scanner.field();
      if (keyword == "newmtl") {
        const std::string name = rest_as_name(scanner);
        soup.materials.push_back({});
        soup.materials.back().name = name;
        named[name] = int(soup.materials.size() - 1);
        current = &soup.materials.back();
      } else if (current && (keyword == "Kd" || keyword == "Ks")) {
        glm::dvec3 rgb;
        rgb.r = scanner.number("red");
        // "Kd r" alone means grey r (the format allows g and b to be left out).
        rgb.g = scanner.at_line_end() ? rgb.r : scanner.number("green");
        rgb.b = scanner.at_line_end() ? rgb.g : scanner.number("blue");
        (keyword == "Kd" ? current->diffuse : current->specular) = glm::clamp(rgb, 0.0, 1.0);
      } else if (current && keyword == "Ns") {
        current->shininess = std::max(0.0, scanner.number("shininess"));
      } else if (current && keyword == "illum") {
        if (scanner.number("illumination model") < 2.0) matte.insert(current->name);
      } else if (keyword == "map_Kd" && !maps) {
        continue;
      } else if (current && keyword == "map_Kd") {
        const std::string_view statement = scanner.rest_of_line();
        const std::string map = map_path(statement, std::filesystem::path(path).parent_path());
        // Its options: -clamp on takes coordinates outside [0, 1] to the
        // edge (as glTF's clamp-to-edge); the others are said, not drawn.
        const MapOptions options = map_options(statement);
        std::string error;
        current->texture = maps->texture(map, error, options.clamp ? TextureImage::Wrap::kClampToEdge : TextureImage::Wrap::kRepeat);
        if (!current->texture && !error.empty())
          soup.warn(line, "material \"" + current->name + "\"'s texture map \"" + map + "\": " + error +
                              ": its faces take the material's Kd colour");
        if (!options.unapplied.empty())
          soup.warn(line, "material \"" + current->name + "\"'s map_Kd option " + options.unapplied +
                              " is not applied: its map is drawn as if the option were not there");
      } else if (!noted_maps && (keyword.substr(0, 4) == "map_" || keyword == "bump" || keyword == "disp" || keyword == "decal")) {
        soup.warn(line, "the materials' texture maps other than map_Kd (" + std::string(keyword) + " and the like) are not drawn");
        noted_maps = true;
      }
    } catch (const InputError& e) {
      if (unread++ == 0) first_unread = "line " + std::to_string(e.where().line) + ": " + e.message();
    }
  }
  // Ns under 1 is a matte surface, as exporters write it (3ds Max's Ns 0,
  // for one) and Blender's importer reads it (roughness 1 - sqrt(Ns / 1000):
  // 0.97 and more, fully rough): no highlight, not Phong's cos^Ns, whose lobe
  // for an exponent under 1 is broader than the diffuse term's own and
  // lights the whole face with Ks. So are illumination models 0 and 1
  // (colour alone, and diffuse alone: Wavefront's MTL specification),
  // whatever Ks says.
  for (size_t m = first_material; m < soup.materials.size(); ++m)
    if (soup.materials[m].shininess < 1.0 || matte.count(soup.materials[m].name)) soup.materials[m].specular = glm::dvec3(0.0);
  if (unread > 0)
    soup.warn(line, "material library \"" + path + "\": " +
                        (unread == 1 ? std::string("1 statement it could not read was") : std::to_string(unread) + " statements it could not read were") +
                        " passed over, the first at " + first_unread);
}

// One stretch of the file, from a line's start to a line's start, read on a
// core of its own. Points go straight into the soup; faces, whose corner
// counts are known only once read, into the stretch's own arrays.
struct ObjStretch {
  std::string_view text;
  int lines = 0, lines_before = 0;
  size_t points = 0, points_before = 0;
  size_t faces = 0, faces_before = 0;
  std::vector<uint32_t> corners, polygon_ends;  // polygon_ends: into `corners`
  // A corner attribute's statements (`vt` or `vn`) and the corners' indices of them.
  struct CornerRefs {
    size_t statements = 0, before = 0;  // in the stretch, and in the stretches before it
    std::vector<uint32_t> indices;  // each corner's (kNone for none), once some corner has one
    bool any = false;
    size_t unread = 0;         // statements and corners' indices that could not be read
    std::string first_unread;  // where the first was, and why
  };
  CornerRefs uvs, normals;
  std::vector<int> polygon_lines;
  // The material statements, replayed in order once every stretch is read:
  // what they do depends on the statements before them.
  struct MaterialStatement {
    int line;
    std::string_view keyword, rest;
    size_t faces_before;  // in the whole file
  };
  std::vector<MaterialStatement> material_statements;
  std::exception_ptr error;  // the first in the stretch; it is read no further
  bool colours = false;      // some vertex has "v x y z r g b"
};

// Splits `text` after a newline near every `chunk_bytes` bytes (a file whose
// lines end in \r alone stays whole).
std::vector<ObjStretch> stretches_of(std::string_view text, size_t chunk_bytes) {
  const size_t count = std::clamp<size_t>(text.size() / std::max<size_t>(chunk_bytes, 1), 1,
                                          8 * size_t(tbb::this_task_arena::max_concurrency()));
  std::vector<ObjStretch> stretches;
  for (size_t k = 0, begin = 0; k < count && (begin < text.size() || stretches.empty()); ++k) {
    size_t end = text.size();
    if (k + 1 < count) {
      const size_t goal = std::max(begin, text.size() * (k + 1) / count);
      const size_t newline = text.find('\n', goal);
      end = newline == std::string_view::npos ? text.size() : newline + 1;
    }
    stretches.push_back({});
    stretches.back().text = text.substr(begin, end - begin);
    begin = end;
  }
  return stretches;
}

// Counts a stretch's lines, points and faces, as read_stretch will read them.
void count_stretch(ObjStretch& stretch, const std::string& path) {
  TextScanner scanner(stretch.text, path);
  while (scanner.next_line()) {
    const std::string_view keyword = scanner.field();
    stretch.points += keyword == "v";
    stretch.faces += keyword == "f";
    stretch.uvs.statements += keyword == "vt";
    stretch.normals.statements += keyword == "vn";
  }
  stretch.lines = scanner.line_number();
}

// A corner's reference to one of its attributes, kept in `refs`.
void add_corner_ref(ObjStretch::CornerRefs& refs, const CornerAttribute& attribute, std::string_view corner, size_t so_far,
                    size_t corners_before, const TextScanner& scanner) {
  bool unreadable = false;
  const uint32_t index = corner_attribute_index(corner, attribute, so_far, unreadable);
  if (unreadable && refs.unread++ == 0)
    refs.first_unread = "line " + std::to_string(scanner.line_number()) + ": the corner " + quote_field(corner) + " has no " +
                        attribute.keyword + " index that umbra can read";
  if (index != kNone && !refs.any) {  // the corners before it have none
    refs.indices.assign(corners_before, kNone);
    refs.any = true;
  }
  if (refs.any) refs.indices.push_back(index);
}

void read_stretch(ObjStretch& stretch, const std::string& path, PolygonSoup& soup, std::vector<glm::vec2>& uvs,
                  std::vector<glm::vec3>* normals) {
  TextScanner scanner(stretch.text, path, stretch.lines_before);
  size_t point = stretch.points_before, uv = stretch.uvs.before, normal = stretch.normals.before;
  stretch.corners.reserve(3 * stretch.faces);
  stretch.polygon_ends.reserve(stretch.faces);
  stretch.polygon_lines.reserve(stretch.faces);
  while (scanner.next_line()) {
    const std::string_view keyword = scanner.field();
    if (keyword == "v") {
      soup.points[point] = scanner.vertex();
      // "v x y z r g b", a colour per vertex as MeshLab and others write it
      // (one more number alone is the homogeneous w, which is read past).
      if (!scanner.at_line_end()) {
        TextScanner extra(scanner.rest_of_line(), path, scanner.line_number() - 1);
        extra.next_line();
        int fields = 0;
        while (fields < 4 && !extra.field().empty()) ++fields;
        if (fields == 3) {  // read as numbers, with the line's located error when one is not
          glm::vec3 rgb;
          for (const int c : {0, 1, 2})
            rgb[c] = float(std::clamp(scanner.number(c == 0 ? "vertex colour red" : c == 1 ? "vertex colour green" : "vertex colour blue"), 0.0, 1.0));
          soup.point_colors[point] = rgb, stretch.colours = true;
        }
      }
      soup.point_lines[point++] = scanner.line_number();
    } else if (keyword == "vt") {
      try {
        const double u = scanner.number("texture coordinate u");
        const double v = scanner.at_line_end() ? 0.0 : scanner.number("texture coordinate v");
        uvs[uv] = glm::vec2(float(u), float(1.0 - v));  // OBJ's v runs up the image
      } catch (const InputError& e) {
        if (stretch.uvs.unread++ == 0) stretch.uvs.first_unread = "line " + std::to_string(e.where().line) + ": " + e.message();
      }
      ++uv;
    } else if (keyword == "vn" && normals) {
      try {
        (*normals)[normal] = glm::vec3(scanner.vertex());
      } catch (const InputError& e) {
        if (stretch.normals.unread++ == 0) stretch.normals.first_unread = "line " + std::to_string(e.where().line) + ": " + e.message();
      }
      ++normal;
    } else if (keyword == "f") {
      const size_t first = stretch.corners.size();
      for (std::string_view corner = scanner.field(); !corner.empty(); corner = scanner.field()) {
        stretch.corners.push_back(corner_index(scanner, corner, point));
        add_corner_ref(stretch.uvs, kTextureCoordinates, corner, uv, stretch.corners.size() - 1, scanner);
        if (normals) add_corner_ref(stretch.normals, kNormals, corner, normal, stretch.corners.size() - 1, scanner);
      }
      if (stretch.corners.size() - first < 3)
        scanner.fail_at_line("a face needs at least 3 vertices, this one has " + std::to_string(stretch.corners.size() - first));
      stretch.polygon_ends.push_back(uint32_t(stretch.corners.size()));
      stretch.polygon_lines.push_back(scanner.line_number());
    } else if (keyword == "mtllib" || keyword == "usemtl") {
      stretch.material_statements.push_back(
          {scanner.line_number(), keyword, scanner.rest_of_line(), stretch.faces_before + stretch.polygon_ends.size()});
    }
  }
}

// The material statements of `stretches`, in order: libraries read as they
// are named, each face given the material named last before it.
void replay_material_statements(const std::vector<ObjStretch>& stretches, size_t face_count, const std::string& path,
                                PolygonSoup& soup, const ReadOptions& maps) {
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::optional<ModelFiles> files;  // each map decoded once, however many materials name it
  if (maps.read) files.emplace(maps, path);
  ModelFiles* const map_files = files ? &*files : nullptr;
  std::map<std::string, int> materials;  // by name
  std::set<std::string> missing;         // used but defined nowhere: said once each
  std::vector<std::pair<size_t, int>> switches;  // (first face, its material), in order
  for (const ObjStretch& stretch : stretches) {
    for (const ObjStretch::MaterialStatement& statement : stretch.material_statements) {
      TextScanner rest(statement.rest, path, statement.line - 1);
      rest.next_line();
      if (statement.keyword == "mtllib") {
        // Several names, or one with spaces in it, as Blender writes "my model.mtl" unquoted.
        const std::string whole = (folder / rest_as_name(rest)).lexically_normal().string();
        std::error_code error;
        if (std::filesystem::is_regular_file(whole, error)) {
          read_material_library(whole, statement.line, soup, materials, map_files);
          continue;
        }
        TextScanner names(statement.rest, path, statement.line - 1);
        names.next_line();
        for (std::string_view name = names.field(); !name.empty(); name = names.field())
          read_material_library((folder / std::string(name)).lexically_normal().string(), statement.line, soup, materials, map_files);
        continue;
      }
      const std::string name = rest_as_name(rest);
      const auto it = materials.find(name);
      if (it == materials.end() && missing.insert(name).second)
        soup.warn(statement.line, "material " + quote_field(name) + " is in no material library: its faces keep the scene's material");
      switches.emplace_back(statement.faces_before, it == materials.end() ? -1 : it->second);
    }
    if (stretch.error) return;
  }
  // Each material from its statement to the next; per-face materials only
  // when some face has one.
  if (switches.empty()) return;
  std::vector<int> face_materials(face_count, -1);
  bool any = false;
  for (size_t k = 0; k < switches.size(); ++k) {
    const size_t end = k + 1 < switches.size() ? switches[k + 1].first : face_count;
    std::fill(face_materials.begin() + std::ptrdiff_t(switches[k].first), face_materials.begin() + std::ptrdiff_t(end),
              switches[k].second);
    any |= switches[k].second >= 0 && end > switches[k].first;
  }
  if (any) soup.polygon_materials = std::move(face_materials);
}

// Each corner's value of an attribute (`vt` or `vn`, kept in `refs` of
// each stretch), `none` for a corner that names none or one past the file's
// last (said once, as are those that could not be read).
template <typename Value>
std::vector<Value> corner_values(const std::vector<ObjStretch>& stretches, ObjStretch::CornerRefs ObjStretch::*refs,
                                 const CornerAttribute& attribute, const std::vector<Value>& values, size_t corner_count,
                                 Value none, const std::string& none_text, PolygonSoup& soup) {
  std::vector<Value> out(corner_count, none);
  size_t corner = 0, past_the_end = 0;
  uint32_t first_past = 0;
  for (const ObjStretch& stretch : stretches) {
    const size_t corners = stretch.polygon_ends.empty() ? 0 : stretch.polygon_ends.back();
    const std::vector<uint32_t>& indices = (stretch.*refs).indices;
    for (size_t c = 0; c < indices.size() && c < corners; ++c) {
      const uint32_t index = indices[c];
      if (index == kNone) continue;
      if (index < values.size()) out[corner + c] = values[index];
      else if (past_the_end++ == 0) first_past = index;
    }
    corner += corners;
  }
  const std::string keyword = attribute.keyword;
  if (past_the_end > 0)
    soup.warn(0, std::to_string(past_the_end) + " face corners name " + attribute.what + " past the file's last (" + keyword + " " +
                     std::to_string(size_t(first_past) + 1) + " of " + std::to_string(values.size()) + ", the first): " + none_text);
  size_t unread = 0;
  std::string first;
  for (const ObjStretch& stretch : stretches) {
    if ((stretch.*refs).unread && first.empty()) first = (stretch.*refs).first_unread;
    unread += (stretch.*refs).unread;
  }
  if (unread > 0)
    soup.warn(0, std::to_string(unread) + " " + attribute.what + " (" + keyword + ") or corners' indices of them could not be read, the first at " +
                     first + ": " + none_text);
  return out;
}

}  // namespace

PolygonSoup read_obj(std::string_view text, const std::string& path, size_t chunk_bytes, const ReadOptions& maps) {
  PolygonSoup soup;
  soup.path = path;
  soup.format = "OBJ";
  // Each stretch is counted, then read, on every core; the counts place each
  // stretch's lines, points and faces in the file's.
  std::vector<ObjStretch> stretches = stretches_of(text, chunk_bytes);
  tbb::parallel_for(size_t(0), stretches.size(), [&](size_t k) { count_stretch(stretches[k], path); });
  for (size_t k = 1; k < stretches.size(); ++k) {
    const ObjStretch& before = stretches[k - 1];
    stretches[k].lines_before = before.lines_before + before.lines;
    stretches[k].points_before = before.points_before + before.points;
    stretches[k].faces_before = before.faces_before + before.faces;
  }
  const ObjStretch& last = stretches.back();
  soup.points.resize(last.points_before + last.points);
  soup.point_lines.resize(soup.points.size());
  soup.point_colors.assign(soup.points.size(), glm::vec3(1.0f));  // kept only if some vertex has a colour
  for (size_t k = 1; k < stretches.size(); ++k) {
    stretches[k].uvs.before = stretches[k - 1].uvs.before + stretches[k - 1].uvs.statements;
    stretches[k].normals.before = stretches[k - 1].normals.before + stretches[k - 1].normals.statements;
  }
  std::vector<glm::vec2> uvs(last.uvs.before + last.uvs.statements);
  // Normals only for a picture (maps are read for one), where it smooths the faces.
  std::vector<glm::vec3> normals(maps.read ? last.normals.before + last.normals.statements : 0);
  tbb::parallel_for(size_t(0), stretches.size(), [&](size_t k) {
    try {
      read_stretch(stretches[k], path, soup, uvs, maps.read ? &normals : nullptr);
    } catch (...) {
      stretches[k].error = std::current_exception();
    }
  });
  // The first error in the file: a library's before a later line's.
  const auto failed = std::find_if(stretches.begin(), stretches.end(), [](const ObjStretch& s) { return bool(s.error); });
  const size_t face_count = last.faces_before + last.faces;
  if (failed == stretches.end()) {
    size_t corner_count = 0;
    for (const ObjStretch& stretch : stretches) corner_count += stretch.corners.size();
    soup.corners.resize(corner_count);
    soup.polygon_starts.resize(face_count + 1);
    soup.polygon_lines.resize(face_count);
    std::vector<size_t> corners_before(stretches.size(), 0);
    for (size_t k = 1; k < stretches.size(); ++k) corners_before[k] = corners_before[k - 1] + stretches[k - 1].corners.size();
    tbb::parallel_for(size_t(0), stretches.size(), [&](size_t k) {
      ObjStretch& stretch = stretches[k];
      std::copy(stretch.corners.begin(), stretch.corners.end(), soup.corners.begin() + std::ptrdiff_t(corners_before[k]));
      for (size_t f = 0; f < stretch.polygon_ends.size(); ++f) {
        soup.polygon_starts[stretch.faces_before + f + 1] = uint32_t(corners_before[k] + stretch.polygon_ends[f]);
        soup.polygon_lines[stretch.faces_before + f] = stretch.polygon_lines[f];
      }
      std::vector<uint32_t>().swap(stretch.corners);
    });
  }
  if (std::none_of(stretches.begin(), stretches.end(), [](const ObjStretch& s) { return s.colours; }))
    std::vector<glm::vec3>().swap(soup.point_colors);
  replay_material_statements(stretches, face_count, path, soup, maps);
  if (failed != stretches.end()) std::rethrow_exception(failed->error);
  const bool textured = std::any_of(soup.materials.begin(), soup.materials.end(), [](const SoupMaterial& m) { return bool(m.texture); });
  if (textured && std::any_of(stretches.begin(), stretches.end(), [](const ObjStretch& s) { return s.uvs.any; }))
    soup.corner_uvs = corner_values(stretches, &ObjStretch::uvs, kTextureCoordinates, uvs, soup.corners.size(), glm::vec2(0.0f),
                                    "they take (0, 0)", soup);
  if (std::any_of(stretches.begin(), stretches.end(), [](const ObjStretch& s) { return s.normals.any; }))
    soup.corner_normals = corner_values(stretches, &ObjStretch::normals, kNormals, normals, soup.corners.size(), glm::vec3(0.0f),
                                        "their faces are drawn flat there", soup);
  return soup;
}

PolygonSoup read_obj(std::string_view text, const std::string& path, const ReadOptions& maps) {
  return read_obj(text, path, size_t(1) << 20, maps);
}

}  // namespace umbra
