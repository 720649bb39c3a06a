#include "mesh/mesh_report.hpp"

#include <cstdio>
#include <sstream>

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

std::string json_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string json_ref(const char* kind, const ElementRef& e) {
  return std::string("{\"") + kind + "\":" + std::to_string(e.index) + ",\"line\":" + std::to_string(e.line) + "}";
}

template <typename T, typename F>
std::string json_list(const std::vector<T>& items, F&& item_json) {
  std::string out = "[";
  for (size_t i = 0; i < items.size(); ++i) out += (i ? "," : "") + item_json(items[i]);
  return out + "]";
}

const char* json_bool(bool b) { return b ? "true" : "false"; }

}  // namespace

std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (const char ch : s) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\u%04x", c);
      out += buffer;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

const char* shadow_method_name(ShadowMethod method) {
  return method == ShadowMethod::kSilhouette ? "silhouette" : "edge-multiplicity";
}

ShadowMethod MeshReport::shadow_method() const {
  const bool closed_2_manifold = !components.empty() && border_edges == 0 && non_manifold_edges == 0 &&
                                 non_manifold_vertices == 0 && non_orientable_components == 0;
  return closed_2_manifold ? ShadowMethod::kSilhouette : ShadowMethod::kEdgeMultiplicity;
}

std::string MeshReport::shadow_method_reason() const {
  const std::vector<std::string> why = topology_problems();
  if (why.empty()) return "closed 2-manifold";
  std::string s = "not a closed 2-manifold (";
  for (size_t i = 0; i < why.size(); ++i) s += (i ? ", " : "") + why[i];
  return s + ")";
}

std::string MeshReport::loading_changes() const {
  std::string s;
  if (duplicate_faces > 0) s = plural(duplicate_faces, "duplicate face", "duplicate faces") + " dropped";
  if (faces_to_flip > 0) s += (s.empty() ? "" : ", ") + plural(faces_to_flip, "face", "faces") + " flipped to agree";
  return s;
}

bool MeshReport::is_closed_manifold() const { return problems().empty(); }

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

std::string MeshReport::verdict() const {
  const std::vector<std::string> why = problems();
  const bool silhouette = shadow_method() == ShadowMethod::kSilhouette;
  std::string s;
  if (why.empty()) {
    s = "closed 2-manifold: casts its shadow from silhouette edges";
    if (inward_components > 0) s += " (oriented inward, which shadows the same; --repair turns it outward)";
    return s;
  }
  const bool oriented = inconsistent_edges == 0;
  s = silhouette && oriented ? "closed and consistently oriented, but not clean (" : "not a closed 2-manifold (";
  for (size_t i = 0; i < why.size(); ++i) s += (i ? ", " : "") + why[i];
  if (!silhouette) return s + "): shadow from an edge-multiplicity volume (exact for any triangles)";
  return s + (oriented ? "): still casts its shadow from silhouette edges"
                       : "): casts its shadow from silhouette edges once the renderer flips those faces");
}

void MeshReport::print_text(std::ostream& out) const {
  out << path << ": " << format << ", " << plural(file_vertices, "vertex", "vertices") << ", "
      << plural(file_faces, "face", "faces") << " (" << plural(triangles, "triangle", "triangles") << ")\n";
  const auto examples_line = [&](const std::vector<std::string>& items) {
    if (items.empty()) return;
    out << "                     e.g. ";
    for (size_t i = 0; i < items.size(); ++i) out << (i ? ", " : "") << items[i];
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
  constexpr size_t kListed = 10;
  for (size_t i = 0; i < components.size() && i < kListed; ++i) {
    const ComponentReport& c = components[i];
    out << "  component " << i << (i < 10 ? "        " : "       ") << plural(c.faces, "face", "faces") << ", "
        << (c.closed ? "closed" : c.manifold ? "open" : "non-manifold") << ", chi " << c.euler_characteristic;
    if (c.genus) out << ", genus " << *c.genus;
    if (c.border_loops) out << ", " << plural(c.border_loops, "hole", "holes");
    if (!c.orientable) out << ", non-orientable";
    if (c.outward) out << (*c.outward ? ", outward" : ", inward");
    out << "\n";
  }
  if (components.size() > kListed) out << "  ... and " << components.size() - kListed << " more components\n";
  out << "  verdict            " << verdict() << "\n";
}

void MeshReport::print_json(std::ostream& out) const {
  size_t closed_count = 0;
  for (const ComponentReport& c : components) closed_count += c.closed;
  const auto vertex_pair = [](const ElementPair& e) { return "[" + json_ref("vertex", e.first) + "," + json_ref("vertex", e.second) + "]"; };
  const auto face_pair = [](const ElementPair& e) { return "[" + json_ref("face", e.first) + "," + json_ref("face", e.second) + "]"; };
  const auto vertex = [](const ElementRef& e) { return json_ref("vertex", e); };
  const auto face = [](const ElementRef& e) { return json_ref("face", e); };
  constexpr size_t kListed = 1000;
  const std::vector<ComponentReport> listed(components.begin(), components.begin() + std::ptrdiff_t(std::min(components.size(), kListed)));
  std::ostringstream s;
  s << "{\"path\":" << json_string(path) << ",\"format\":" << json_string(format)
    << ",\"file_vertices\":" << file_vertices << ",\"file_faces\":" << file_faces << ",\"triangles\":" << triangles
    << ",\"vertices\":" << vertices << ",\"merged_vertices\":" << merged_vertices
    << ",\"isolated_vertices\":" << isolated_vertices << ",\"edges\":" << edges
    << ",\"components\":" << components.size() << ",\"closed_components\":" << closed_count
    << ",\"border_edges\":" << border_edges << ",\"border_loops\":" << border_loops
    << ",\"non_manifold_edges\":" << non_manifold_edges << ",\"non_manifold_vertices\":" << non_manifold_vertices
    << ",\"duplicate_faces\":" << duplicate_faces << ",\"degenerate_faces\":" << degenerate_faces
    << ",\"inconsistent_edges\":" << inconsistent_edges << ",\"faces_to_flip\":" << faces_to_flip
    << ",\"non_orientable_components\":" << non_orientable_components << ",\"inward_components\":" << inward_components
    << ",\"self_intersections\":{\"checked\":" << json_bool(self_intersections.checked)
    << ",\"complete\":" << json_bool(self_intersections.complete) << ",\"face_pairs\":" << self_intersections.face_pairs
    << ",\"seconds\":" << json_number(self_intersections.seconds)
    << ",\"time_limit_seconds\":" << json_number(self_intersections.time_limit_seconds) << "}"
    << ",\"euler_characteristic\":" << euler_characteristic
    << ",\"bbox\":{\"min\":[" << json_number(bbox_min.x) << "," << json_number(bbox_min.y) << "," << json_number(bbox_min.z)
    << "],\"max\":[" << json_number(bbox_max.x) << "," << json_number(bbox_max.y) << "," << json_number(bbox_max.z) << "]}"
    << ",\"component_list\":" << json_list(listed, [](const ComponentReport& c) {
         return "{\"faces\":" + std::to_string(c.faces) + ",\"vertices\":" + std::to_string(c.vertices) +
                ",\"edges\":" + std::to_string(c.edges) + ",\"border_edges\":" + std::to_string(c.border_edges) +
                ",\"border_loops\":" + std::to_string(c.border_loops) +
                ",\"euler_characteristic\":" + std::to_string(c.euler_characteristic) +
                ",\"closed\":" + json_bool(c.closed) + ",\"manifold\":" + json_bool(c.manifold) +
                ",\"orientable\":" + json_bool(c.orientable) +
                ",\"consistently_oriented\":" + json_bool(c.consistently_oriented) +
                ",\"genus\":" + (c.genus ? std::to_string(*c.genus) : "null") +
                ",\"outward\":" + (c.outward ? json_bool(*c.outward) : "null") + "}";
       })
    << ",\"examples\":{\"border_edges\":" << json_list(examples.border_edges, vertex_pair)
    << ",\"non_manifold_edges\":" << json_list(examples.non_manifold_edges, vertex_pair)
    << ",\"non_manifold_vertices\":" << json_list(examples.non_manifold_vertices, vertex)
    << ",\"duplicate_faces\":" << json_list(examples.duplicate_faces, face_pair)
    << ",\"degenerate_faces\":" << json_list(examples.degenerate_faces, face)
    << ",\"faces_to_flip\":" << json_list(examples.faces_to_flip, face)
    << ",\"self_intersections\":" << json_list(examples.self_intersections, face_pair) << "}"
    << ",\"closed_manifold\":" << json_bool(is_closed_manifold())
    << ",\"shadow_method\":\"" << shadow_method_name(shadow_method()) << "\""
    << ",\"problems\":" << json_list(problems(), json_string) << ",\"verdict\":" << json_string(verdict()) << "}\n";
  out << s.str();
}

}  // namespace umbra
