#include "scene/mesh_loader.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <exception>
#include <filesystem>
#include <limits>
#include <numeric>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vector_relational.hpp>
#include <tbb/parallel_for.h>

#include "mesh/check/mesh_check.hpp"
#include "mesh/check/self_intersections.hpp"
#include "mesh/io/mesh_file.hpp"
#include "mesh/predicates/orientation.hpp"
#include "mesh/topology/crease_normals.hpp"
#include "scene/mesh_placement.hpp"
#include "scene/scene_text.hpp"

namespace umbra {
namespace {

// One statement's mesh as read, with what the scene takes from the file
// once every mesh has loaded: its warnings and its own materials.
struct LoadedMesh {
  Mesh mesh;
  std::vector<ReadWarning> warnings;
  std::vector<SoupMaterial> file_materials;  // which mesh.triangle_materials index until placed in the scene
  double rounding = 0.0;  // how far placing may have moved a point, at most (placed_points)
};

// Fit, then scale, then rotate, then translate (scene-format.md): the
// transform that takes the file's points into the scene. A positive scale
// and a rotation keep the faces' orientation. `rounding`: a bound on how far
// rounding may have moved any placed point, which grows with the file's
// coordinates over the mesh's size (a 1e-3 cube at 3e7, fitted, moves by
// about 1e-5).
std::vector<glm::dvec3> placed_points(Mesh& m, const FileLoc& path_at, const MeshAnalysis& analysis, double& rounding) {
  if (m.fit && !analysis.positions.empty()) {
    // The box of the faces' corners: a point no face uses is no part of the shape.
    glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    for (const auto& t : analysis.triangles)
      for (const uint32_t v : t) lo = glm::min(lo, analysis.positions[v]), hi = glm::max(hi, analysis.positions[v]);
    const double longest = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
    // Corners that coincide leave no triangles; corners on one line leave
    // triangles, but nothing to see.
    const auto flat = [&](const std::array<uint32_t, 3>& t) {
      return collinear(analysis.positions[t[0]], analysis.positions[t[1]], analysis.positions[t[2]]);
    };
    if (std::all_of(analysis.triangles.begin(), analysis.triangles.end(), flat))
      throw InputError(path_at, "mesh file " + in_quotes(m.path) + " has no faces with area to fit", InputProblem::kNoFaces);
    if (std::isinf(longest))
      throw InputError(path_at, "mesh file " + in_quotes(m.path) + " is too large to fit: its extent overflows double precision");
    if (!(longest > 0.0))
      throw InputError(path_at, "mesh file " + in_quotes(m.path) + " has no extent to fit: its faces' corners coincide");
    m.file_bounds_min = lo, m.file_bounds_max = hi;
  }
  const MeshPlacement placed = placement_of(m);
  std::vector<glm::dvec3> points;
  points.reserve(analysis.positions.size());
  double farthest = 0.0;  // the largest coordinate, whose last bits the subtraction of the centre keeps
  for (const glm::dvec3& p : analysis.positions) {
    points.push_back(placed(p));
    farthest = std::max({farthest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  // The point and the centre each to half an ulp of `farthest`, scaled;
  // then the rotation and the translation, a few ulps of the result.
  rounding = 8.0 * std::numeric_limits<double>::epsilon() * (2.0 * farthest * std::abs(placed.scale) + glm::length(m.translation) + 1.0);
  return points;
}

// The mesh's shading normals for `smooth`: the file's, turned as its points
// were (a scale is uniform and positive, so turns none), else its creases'.
void smooth_normals(Mesh& m, std::vector<std::array<glm::vec3, 3>>& file_normals) {
  if (file_normals.empty()) {
    m.triangle_normals = crease_normals(m.positions, m.triangles, *m.smooth_deg);
    return;
  }
  const glm::mat3 rotation(glm::rotate(glm::dmat4(1.0), glm::radians(m.rotation_deg), glm::normalize(m.rotation_axis)));
  for (auto& corners : file_normals) {
    bool whole = true;  // every corner has one: else the face is drawn flat
    for (glm::vec3& n : corners) {
      const float length = glm::length(n);
      whole = whole && length > 0.0f && std::isfinite(length);
      if (whole) n = rotation * (n / length);
    }
    if (!whole) corners.fill(glm::vec3(0.0f));
  }
  m.triangle_normals = std::move(file_normals);
}

// Reads, checks and places one mesh; throws its located InputError.
LoadedMesh load_mesh(MeshStatement statement, const ReadOptions& maps) {
  LoadedMesh loaded{std::move(statement.mesh), {}, {}};
  Mesh& m = loaded.mesh;
  MeshAnalysis analysis;
  try {
    CheckOptions topology_only;
    topology_only.self_intersection_seconds = 0.0;
    topology_only.triangle_topology = true;
    topology_only.decide_back_faces = true;
    analysis = statement.soup ? analyse_mesh(*statement.soup, topology_only)
                              : analyse_mesh(read_polygon_soup(m.path, maps), topology_only);
  } catch (const InputError& e) {
    if (statement.staged) throw;
    if (e.where().line == 0)  // the file as a whole: say so at the statement that names it
      throw InputError(statement.path_at, "mesh file " + in_quotes(m.path) + ": " + e.message(), e.problem());
    throw InputError(e.where(), e.message() + " (in the mesh of " + m.where.str() + ")", e.problem());
  }
  m.positions = placed_points(m, statement.path_at, analysis, loaded.rounding);
  m.triangles = std::move(analysis.triangles);
  if (!m.triangles.empty()) {  // the faces' box, as fit measures it
    m.bounds_min = m.bounds_max = m.positions[m.triangles[0][0]];
    for (const auto& t : m.triangles)
      for (const uint32_t v : t) m.bounds_min = glm::min(m.bounds_min, m.positions[v]), m.bounds_max = glm::max(m.bounds_max, m.positions[v]);
  }
  m.loading_changes = analysis.report.loading_changes();
  m.back_faces = analysis.back_faces;
  m.triangle_materials = std::move(analysis.triangle_materials);
  m.triangle_colors = std::move(analysis.triangle_colors);
  m.triangle_uvs = std::move(analysis.triangle_uvs);
  if (m.smooth_deg && m.triangles.size() >= m.smooth_triangle_limit) m.smooth_deg.reset();
  if (m.smooth_deg) smooth_normals(m, analysis.triangle_normals);
  m.edges = std::move(analysis.topology->edges);  // asked for above: always given
  m.components = std::move(analysis.topology->components);
  loaded.warnings = std::move(analysis.report.warnings);
  loaded.file_materials = std::move(analysis.materials);
  return loaded;
}

// Beyond the cube by more than placing's rounding.
bool outside_the_cube(const Mesh& m, double rounding) {
  return glm::any(glm::greaterThan(glm::max(glm::abs(m.bounds_min), glm::abs(m.bounds_max)), glm::dvec3(1.0 + 1e-9 + rounding)));
}

std::string box_text(const glm::dvec3& lo, const glm::dvec3& hi) {
  const auto point = [](const glm::dvec3& p) {
    return "(" + number_text(p.x) + ", " + number_text(p.y) + ", " + number_text(p.z) + ")";
  };
  return point(lo) + " to " + point(hi);
}

// The file's own materials join the scene's, named "FILE:NAME", unless the
// statement names a material, which then covers every face, or says `plain`,
// which drops its vertex colours too. A face the
// file gives no material takes the statement's (or the default).
void place_file_materials(LoadedMesh& loaded, const std::string& written, Scene& scene) {
  Mesh& m = loaded.mesh;
  if (m.plain) std::vector<std::array<glm::vec3, 3>>().swap(m.triangle_colors);
  if (m.material_given || m.plain || loaded.file_materials.empty()) {
    m.triangle_materials.clear();
    std::vector<std::array<glm::vec2, 3>>().swap(m.triangle_uvs);  // no texture maps to look up
    return;
  }
  const int first = int(scene.materials.size());
  for (const SoupMaterial& f : loaded.file_materials) {
    Material material;
    material.name = written + ":" + f.name;
    material.ambient = f.diffuse;  // as a surface reflects diffuse light, so ambient light
    material.diffuse = f.diffuse;
    material.specular = f.specular;
    material.shininess = f.shininess;
    material.texture = f.texture;
    scene.materials.push_back(material);
  }
  for (int& t : m.triangle_materials) t = t < 0 ? m.material : first + t;
}

}  // namespace

void load_scene_meshes(std::vector<MeshStatement> statements, Scene& scene, const MeshLoadProgress& progress,
                       const ReadOptions& maps) {
  const std::filesystem::path folder = std::filesystem::path(scene.path).parent_path();
  std::vector<std::string> written(statements.size());
  for (size_t k = 0; k < statements.size(); ++k) {
    Mesh& m = statements[k].mesh;
    written[k] = m.path;
    m.path = (folder / written[k]).lexically_normal().string();
  }
  std::vector<LoadedMesh> loaded(statements.size());
  std::vector<std::exception_ptr> errors(statements.size());
  std::atomic<size_t> started{0};
  tbb::parallel_for(size_t(0), statements.size(), [&](size_t k) {
    if (progress) progress(started++, statements.size(), statements[k].mesh.path);
    try {
      loaded[k] = load_mesh(std::move(statements[k]), maps);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  });
  const auto warn = [&](const FileLoc& where, const std::string& message) { scene.warnings.push_back({where, message}); };
  for (size_t k = 0; k < loaded.size(); ++k) {
    if (errors[k]) std::rethrow_exception(errors[k]);
    Mesh& m = loaded[k].mesh;
    const std::string named = "mesh " + in_quotes(written[k]);
    for (const ReadWarning& w : loaded[k].warnings) {
      if (w.line > 0) warn({m.path, w.line, 0}, w.message);
      else warn(m.where, named + ": " + w.message);
    }
    place_file_materials(loaded[k], written[k], scene);
    if (m.triangles.empty()) {
      warn(m.where, named + " has no faces: it casts no shadow");
    } else {
      if (outside_the_cube(m, loaded[k].rounding))
        warn(m.where, named + " reaches outside the cube [-1,1]^3 that scenes are made for (its box is " +
                          box_text(m.bounds_min, m.bounds_max) + (m.fit ? ")" : "; \"fit\" scales it into the cube)"));
      if (!m.components.all_cast_from_silhouette()) warn(m.where, named + " is " + m.components.phrase() + ": " + m.components.volume_phrase());
    }
    scene.meshes.push_back(std::move(m));
  }
}

void settle_back_faces_by_search(Scene& scene) {
  for (Mesh& m : scene.meshes) {
    if (m.back_faces != BackFaces::kHiddenUnlessSeen) continue;
    // Each triangle its own face: two triangles of one polygon lie side by
    // side, and cross only where the polygon does.
    std::vector<uint32_t> own_face(m.triangles.size());
    std::iota(own_face.begin(), own_face.end(), 0u);
    const SelfIntersections found =
        find_self_intersections(m.positions, m.triangles, own_face, std::numeric_limits<double>::infinity(), 0);
    m.back_faces = found.face_pairs == 0 ? BackFaces::kHidden : BackFaces::kDrawn;
  }
}

}  // namespace umbra
