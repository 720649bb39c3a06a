#include "mesh/check/mesh_report.hpp"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace umbra {
namespace {

std::string plural(size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string element(const char* kind, const ElementRef& e) {
  std::string s = std::string(kind) + " " + std::to_string(e.index);
  if (e.line > 0) s += " (line " + std::to_string(e.line) + ")";
  return s;
}

std::string edge(const ElementPair& e) {
  std::string s = "edge " + std::to_string(e.first.index) + "-" + std::to_string(e.second.index);
  if (e.first.line > 0) s += " (lines " + std::to_string(e.first.line) + ", " + std::to_string(e.second.line) + ")";
  return s;
}

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

std::string seconds(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f s", x);
  return buffer;
}

// One JSON value on one line. Invalid UTF-8 (a file name in Latin-1, say)
// becomes U+FFFD: the output is always valid UTF-8, as JSON requires
// (docs/check.md).
std::string json_line(const nlohmann::ordered_json& value) {
  return value.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

}  // namespace

const char* volume_kind_name(VolumeKind kind) {
  switch (kind) {
    case VolumeKind::kSilhouette: return "silhouette";
    case VolumeKind::kEdgeMultiplicity: return "edge-multiplicity";
    case VolumeKind::kMixed: break;
  }
  return "mixed";
}

size_t MeshReport::silhouette_components() const {
  return size_t(std::count_if(components.begin(), components.end(), [](const ComponentReport& c) { return c.casts_from_silhouette(); }));
}

VolumeKind MeshReport::volume_kind() const {
  const size_t silhouette = silhouette_components();
  if (silhouette == 0) return VolumeKind::kEdgeMultiplicity;
  return silhouette == components.size() ? VolumeKind::kSilhouette : VolumeKind::kMixed;
}

std::string MeshReport::loading_changes() const {
  std::string s;
  if (duplicate_faces > 0) s = plural(duplicate_faces, "duplicate face", "duplicate faces") + " dropped";
  if (faces_to_flip > 0) s += (s.empty() ? "" : ", ") + plural(faces_to_flip, "face", "faces") + " flipped to agree";
  return s;
}

bool MeshReport::is_closed_manifold() const { return problems().empty(); }

bool MeshReport::back_faces_hidden() const {
  return !components.empty() &&
         std::all_of(components.begin(), components.end(), [](const ComponentReport& c) { return c.hides_back_faces; });
}

std::vector<std::string> MeshReport::topology_problems() const {
  std::vector<std::string> out;
  if (components.empty()) out.push_back("no faces");
  if (border_edges > 0)
    out.push_back(plural(border_edges, "border edge", "border edges") + " in " + plural(border_loops, "hole", "holes"));
  if (non_manifold_edges > 0) out.push_back(plural(non_manifold_edges, "non-manifold edge", "non-manifold edges"));
  if (non_manifold_vertices > 0) out.push_back(plural(non_manifold_vertices, "non-manifold vertex", "non-manifold vertices"));
  if (non_orientable_components > 0)
    out.push_back(plural(non_orientable_components, "non-orientable component", "non-orientable components"));
  if (inconsistent_edges > 0)
    out.push_back("inconsistent orientation (" + plural(faces_to_flip, "face", "faces") + " to flip)");
  return out;
}

std::vector<std::string> MeshReport::problems() const {
  std::vector<std::string> out = topology_problems();
  if (duplicate_faces > 0) out.push_back(plural(duplicate_faces, "duplicate face", "duplicate faces"));
  if (degenerate_faces > 0) out.push_back(plural(degenerate_faces, "degenerate face", "degenerate faces"));
  if (!self_intersections.checked) {
    out.push_back("self-intersections not checked");
  } else if (self_intersections.face_pairs > 0) {
    out.push_back(plural(self_intersections.face_pairs, "self-intersecting face pair", "self-intersecting face pairs") +
                  (self_intersections.complete ? "" : " (search stopped at the time limit)"));
  } else if (!self_intersections.complete) {
    out.push_back("self-intersection search stopped after " + number(self_intersections.time_limit_seconds) + " s");
  }
  return out;
}

std::vector<std::string> MeshReport::solid_problems() const {
  std::vector<std::string> out;
  if (components.empty()) return {"no faces"};
  if (border_edges > 0) out.push_back("open (" + plural(border_loops, "hole", "holes") + ")");
  if (non_manifold_edges > 0 || non_manifold_vertices > 0)
    out.push_back("non-manifold (" + plural(non_manifold_edges, "edge", "edges") + ", " + plural(non_manifold_vertices, "vertex", "vertices") + ")");
  if (non_orientable_components > 0) out.push_back("non-orientable");
  else if (inconsistent_edges > 0) out.push_back("faces disagree (" + plural(faces_to_flip, "face", "faces") + " to flip)");
  if (inward_components > 0) out.push_back("inside out (" + plural(inward_components, "closed component faces", "closed components face") + " inward)");
  if (undecided_components > 0) out.push_back("which way " + plural(undecided_components, "closed component faces", "closed components face") + " is undecided");
  if (!self_intersections.checked || !self_intersections.complete) out.push_back("self-intersections not searched in full");
  else if (self_intersections.face_pairs > 0)
    out.push_back("self-intersecting (" + plural(self_intersections.face_pairs, "face pair", "face pairs") + ")");
  return out;
}

std::string MeshReport::verdict_head() const {
  if (triangles == 0) return "no faces";
  if (problems().empty()) return "closed 2-manifold";
  if (!topology_problems().empty()) return "not a closed 2-manifold";
  // A search skipped (--time-limit 0) or stopped with nothing found says
  // nothing is wrong, only that nothing was proved clean.
  const bool unproved = duplicate_faces == 0 && degenerate_faces == 0 && self_intersections.face_pairs == 0;
  return unproved ? "closed and consistently oriented, not known to be clean" : "closed and consistently oriented, but not clean";
}

std::string MeshReport::verdict() const {
  if (triangles == 0) return "no faces: nothing to check, and nothing to cast a shadow";
  const std::vector<std::string> why = problems();
  std::string s;
  if (why.empty() && volume_kind() != VolumeKind::kSilhouette)  // only overlapping diagonals keep it from the silhouette
    return "closed 2-manifold: casts its shadow from an edge-multiplicity volume where a polygon's diagonal, once "
           "triangulated, runs along another edge";
  if (why.empty()) {
    s = "closed 2-manifold: casts its shadow from silhouette edges";
    if (inward_components > 0) s += " (oriented inward, which shadows the same; --repair turns it outward)";
    return s;
  }
  const bool oriented = inconsistent_edges == 0;
  s = verdict_head() + " (";
  for (size_t i = 0; i < why.size(); ++i) s += (i ? ", " : "") + why[i];
  if (volume_kind() == VolumeKind::kEdgeMultiplicity)
    return s + "): shadow from an edge-multiplicity volume (exact for any triangles)";
  if (volume_kind() == VolumeKind::kMixed) {
    const size_t silhouette = silhouette_components();
    return s + "): shadow from silhouette edges for its " + plural(silhouette, "closed component", "closed components") +
           (oriented ? "" : " (once the renderer flips those faces)") + ", from an edge-multiplicity volume for the other " +
           std::to_string(components.size() - silhouette);
  }
  return s + (oriented ? "): still casts its shadow from silhouette edges"
                       : "): casts its shadow from silhouette edges once the renderer flips those faces");
}

void MeshReport::print_text(std::ostream& out) const {
  out << path << ": " << format << ", " << plural(file_vertices, "vertex", "vertices") << ", "
      << plural(file_faces, "face", "faces") << " (" << plural(triangles, "triangle", "triangles") << ")\n";
  for (const ReadWarning& w : warnings)
    out << "  warning            " << (w.line ? "line " + std::to_string(w.line) + ": " : "") << w.message << "\n";
  const auto examples_line = [&](const std::vector<std::string>& items) {
    if (items.empty()) return;
    out << "                     e.g. ";
    for (size_t i = 0; i < std::min(items.size(), kMaxExamples); ++i) out << (i ? ", " : "") << items[i];
    out << "\n";
  };
  const auto edges_of = [](const std::vector<ElementPair>& v) {
    std::vector<std::string> s;
    for (const auto& e : v) s.push_back(edge(e));
    return s;
  };
  const auto refs_of = [](const char* kind, const std::vector<ElementRef>& v) {
    std::vector<std::string> s;
    for (const auto& e : v) s.push_back(element(kind, e));
    return s;
  };
  size_t closed_count = 0;
  for (const ComponentReport& c : components) closed_count += c.closed;

  out << "  vertices           " << vertices << " distinct (" << merged_vertices << " merged as repeats, "
      << isolated_vertices << " unused)\n";
  out << "  edges              " << edges << "\n";
  out << "  components         " << components.size() << " (" << closed_count << " closed)\n";
  out << "  border             " << plural(border_edges, "edge", "edges") << " in " << plural(border_loops, "loop", "loops")
      << "\n";
  examples_line(edges_of(examples.border_edges));
  out << "  non-manifold       " << plural(non_manifold_edges, "edge", "edges") << ", "
      << plural(non_manifold_vertices, "vertex", "vertices") << "\n";
  examples_line(edges_of(examples.non_manifold_edges));
  examples_line(refs_of("vertex", examples.non_manifold_vertices));
  out << "  duplicate faces    " << duplicate_faces << "\n";
  {
    std::vector<std::string> s;
    for (const auto& [face, original] : examples.duplicate_faces)
      s.push_back(element("face", face) + " repeats " + element("face", original));
    examples_line(s);
  }
  out << "  degenerate faces   " << degenerate_faces << "\n";
  examples_line(refs_of("face", examples.degenerate_faces));
  out << "  orientation        ";
  if (non_orientable_components > 0) out << plural(non_orientable_components, "component is", "components are") << " non-orientable; ";
  if (inconsistent_edges == 0) out << "consistent";
  else out << plural(inconsistent_edges, "edge disagrees", "edges disagree") << ", " << plural(faces_to_flip, "face", "faces") << " to flip";
  if (inward_components > 0) out << "; " << plural(inward_components, "closed component faces", "closed components face") << " inward";
  if (undecided_components > 0)
    out << "; "
        << (self_intersections.checked && self_intersections.complete
                ? plural(undecided_components, "closed component crosses", "closed components cross") +
                      " faces: which way they face is undecided"
                : plural(undecided_components, "closed component", "closed components") +
                      ": which way they face is undecided without a complete self-intersection search");
  out << "\n";
  examples_line(refs_of("flip face", examples.faces_to_flip));
  out << "  self-intersections ";
  if (!self_intersections.checked) {
    out << "not checked\n";
  } else {
    out << plural(self_intersections.face_pairs, "face pair", "face pairs") << " ("
        << (self_intersections.complete ? "complete" : "stopped at the time limit of " + number(self_intersections.time_limit_seconds) + " s")
        << ", " << seconds(self_intersections.seconds) << ")\n";
    std::vector<std::string> s;
    for (const auto& [f, g] : examples.self_intersections) s.push_back(element("face", f) + " x " + element("face", g));
    examples_line(s);
  }
  out << "  Euler char.        " << euler_characteristic << "\n";
  out << "  bounding box       (" << number(bbox_min.x) << ", " << number(bbox_min.y) << ", " << number(bbox_min.z) << ") to ("
      << number(bbox_max.x) << ", " << number(bbox_max.y) << ", " << number(bbox_max.z) << ")\n";
  const glm::dvec3 size = bbox_max - bbox_min;
  out << "  size               " << number(size.x) << " x " << number(size.y) << " x " << number(size.z) << "\n";
  out << "  area               " << number(area) << "\n";
  out << "  volume             "
      << (enclosed_volume ? number(*enclosed_volume) + " (its closed components', negative where they face in)" : std::string("none: no closed component"))
      << "\n";
  constexpr size_t kListed = 10;
  for (size_t i = 0; i < components.size() && i < kListed; ++i) {
    const ComponentReport& c = components[i];
    out << "  component " << i << (i < 10 ? "        " : "       ") << plural(c.faces, "face", "faces") << ", "
        << (c.closed ? "closed" : c.manifold ? "open" : "non-manifold") << ", chi " << c.euler_characteristic;
    if (c.genus) out << ", genus " << *c.genus;
    if (c.border_loops) out << ", " << plural(c.border_loops, "hole", "holes");
    if (c.non_manifold_edges) out << ", " << plural(c.non_manifold_edges, "non-manifold edge", "non-manifold edges");
    if (c.non_manifold_vertices) out << ", " << plural(c.non_manifold_vertices, "non-manifold vertex", "non-manifold vertices");
    if (c.overlapping_diagonals)
      out << ", " << plural(c.overlapping_diagonals, "diagonal", "diagonals") << " along another edge once triangulated";
    if (!c.orientable) out << ", non-orientable";
    if (c.outward) out << (*c.outward ? ", outward" : ", inward");
    if (c.enclosed_volume) out << ", encloses " << number(*c.enclosed_volume);
    else if (c.closed && c.orientable) out << ", facing undecided";
    out << "; " << (c.casts_from_silhouette() ? "silhouette" : "edge-multiplicity") << " volume\n";
  }
  if (components.size() > kListed) out << "  ... and " << components.size() - kListed << " more components\n";
  const std::vector<std::string> not_solid = solid_problems();
  std::string solid = not_solid.empty() ? "yes" : "no: ";
  for (size_t i = 0; i < not_solid.size(); ++i) solid += (i ? ", " : "") + not_solid[i];
  out << "  solid              " << solid << "\n";
  out << "  verdict            " << verdict() << "\n";
}

void MeshReport::print_json(std::ostream& out) const {
  using Json = nlohmann::ordered_json;  // keys in the order docs/check.md lists them
  const auto ref = [](const char* kind, const ElementRef& e) {
    return Json{{kind, e.index}, {"line", e.line}, {"at", {e.at.x, e.at.y, e.at.z}}};
  };
  const auto refs = [&](const char* kind, const std::vector<ElementRef>& list) {
    Json items = Json::array();
    for (size_t i = 0; i < std::min(list.size(), kMaxExamples); ++i) items.push_back(ref(kind, list[i]));
    return items;
  };
  const auto pairs = [&](const char* kind, const std::vector<ElementPair>& list) {
    Json items = Json::array();
    for (size_t i = 0; i < std::min(list.size(), kMaxExamples); ++i)
      items.push_back(Json::array({ref(kind, list[i].first), ref(kind, list[i].second)}));
    return items;
  };
  constexpr size_t kListed = 1000;
  size_t closed_count = 0;
  for (const ComponentReport& c : components) closed_count += c.closed;
  Json component_list = Json::array();
  for (size_t i = 0; i < std::min(components.size(), kListed); ++i) {
    const ComponentReport& c = components[i];
    component_list.push_back({{"faces", c.faces},
                              {"vertices", c.vertices},
                              {"edges", c.edges},
                              {"border_edges", c.border_edges},
                              {"border_loops", c.border_loops},
                              {"non_manifold_edges", c.non_manifold_edges},
                              {"non_manifold_vertices", c.non_manifold_vertices},
                              {"overlapping_diagonals", c.overlapping_diagonals},
                              {"euler_characteristic", c.euler_characteristic},
                              {"closed", c.closed},
                              {"manifold", c.manifold},
                              {"orientable", c.orientable},
                              {"consistently_oriented", c.consistently_oriented},
                              {"genus", c.genus ? Json(*c.genus) : Json(nullptr)},
                              {"outward", c.outward ? Json(*c.outward) : Json(nullptr)},
                              {"volume", c.enclosed_volume ? Json(*c.enclosed_volume) : Json(nullptr)},
                              {"hides_back_faces", c.hides_back_faces},
                              {"shadow_method", volume_kind_name(c.casts_from_silhouette() ? VolumeKind::kSilhouette
                                                                                              : VolumeKind::kEdgeMultiplicity)}});
  }
  Json report = {
      {"path", path},
      {"format", format},
      {"file_vertices", file_vertices},
      {"file_faces", file_faces},
      {"triangles", triangles},
      {"vertices", vertices},
      {"merged_vertices", merged_vertices},
      {"isolated_vertices", isolated_vertices},
      {"edges", edges},
      {"components", components.size()},
      {"closed_components", closed_count},
      {"border_edges", border_edges},
      {"border_loops", border_loops},
      {"non_manifold_edges", non_manifold_edges},
      {"non_manifold_vertices", non_manifold_vertices},
      {"duplicate_faces", duplicate_faces},
      {"degenerate_faces", degenerate_faces},
      {"inconsistent_edges", inconsistent_edges},
      {"faces_to_flip", faces_to_flip},
      {"non_orientable_components", non_orientable_components},
      {"inward_components", inward_components},
      {"undecided_components", undecided_components},
      {"self_intersections",
       {{"checked", self_intersections.checked},
        {"complete", self_intersections.complete},
        {"face_pairs", self_intersections.face_pairs},
        {"seconds", self_intersections.seconds},
        {"time_limit_seconds", self_intersections.time_limit_seconds}}},
      {"euler_characteristic", euler_characteristic},
      {"bbox", {{"min", {bbox_min.x, bbox_min.y, bbox_min.z}}, {"max", {bbox_max.x, bbox_max.y, bbox_max.z}}}},
      {"size", {bbox_max.x - bbox_min.x, bbox_max.y - bbox_min.y, bbox_max.z - bbox_min.z}},
      {"area", area},
      {"volume", enclosed_volume ? Json(*enclosed_volume) : Json(nullptr)},
      {"component_list", component_list},
      {"examples",
       {{"border_edges", pairs("vertex", examples.border_edges)},
        {"non_manifold_edges", pairs("vertex", examples.non_manifold_edges)},
        {"non_manifold_vertices", refs("vertex", examples.non_manifold_vertices)},
        {"duplicate_faces", pairs("face", examples.duplicate_faces)},
        {"degenerate_faces", refs("face", examples.degenerate_faces)},
        {"faces_to_flip", refs("face", examples.faces_to_flip)},
        {"self_intersections", pairs("face", examples.self_intersections)}}},
      {"closed_manifold", is_closed_manifold()},
      // The flags of printing and of mesh corpora (Zhou and Jacobson,
      // "Thingi10K: A Dataset of 10,000 3D-Printing Models", 2016).
      {"closed", !components.empty() && border_edges == 0},
      {"edge_manifold", non_manifold_edges == 0},
      {"vertex_manifold", non_manifold_vertices == 0},
      {"oriented", non_orientable_components == 0 && inconsistent_edges == 0},
      {"self_intersecting", self_intersections.checked && self_intersections.complete ? Json(self_intersections.face_pairs > 0)
                                                                                      : Json(nullptr)},
      {"solid", is_solid()},
      {"solid_problems", solid_problems()},
      {"shadow_method", volume_kind_name(volume_kind())},
      {"problems", problems()},
      {"verdict", verdict()}};
  if (!warnings.empty()) {  // only when the reader warned: reports of well-formed files keep their keys
    Json list = Json::array();
    for (const ReadWarning& w : warnings) list.push_back({{"line", w.line}, {"message", w.message}});
    report["warnings"] = list;
  }
  out << json_line(report);
}

std::string MeshReport::solid_verdict() const {
  const std::vector<std::string> not_solid = solid_problems();
  std::string s = not_solid.empty() ? "solid" : "not a solid: ";
  for (size_t i = 0; i < not_solid.size(); ++i) s += (i ? ", " : "") + not_solid[i];
  return s;
}

void MeshReport::print_brief(std::ostream& out, bool solid) const {
  out << path << ": " << format << ", " << plural(triangles, "triangle", "triangles") << ", "
      << plural(components.size(), "component", "components") << ": " << (solid ? solid_verdict() : verdict()) << "\n";
}

std::string json_error_line(const std::string& path, const std::string& error) {
  return json_line(nlohmann::ordered_json{{"path", path}, {"error", error}});
}

std::string json_passed_over_line(const std::string& path, const std::string& why, const std::string& kind) {
  return json_line(nlohmann::ordered_json{{"path", path}, {"passed_over", why}, {"kind", kind}});
}

}  // namespace umbra
