#include "scene/scene_parser.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <optional>
#include <map>
#include <set>
#include <sstream>

#include <glm/geometric.hpp>

#include "mesh/io/mapped_file.hpp"
#include "mesh/predicates/orientation.hpp"
#include "mesh/word_list.hpp"
#include "scene/scene_text.hpp"

namespace umbra {
namespace {

// `v`'s direction as a unit vector, `v` scaled by its largest component
// first: a direction of (1e-320, 0, 0) is +x, though its length underflows
// to 0 and glm::normalize would make it NaN. (0, 0, 0) stays as it is.
glm::dvec3 direction(const glm::dvec3& v) {
  const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  return largest > 0.0 ? glm::normalize(v / largest) : v;
}


struct Token {
  std::string text;
  int column = 0;  // 1-based byte column
};

// Splits one line into tokens; `#` starts a comment, `"` quotes a path.
std::vector<Token> tokenize(const std::string& line, const FileLoc& where) {
  std::vector<Token> tokens;
  size_t i = 0;
  while (i < line.size()) {
    const char ch = line[i];
    if (ch == ' ' || ch == '\t' || ch == '\r') {
      ++i;
    } else if (ch == '#') {
      break;
    } else if (ch == '"') {
      const size_t close = line.find('"', i + 1);
      if (close == std::string::npos)
        throw InputError({where.file, where.line, int(i) + 1}, "unterminated quoted path (missing closing \")");
      tokens.push_back({line.substr(i + 1, close - i - 1), int(i) + 1});
      i = close + 1;
    } else {
      const size_t end = line.find_first_of(" \t\r#", i);
      const size_t stop = end == std::string::npos ? line.size() : end;
      tokens.push_back({line.substr(i, stop - i), int(i) + 1});
      i = stop;
    }
  }
  return tokens;
}

// Reads the tokens of one statement left to right, with located errors.
class StatementReader {
 public:
  StatementReader(std::vector<Token> tokens, FileLoc line_loc, int line_length)
      : tokens_(std::move(tokens)), line_(std::move(line_loc)), line_length_(line_length) {}

  const std::string& keyword() const { return tokens_[0].text; }
  bool done() const { return next_ >= tokens_.size(); }
  const Token& peek() const { return tokens_[next_]; }
  FileLoc loc_of(const Token& t) const { return {line_.file, line_.line, t.column}; }
  FileLoc statement_loc() const { return loc_of(tokens_[0]); }
  // Where the next token is, or the end of the line when there is none.
  FileLoc next_loc() const {
    return done() ? FileLoc{line_.file, line_.line, line_length_ + 1} : loc_of(peek());
  }

  [[noreturn]] void fail_at_next(const std::string& message) const { throw InputError(next_loc(), message); }

  std::string got() const { return done() ? "end of line" : in_quotes(peek().text); }

  double number(const std::string& what) {
    if (done()) fail_at_next("expected a number for the " + what + ", got end of line");
    std::string text = peek().text;
    const char* first = text.c_str();
    if (*first == '+') ++first;  // C's strtod accepts a leading '+'; from_chars does not
    double value = 0.0;
    const char* last = text.c_str() + text.size();
    const auto [ptr, ec] = std::from_chars(first, last, value);
    // nan and inf (and overflow to inf) are errors, not numbers (scene-format.md).
    if (ec != std::errc() || ptr != last || !std::isfinite(value) || first == last)
      fail_at_next("expected a number for the " + what + ", got " + got());
    ++next_;
    return value;
  }

  glm::dvec3 vec3(const std::string& what) {
    const double x = number(what + " x");
    const double y = number(what + " y");
    const double z = number(what + " z");
    return {x, y, z};
  }

  glm::dvec3 color(const std::string& what) {
    const FileLoc at = next_loc();
    const glm::dvec3 rgb{number(what + " red"), number(what + " green"), number(what + " blue")};
    if (rgb.r < 0 || rgb.g < 0 || rgb.b < 0) throw InputError(at, "the " + what + " must not be negative");
    return rgb;
  }

  std::string word(const std::string& what) {
    if (done()) fail_at_next("expected " + what + ", got end of line");
    return tokens_[next_++].text;
  }

  // Takes an optional keyword from `allowed`; each may appear once.
  std::optional<std::string> keyword_of(const std::string& statement, const std::vector<std::string>& allowed) {
    if (done()) return std::nullopt;
    const std::string& k = peek().text;
    bool known = false;
    for (const std::string& a : allowed) known = known || a == k;
    if (!known) {
      fail_at_next("unknown keyword " + in_quotes(k) + " in " + statement + " (expected " + word_list(allowed) + ")");
    }
    if (!seen_.insert(k).second) fail_at_next("keyword " + in_quotes(k) + " is given twice");
    ++next_;
    return k;
  }

  bool seen(const std::string& k) const { return seen_.count(k) > 0; }

 private:
  std::vector<Token> tokens_;
  FileLoc line_;
  int line_length_;
  size_t next_ = 1;  // token 0 is the statement keyword
  std::set<std::string> seen_;
};

class SceneBuilder {
 public:
  explicit SceneBuilder(const std::string& name) {
    scene_.path = name;
    scene_.materials.emplace_back().name = "default";
  }

  void statement(StatementReader& r) {
    // The statements of the format (docs/scene-format.md), each read by its member.
    struct Statement {
      const char* keyword;
      void (SceneBuilder::*read)(StatementReader&);
    };
    static constexpr Statement kStatements[] = {
        {"light", &SceneBuilder::light},       {"material", &SceneBuilder::material}, {"sphere", &SceneBuilder::sphere},
        {"triangle", &SceneBuilder::triangle}, {"mesh", &SceneBuilder::mesh},         {"camera", &SceneBuilder::camera},
        {"background", &SceneBuilder::background}, {"floor", &SceneBuilder::floor},
        {"antialias", &SceneBuilder::antialias}, {"size", &SceneBuilder::size}, {"headlight", &SceneBuilder::headlight},
        {"hemisphere", &SceneBuilder::hemisphere}, {"tone", &SceneBuilder::tone},
    };
    const std::string& k = r.keyword();
    std::vector<std::string> keywords;
    for (const Statement& s : kStatements) {
      if (k == s.keyword) return (this->*s.read)(r);
      keywords.push_back(s.keyword);
    }
    throw InputError(r.statement_loc(), "unknown statement " + in_quotes(k) + " (expected " + word_list(keywords) + ")");
  }

  Scene finish(const MeshLoadProgress& progress, const ReadOptions& maps) {
    // Every mesh file is read once the whole scene has parsed, so that a
    // typo later in the scene is reported before a large file is read.
    load_scene_meshes(std::move(pending_meshes_), scene_, progress, maps);
    if (scene_.lights.empty())
      throw InputError({scene_.path}, "the scene has no light: add a line such as \"light 0.6 0.8 1.6\"");
    return std::move(scene_);
  }

 private:
  void light(StatementReader& r) {
    Light light;
    light.where = r.statement_loc();
    light.position = r.vec3("light position");
    while (auto k = r.keyword_of("light", {"color", "ambient"})) {
      if (*k == "color") light.color = r.color("light color");
      else light.ambient = r.color("light ambient intensity");
    }
    const int number = int(scene_.lights.size()) + 1;
    if (light.position.z <= 1.0)
      warn(light.where, "light " + std::to_string(number) + " has z <= 1: scenes are lit from z > 1, "
                        "so the viewpoint may be in shadow");
    scene_.lights.push_back(light);
  }

  void material(StatementReader& r) {
    Material m;
    const FileLoc name_at = r.next_loc();
    m.name = r.word("a material name");
    if (const auto it = materials_.find(m.name); it != materials_.end())
      throw InputError(name_at, "material " + in_quotes(m.name) + " is already defined at line " +
                                    std::to_string(it->second.line));
    while (auto k = r.keyword_of("material", {"ambient", "diffuse", "specular", "shininess", "shadow-catcher"})) {
      if (*k == "shadow-catcher") m.shadow_catcher = true;
      else if (*k == "ambient") m.ambient = r.color("material ambient");
      else if (*k == "diffuse") m.diffuse = r.color("material diffuse");
      else if (*k == "specular") m.specular = r.color("material specular");
      else {
        const FileLoc at = r.next_loc();
        m.shininess = r.number("shininess");
        if (m.shininess < 0) throw InputError(at, "shininess must not be negative");
      }
    }
    materials_[m.name] = name_at;
    // "default" is the material of everything that names none: written
    // once, it takes the built-in one's place.
    if (m.name == "default") scene_.materials[0] = m;
    else scene_.materials.push_back(m);
  }

  int material_ref(StatementReader& r, const std::string& statement) {
    return r.keyword_of(statement, {"material"}) ? material_named(r) : 0;
  }

  int material_named(StatementReader& r) {
    const FileLoc at = r.next_loc();
    const std::string name = r.word("a material name");
    if (name == "default" && materials_.count(name)) return 0;
    for (size_t i = 1; i < scene_.materials.size(); ++i)
      if (scene_.materials[i].name == name) return int(i);
    throw InputError(at, "material " + in_quotes(name) + " is not defined (define it on an earlier line)");
  }

  void sphere(StatementReader& r) {
    Sphere s;
    s.where = r.statement_loc();
    s.center = r.vec3("sphere centre");
    const FileLoc radius_at = r.next_loc();
    s.radius = r.number("sphere radius");
    if (s.radius <= 0)
      throw InputError(radius_at, "the sphere radius must be positive, got " + number_text(s.radius));
    s.material = material_ref(r, "sphere");
    if (glm::any(glm::greaterThan(glm::abs(s.center) + s.radius, glm::dvec3(1.0))))
      warn(s.where, "sphere reaches outside the cube [-1,1]^3 that scenes are made for");
    scene_.spheres.push_back(s);
  }

  void triangle(StatementReader& r) {
    Triangle t;
    t.where = r.statement_loc();
    t.a = r.vec3("first triangle vertex");
    t.b = r.vec3("second triangle vertex");
    t.c = r.vec3("third triangle vertex");
    t.material = material_ref(r, "triangle");
    for (const glm::dvec3& p : {t.a, t.b, t.c})
      if (glm::any(glm::greaterThan(glm::abs(p), glm::dvec3(1.0)))) {
        warn(t.where, "triangle reaches outside the cube [-1,1]^3 that scenes are made for");
        break;
      }
    if (collinear(t.a, t.b, t.c))
      warn(t.where, "degenerate triangle (its vertices are collinear): it covers no pixel and casts no shadow");
    scene_.triangles.push_back(t);
  }

  void mesh(StatementReader& r) {
    Mesh m;
    m.where = r.statement_loc();
    const FileLoc path_at = r.next_loc();
    m.path = r.word("a mesh file path");
    while (auto k = r.keyword_of("mesh", {"material", "fit", "scale", "rotate", "translate", "plain", "smooth"})) {
      if (*k == "fit") {
        m.fit = true;
      } else if (*k == "smooth") {
        const FileLoc at = r.next_loc();
        m.smooth_deg = r.number("crease angle");
        if (!(*m.smooth_deg >= 0 && *m.smooth_deg <= 180))
          throw InputError(at, "the crease angle must be from 0 to 180 degrees, got " + number_text(*m.smooth_deg));
      } else if (*k == "plain") {
        m.plain = true;
      } else if (*k == "material") {
        m.material = material_named(r);
        m.material_given = true;
      } else if (*k == "scale") {
        const FileLoc at = r.next_loc();
        m.scale = r.number("mesh scale");
        if (m.scale <= 0) throw InputError(at, "the mesh scale must be positive, got " + number_text(m.scale));
      } else if (*k == "rotate") {
        const FileLoc at = r.next_loc();
        m.rotation_axis = r.vec3("mesh rotation axis");
        if (m.rotation_axis == glm::dvec3(0.0)) throw InputError(at, "the mesh rotation axis must not be (0, 0, 0)");
        m.rotation_deg = r.number("mesh rotation angle");
      } else {
        m.translation = r.vec3("mesh translation");
      }
    }
    pending_meshes_.push_back({std::move(m), path_at, nullptr});
  }

  void camera(StatementReader& r) {
    if (scene_.camera_from)
      throw InputError(r.statement_loc(), "a second camera statement (the first is at line " +
                                              std::to_string(scene_.camera_from->line) + ")");
    Camera c;
    FileLoc lens_at;
    while (auto k = r.keyword_of("camera", {"eye", "target", "up", "fovy", "orthographic"})) {
      if (*k == "eye") {
        c.eye = r.vec3("camera eye");
      } else if (*k == "target") {
        c.target = r.vec3("camera target");
      } else if (*k == "up") {
        c.up = direction(r.vec3("camera up"));
      } else if (*k == "fovy") {
        if (r.seen("orthographic")) r.fail_at_next("a camera has fovy (a perspective) or orthographic HEIGHT, not both");
        lens_at = r.next_loc();
        c.fovy_deg = r.number("camera fovy");
        if (!(c.fovy_deg > 0 && c.fovy_deg < 180))
          throw InputError(lens_at, "fovy must be between 0 and 180 degrees, got " + number_text(c.fovy_deg));
      } else {
        if (r.seen("fovy")) r.fail_at_next("a camera has fovy (a perspective) or orthographic HEIGHT, not both");
        lens_at = r.next_loc();
        c.ortho_height = r.number("the orthographic camera's height");
        if (!(c.ortho_height > 0 && std::isfinite(c.ortho_height)))
          throw InputError(lens_at, "an orthographic camera's height must be above 0, got " + number_text(c.ortho_height));
      }
    }
    for (const char* k : {"eye", "target", "up"})
      if (!r.seen(k))
        r.fail_at_next(std::string("the camera needs \"") + k + "\" (camera eye X Y Z target X Y Z up X Y Z fovy DEG)");
    if (!r.seen("fovy") && !r.seen("orthographic"))
      r.fail_at_next("the camera needs \"fovy\" (camera eye X Y Z target X Y Z up X Y Z fovy DEG), or orthographic HEIGHT");
    const glm::dvec3 view = c.target - c.eye;
    if (glm::length(view) == 0)
      throw InputError(r.statement_loc(), "the camera eye and target are the same point");
    if (glm::length(glm::cross(view, c.up)) == 0)
      throw InputError(r.statement_loc(), "the camera up vector is zero or parallel to the view direction");
    scene_.camera = c;
    scene_.camera_from = r.statement_loc();
  }

  void background(StatementReader& r) {
    if (background_from_)
      throw InputError(r.statement_loc(), "a second background statement (the first is at line " +
                                              std::to_string(background_from_->line) + ")");
    background_from_ = r.statement_loc();
    if (!r.done() && r.peek().text == "transparent") {
      r.word("transparent");
      scene_.background.transparent = true;
      return;
    }
    scene_.background.color = r.color("background colour");
  }

  // A level square, two triangles wound as the bundled scenes' floors are,
  // which may reach past the cube without a warning: a floor is meant to.
  void floor(StatementReader& r) {
    const FileLoc where = r.statement_loc();
    const double z = r.number("floor height");
    glm::dvec2 centre(0.0);
    double half = 1.0;
    int material = 0;
    while (auto k = r.keyword_of("floor", {"centre", "size", "material"})) {
      if (*k == "centre") {
        centre.x = r.number("floor centre x");
        centre.y = r.number("floor centre y");
      } else if (*k == "size") {
        const FileLoc at = r.next_loc();
        half = r.number("floor size");
        if (half <= 0) throw InputError(at, "the floor size must be positive, got " + number_text(half));
      } else {
        material = material_named(r);
      }
    }
    const glm::dvec3 a(centre.x - half, centre.y - half, z), b(centre.x + half, centre.y - half, z),
        c(centre.x + half, centre.y + half, z), d(centre.x - half, centre.y + half, z);
    for (const glm::dvec3& corner : {a, c})
      if (!std::isfinite(corner.x) || !std::isfinite(corner.y))
        throw InputError(where, "the floor's corners overflow double precision: make it smaller");
    scene_.triangles.push_back({a, b, c, material, where});
    scene_.triangles.push_back({a, c, d, material, where});
  }

  void antialias(StatementReader& r) {
    if (scene_.antialias) throw InputError(r.statement_loc(), "a second antialias statement");
    const FileLoc at = r.next_loc();
    const double n = r.number("samples per side");
    if (n != std::floor(n) || n < 1 || n > 4)
      throw InputError(at, "antialias takes a whole number of samples per side from 1 to 4, got " + number_text(n));
    scene_.antialias = int(n);
    scene_.antialias_all = r.keyword_of("antialias", {"all"}).has_value();
  }

  void size(StatementReader& r) {
    if (scene_.size) throw InputError(r.statement_loc(), "a second size statement");
    int side[2];
    for (int k = 0; k < 2; ++k) {
      const FileLoc at = r.next_loc();
      const double n = r.number(k == 0 ? "picture width" : "picture height");
      if (n != std::floor(n) || n < 1 || n > kLargestPictureSide)
        throw InputError(at, std::string("size takes the picture's ") + (k == 0 ? "width" : "height") +
                                 " in whole pixels from 1 to " + std::to_string(kLargestPictureSide) + ", got " + number_text(n));
      side[k] = int(n);
    }
    scene_.size = {side[0], side[1]};
  }

  // Each said once: a second is an error, never a silent replacement.
  void once(StatementReader& r) {
    const auto [it, first] = said_once_.emplace(r.keyword(), r.statement_loc().line);
    if (!first)
      throw InputError(r.statement_loc(), "a second " + r.keyword() + " statement (the first is at line " + std::to_string(it->second) + ")");
  }

  void headlight(StatementReader& r) {
    once(r);
    scene_.fill.headlight = r.color("headlight intensity");
  }

  void hemisphere(StatementReader& r) {
    once(r);
    while (auto k = r.keyword_of("hemisphere", {"sky", "ground", "up"})) {
      if (*k == "sky") scene_.fill.sky = r.color("sky intensity");
      else if (*k == "ground") scene_.fill.ground = r.color("ground intensity");
      else {
        const FileLoc at = r.next_loc();
        const glm::dvec3 up = r.vec3("hemisphere up");
        if (up == glm::dvec3(0.0)) throw InputError(at, "the hemisphere's up must not be (0, 0, 0)");
        scene_.fill.up = direction(up);
      }
    }
  }

  void tone(StatementReader& r) {
    once(r);
    const FileLoc at = r.next_loc();
    const std::string curve = r.word("a tone curve (clip or soft)");
    if (curve == "clip") scene_.tone = ToneCurve::kClip;
    else if (curve == "soft") scene_.tone = ToneCurve::kSoft;
    else throw InputError(at, "unknown tone curve " + in_quotes(curve) + " (expected clip or soft)");
  }

  void warn(const FileLoc& where, const std::string& message) { scene_.warnings.push_back({where, message}); }

  Scene scene_;
  std::map<std::string, FileLoc> materials_;
  std::vector<MeshStatement> pending_meshes_;
  std::optional<FileLoc> background_from_;
  std::map<std::string, int> said_once_;  // statement keyword: its line
};

}  // namespace

Scene parse_scene_text(const std::string& text, const std::string& name, const MeshLoadProgress& progress,
                       const ReadOptions& maps) {
  SceneBuilder builder(name);
  std::istringstream in(text);
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const FileLoc line_loc{name, line_number, 0};
    std::vector<Token> tokens = tokenize(line, line_loc);
    if (tokens.empty()) continue;
    StatementReader reader(std::move(tokens), line_loc, int(line.size()));
    builder.statement(reader);
    if (!reader.done())
      reader.fail_at_next("unexpected " + reader.got() + " after the end of the " + reader.keyword() + " statement");
  }
  return builder.finish(progress, maps);
}

Scene parse_scene_file(const std::string& path, const MeshLoadProgress& progress, const ReadOptions& maps) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError({path}, "is a folder, not a scene file");
  // Mapped, as a regular file only: a FIFO named as a scene never blocks.
  std::optional<MappedFile> file;
  try {
    file.emplace(path);
  } catch (const InputError& e) {
    // Unread, a file not named .scene is not known to be one (nothere.obj).
    if (std::filesystem::path(path).extension() != ".scene") throw;
    std::string why = e.message();
    if (why.rfind("cannot open: ", 0) == 0) why.erase(0, 13);
    throw InputError({path}, "cannot open the scene file: " + why);
  }
  const std::string text(file->bytes());
  if (file->cut_short()) throw InputError({path}, "the scene file was cut short while it was read: read it again once it is written");
  return parse_scene_text(text, path, progress, maps);
}

}  // namespace umbra
