#include "tools/defect_picture.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "image/stroke_drawing.hpp"
#include "image/text_drawing.hpp"
#include "scene/camera.hpp"
#include "scene/staged_scene.hpp"
#include "tools/command_line.hpp"
#include "tools/picture_choices.hpp"
#include "tools/picture_drawing.hpp"

namespace umbra {
namespace {

// A mark a surface hides is drawn at this opacity: there, but behind.
constexpr double kHiddenOpacity = 0.35;
// A mark is hidden where the surface seen is nearer than it by more than
// this share of its distance (the surface it lies on is at its own depth,
// give or take the depth buffer's steps and a stroke's width).
constexpr double kDepthSlack = 0.01;

glm::dvec3 colour_of(const std::array<uint8_t, 3>& c) { return glm::dvec3(c[0], c[1], c[2]) / 255.0; }

// The soup with every face in the surface's grey, the self-intersecting
// ones and those to flip tinted: its own materials, maps and vertex colours
// left out.
PolygonSoup tinted(const PolygonSoup& soup, const MeshReport& report) {
  PolygonSoup copy = soup;
  copy.point_colors.clear();
  copy.corner_uvs.clear();
  copy.materials = {SoupMaterial{"surface", glm::dvec3(0.8), glm::dvec3(0.0), 32.0, nullptr},
                    SoupMaterial{"self-intersecting", colour_of(DefectColours::kSelfIntersectingFace), glm::dvec3(0.0), 32.0, nullptr},
                    SoupMaterial{"to flip", colour_of(DefectColours::kFaceToFlip), glm::dvec3(0.0), 32.0, nullptr}};
  copy.polygon_materials.assign(copy.polygon_count(), 0);
  for (const ElementRef& f : report.examples.faces_to_flip) copy.polygon_materials[f.index] = 2;
  for (const auto& [f, g] : report.examples.self_intersections) copy.polygon_materials[f.index] = copy.polygon_materials[g.index] = 1;
  return copy;
}

std::string counted(size_t n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

}  // namespace

DefectPicture::DefectPicture(const PolygonSoup& soup, const MeshReport& report, const std::string& own_up, int width, int height,
                             const StageView& view)
    : report_(report), width_(width), height_(height) {
  RenderSettings settings;
  settings.width = width, settings.height = height;
  StagingOptions staging;
  staging.view = view;
  // Seen from below, the floor would hide the model and its defects.
  staging.no_floor = view.camera_elevation_deg.value_or(0.0) < 0.0;
  scene_ = stage_polygon_soup(std::make_shared<const PolygonSoup>(tinted(soup, report)), nullptr, staging_for(staging, settings), own_up);
  placed_ = placement_of(scene_.meshes.at(0));
}

glm::dvec3 DefectPicture::project(const glm::dvec3& file_point) const {
  // The camera's pixel centres are at whole numbers; the strokes' at half-integers.
  const Projected p = scene_.camera.project(placed_(file_point), width_, height_);
  return {p.px + 0.5, p.py + 0.5, p.depth};
}

Image DefectPicture::draw(HeadlessGl gl) const {
  RenderSettings settings;
  settings.width = width_, settings.height = height_;
  set_picture_samples(settings, std::nullopt, false, false, scene_);
  std::optional<HeadlessContext> context;
  PictureRequest request;
  request.depth = true;
  DrawnPicture drawn = draw_picture(scene_, settings, request, context, gl);
  Image& image = drawn.image;
  const std::vector<float>& seen = drawn.depth;

  // Strokes as wide as a 300th of the picture's smaller side, at least 3 pixels.
  const double radius = std::max(1.5, std::min(width_, height_) / 600.0);
  const auto opacity_at = [&](const glm::dvec3& a, const glm::dvec3& b) {
    return [&, a, b](int x, int y) {
      const glm::dvec2 p(x + 0.5, y + 0.5), along = glm::dvec2(b) - glm::dvec2(a);
      const double length2 = glm::dot(along, along);
      const double t = length2 > 0.0 ? std::clamp(glm::dot(p - glm::dvec2(a), along) / length2, 0.0, 1.0) : 0.0;
      const double depth = a.z + t * (b.z - a.z);
      const double surface = seen[size_t(y) * size_t(width_) + size_t(x)];
      return surface < depth * (1.0 - kDepthSlack) ? kHiddenOpacity : 1.0;
    };
  };
  const auto stroke_edges = [&](const std::vector<ElementPair>& edges, const std::array<uint8_t, 3>& ink) {
    for (const auto& [u, v] : edges) {
      const glm::dvec3 a = project(u.at), b = project(v.at);
      if (a.z > 0.0 && b.z > 0.0) draw_stroke(image, glm::dvec2(a), glm::dvec2(b), radius, ink, opacity_at(a, b));
    }
  };
  stroke_edges(report_.examples.border_edges, DefectColours::kBorderEdge);
  stroke_edges(report_.examples.non_manifold_edges, DefectColours::kNonManifoldEdge);
  for (const ElementRef& v : report_.examples.non_manifold_vertices) {
    const glm::dvec3 p = project(v.at);
    if (p.z > 0.0) draw_stroke(image, glm::dvec2(p), glm::dvec2(p), 2.5 * radius, DefectColours::kNonManifoldVertex, opacity_at(p, p));
  }

  // The legend: a line per kind found, its colour and its count.
  struct Line {
    std::array<uint8_t, 3> ink;
    std::string text;
  };
  std::vector<Line> lines;
  const MeshReport& r = report_;
  if (r.border_edges)
    lines.push_back({DefectColours::kBorderEdge, counted(r.border_edges, "border edge", "border edges") + " (" +
                                                     counted(r.border_loops, "hole", "holes") + ")"});
  if (r.non_manifold_edges) lines.push_back({DefectColours::kNonManifoldEdge, counted(r.non_manifold_edges, "non-manifold edge", "non-manifold edges")});
  if (r.non_manifold_vertices)
    lines.push_back({DefectColours::kNonManifoldVertex, counted(r.non_manifold_vertices, "non-manifold vertex", "non-manifold vertices")});
  if (r.self_intersections.face_pairs)
    lines.push_back({DefectColours::kSelfIntersectingFace,
                     counted(r.self_intersections.face_pairs, "self-intersecting face pair", "self-intersecting face pairs") +
                         (r.self_intersections.complete ? "" : " (search stopped)")});
  if (r.faces_to_flip) lines.push_back({DefectColours::kFaceToFlip, counted(r.faces_to_flip, "face to flip", "faces to flip")});
  // What the verdict counts but the picture cannot show: said, without a swatch.
  constexpr std::array<uint8_t, 3> kNoSwatch{0, 0, 0};
  if (r.duplicate_faces) lines.push_back({kNoSwatch, counted(r.duplicate_faces, "duplicate face", "duplicate faces") + " (not drawn)"});
  if (r.degenerate_faces) lines.push_back({kNoSwatch, counted(r.degenerate_faces, "degenerate face", "degenerate faces") + " (not drawn)"});
  if (!r.self_intersections.checked) lines.push_back({kNoSwatch, "self-intersections not checked"});
  const std::array<uint8_t, 3> ink{30, 30, 30};
  const std::string name = r.path.substr(r.path.find_last_of('/') + 1);
  std::vector<std::string> texts{printable(name + ": " + r.verdict_head())};
  for (const Line& l : lines) texts.push_back(l.text);
  int widest = 0;
  for (const std::string& t : texts) widest = std::max(widest, text_width(t));
  const int pad = 8, swatch = kTextLineHeight - 8, indent = swatch + 8;
  fill_rectangle(image, 0, 0, 2 * pad + indent + widest, 2 * pad + int(texts.size()) * kTextLineHeight, {255, 255, 255}, 0.8);
  draw_text(image, pad, pad + 2, texts[0], ink);
  for (size_t k = 0; k < lines.size(); ++k) {
    const int y = pad + int(k + 1) * kTextLineHeight;
    if (lines[k].ink != kNoSwatch) fill_rectangle(image, pad, y + 2, pad + swatch, y + 2 + swatch, lines[k].ink, 1.0);
    draw_text(image, pad + indent, y + 2, lines[k].text, ink);
  }
  return image;
}

}  // namespace umbra
