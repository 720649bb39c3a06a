// The compiled part of the Python module `umbra` (umbra/__init__.py is the
// rest): loading, checking, repairing and drawing a mesh given as a path or
// as NumPy arrays, over the same libraries as the command. pybind11
// (Debian's pybind11-dev) binds it.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "image/exr_file.hpp"
#include "mesh/check/mesh_check.hpp"
#include "mesh/check/mesh_repair.hpp"
#include "mesh/input_error.hpp"
#include "mesh/io/array_soup.hpp"
#include "mesh/io/mesh_file.hpp"
#include "mesh/io/mesh_format.hpp"
#include "scene/scene_checks.hpp"
#include "scene/staged_scene.hpp"
#include "tools/command_line.hpp"
#include "tools/defect_picture.hpp"
#include "tools/picture_choices.hpp"
#include "tools/picture_drawing.hpp"
#include "tools/view_preparation.hpp"
#include "tools/view_set.hpp"

namespace py = pybind11;

namespace umbra {
namespace {

// A mesh as umbra/__init__.py hands it over: a file's path, or vertices and
// faces arrays and the name messages call them by.
struct ArraysMesh {
  py::array vertices, faces;
  std::string name;
};
using MeshSource = std::variant<std::string, ArraysMesh>;

// `a` as soup_from_arrays reads it; `what` ("vertices") and `name` for messages.
ArrayView view_of(const py::array& a, const char* what, const std::string& name) {
  if (a.ndim() != 2) {
    std::string shape = "(";
    for (py::ssize_t d = 0; d < a.ndim(); ++d) shape += (d ? ", " : "") + std::to_string(a.shape(d));
    throw InputError({name}, std::string(what) + " must be a two-dimensional array, got shape " + shape + (a.ndim() == 1 ? ",)" : ")"));
  }
  return {a.data(), a.dtype().kind(), size_t(a.itemsize()), size_t(a.shape(0)), size_t(a.shape(1)), a.strides(0), a.strides(1)};
}

// Read with the GIL held (the arrays are Python objects); the soup is ours.
PolygonSoup soup_of(const ArraysMesh& mesh) {
  return soup_from_arrays(view_of(mesh.vertices, "vertices", mesh.name), view_of(mesh.faces, "faces", mesh.name), mesh.name);
}

// Hands `values` to NumPy without copying: the array owns them.
template <typename T>
py::array_t<T> owned_array(std::vector<T>&& values, std::vector<py::ssize_t> shape) {
  auto* held = new std::vector<T>(std::move(values));
  py::capsule owner(held, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(shape, held->data(), owner);
}

// An RGB image with alpha 255 added, in one pass.
Image with_alpha(const Image& image) {
  Image rgba(image.width, image.height, 4);
  for (size_t i = 0, n = size_t(image.width) * size_t(image.height); i < n; ++i) {
    for (int c = 0; c < 3; ++c) rgba.pixels[i * 4 + c] = image.pixels[i * 3 + c];
    rgba.pixels[i * 4 + 3] = 255;
  }
  return rgba;
}

// An (h, w, 4) array of `image`: its bytes where it has alpha, else with alpha 255.
py::array_t<uint8_t> rgba_array(Image&& image) {
  const auto w = py::ssize_t(image.width), h = py::ssize_t(image.height);
  if (image.channels != 4) image = with_alpha(image);
  return owned_array(std::move(image.pixels), {h, w, 4});
}

std::vector<std::string> warning_lines(const Scene& scene) {
  std::vector<std::string> lines;
  for (const Warning& w : scene.warnings) lines.push_back(w.where.str() + ": " + w.message);
  return lines;
}

// One GL context kept for many pictures, drawn one at a time from any thread.
class Renderer {
 public:
  explicit Renderer(const std::string& gl) : gl_(gl) {
    if (!headless_gl_from_name(gl)) throw UsageError("gl expects " + headless_gl_names() + ", got \"" + gl + "\"");
  }

  // (image, mask or None, depth or None, warnings) for `source` drawn as
  // `words` (umbra render's options) say.
  py::tuple render(const MeshSource& source, const std::vector<std::string>& words, bool want_mask, bool want_depth) {
    PictureChoices c = choices(source, words);
    DrawnPicture drawn;
    std::vector<std::string> warnings;
    {
      py::gil_scoped_release released;
      const Scene scene = staged(source, c, warnings);
      PictureRequest request;
      request.show_volumes = c.show_volumes;
      request.mask = want_mask;
      request.depth = want_depth;
      const std::lock_guard<std::mutex> one_at_a_time(drawing_);
      if (closed_) throw std::runtime_error("this Renderer is closed");
      drawn = draw_picture(scene, c.settings, request, context_, c.gl);
    }
    const py::ssize_t w = drawn.image.width, h = drawn.image.height;
    py::object mask = py::none(), depth = py::none();
    if (drawn.mask) mask = owned_array(std::move(drawn.mask->pixels), {h, w});
    if (want_depth) depth = owned_array(std::move(drawn.depth), {h, w});
    return py::make_tuple(rgba_array(std::move(drawn.image)), mask, depth, warnings);
  }

  // (dict of stacked arrays, transforms.json's text, warnings) for `count`
  // views of `source` spread as `spread` says, with `passes` ("" for none),
  // as umbra render --views draws them.
  // With `cameras_text` (a transforms.json's content, named `cameras_name`
  // in messages), the views it names instead of `count`.
  // With `turning` ("model" or "light"), a motion's `count` frames instead, as --turntable draws them.
  py::tuple render_views(const MeshSource& source, const std::vector<std::string>& words, int count, const std::string& spread,
                         const std::string& pass_list, const std::string& cameras_text, const std::string& cameras_name,
                         const std::string& turning_word) {
    if (count < 1) throw UsageError("views must be at least 1, got " + std::to_string(count));
    const ViewSpread spread_of = parse_view_spread("--views-on", spread);
    const std::vector<DataPass> passes = pass_list.empty() ? std::vector<DataPass>{} : parse_data_passes("--passes", pass_list);
    Turning turning = Turning::kNone;
    if (!turning_word.empty() && !parse_turning(turning_word, turning))
      throw UsageError("orbit takes \"model\" or \"light\", got \"" + turning_word + "\"");
    PictureChoices c = choices(source, words);
    if (const auto* path = std::get_if<std::string>(&source); path && turning == Turning::kNone) require_staged({"--views"}, *path);
    leave_floor_out_of_sphere(c.staging, c.staging_given, spread_of);
    std::vector<std::string> warnings;
    std::vector<uint8_t> color, object, shadow;
    std::vector<float> depth, normal;
    size_t lights = 0;
    std::string transforms_text;
    {
      py::gil_scoped_release released;
      // A cameras file's size is the picture's, which staging weighs.
      std::optional<TransformsFile> given;
      if (!cameras_text.empty()) {
        given = read_transforms(cameras_text, cameras_name);
        count = int(given->count());
        if (!c.size_given) c.settings.width = given->width, c.settings.height = given->height, c.size_given = true;
        turning = given->turning;
      }
      c.staging.view.turning = turning;  // framed for the whole motion
      Scene scene = staged(source, c, warnings, size_t(count));
      lights = scene.lights.size();
      // A staged mesh's views are in its file's coordinates; a scene's in its own.
      const auto* path = std::get_if<std::string>(&source);
      const MeshPlacement placement = path && !is_mesh_file(*path) ? MeshPlacement{} : placement_of(scene.meshes.at(0));
      const double aspect = double(c.settings.width) / c.settings.height;
      const std::vector<Shot> shots = requested_shots(scene, placement, {count, spread_of, turning, {}, {}}, given, c.staging.view, aspect);
      require_lights_off_casters(scene, shots);
      std::vector<std::string> stems;
      for (int i = 0; i < count; ++i) stems.push_back(view_stem(i, count));
      transforms_text = transforms_json(shots, scene, placement, c.settings.width, c.settings.height, passes, stems, turning).dump();
      const std::lock_guard<std::mutex> one_at_a_time(drawing_);
      if (closed_) throw std::runtime_error("this Renderer is closed");
      draw_views(scene, shots, placement, c.settings, passes, context_, c.gl, [&](int, DrawnView&& view) {
        const Image rgba = view.color.channels == 4 ? std::move(view.color) : with_alpha(view.color);
        color.insert(color.end(), rgba.pixels.begin(), rgba.pixels.end());
        const SurfacePasses& s = view.surface;
        depth.insert(depth.end(), s.depth.begin(), s.depth.end());
        for (const glm::vec3& n : s.normal) normal.insert(normal.end(), {n.x, n.y, n.z});
        object.insert(object.end(), s.object.begin(), s.object.end());
        for (const Image& mask : view.shadow) shadow.insert(shadow.end(), mask.pixels.begin(), mask.pixels.end());
      });
    }
    const py::ssize_t n = count, h = c.settings.height, w = c.settings.width;
    py::dict arrays;
    arrays["color"] = owned_array(std::move(color), {n, h, w, 4});
    const auto asked = [&](DataPass p) { return std::count(passes.begin(), passes.end(), p) > 0; };
    if (asked(DataPass::kDepth)) arrays["depth"] = owned_array(std::move(depth), {n, h, w});
    if (asked(DataPass::kNormal)) arrays["normal"] = owned_array(std::move(normal), {n, h, w, 3});
    if (asked(DataPass::kObject)) arrays["object"] = owned_array(std::move(object), {n, h, w});
    if (asked(DataPass::kShadow)) arrays["shadows"] = owned_array(std::move(shadow), {n, py::ssize_t(lights), h, w});
    return py::make_tuple(arrays, transforms_text, warnings);
  }

  void close() {
    py::gil_scoped_release released;
    const std::lock_guard<std::mutex> one_at_a_time(drawing_);
    context_.reset();
    closed_ = true;
  }

  std::string platform() {
    const std::lock_guard<std::mutex> one_at_a_time(drawing_);
    return context_ ? context_->description() : "";
  }

 private:
  // The options `words` say, for a picture of `source`.
  PictureChoices choices(const MeshSource& source, const std::vector<std::string>& words) const {
    std::vector<std::string> all = words;
    if (gl_ != "auto") all.insert(all.end(), {"--gl", gl_});
    PictureChoices c = parse_picture_choices(all);
    if (const auto* path = std::get_if<std::string>(&source)) require_staged(c.staging_given, *path);
    return c;
  }

  // The scene `source` stands for, staged as `c` says, with its size and
  // samples settled in `c` and its warnings' lines added to `warnings`.
  // `views` pictures of it are drawn, which weighs how they are antialiased.
  static Scene staged(const MeshSource& source, PictureChoices& c, std::vector<std::string>& warnings, size_t views = 1) {
    const StagingOptions staging = staging_for(c.staging, c.settings);
    Scene scene;
    if (const auto* arrays = std::get_if<ArraysMesh>(&source)) {
      scene = stage_polygon_soup(std::make_shared<const PolygonSoup>(soup_of(*arrays)), nullptr, staging);
    } else {
      const std::string& path = std::get<std::string>(source);
      if (const std::optional<InputError> error = neither_scene_nor_mesh(path)) throw *error;
      scene = parse_scene_or_mesh_file(path, {}, nullptr, staging, ReadOptions{true, "", false, {}});
    }
    warnings = warning_lines(scene);
    require_lights_off_casters(scene);
    require_caught_shadows_kept(scene, c.settings.method);
    set_picture_size(c.settings, c.size_given, scene);
    set_picture_samples(c.settings, c.antialias, c.antialias_all, c.show_volumes, scene, views);
    require_drawable_size(c.settings.width, c.settings.height, c.settings.frame_samples());
    return scene;
  }

  std::string gl_;
  std::mutex drawing_;
  std::optional<HeadlessContext> context_;
  bool closed_ = false;
};

PolygonSoup read_source(const MeshSource& source, const ReadOptions& maps) {
  if (const auto* path = std::get_if<std::string>(&source)) return read_polygon_soup(*path, maps);
  return soup_of(std::get<ArraysMesh>(source));
}

// The report's offending elements, every one, as index arrays: (k, 2) for
// edges and face pairs, (k,) for vertices and faces.
py::dict defect_arrays(const MeshReport::Examples& e) {
  const auto refs = [](const std::vector<ElementRef>& list) {
    std::vector<uint32_t> v;
    for (const ElementRef& r : list) v.push_back(r.index);
    const auto n = py::ssize_t(v.size());
    return owned_array(std::move(v), {n});
  };
  const auto pairs = [](const std::vector<ElementPair>& list) {
    std::vector<uint32_t> v;
    for (const auto& [a, b] : list) v.push_back(a.index), v.push_back(b.index);
    const auto n = py::ssize_t(list.size());
    return owned_array(std::move(v), {n, 2});
  };
  py::dict d;
  d["border_edges"] = pairs(e.border_edges);
  d["non_manifold_edges"] = pairs(e.non_manifold_edges);
  d["non_manifold_vertices"] = refs(e.non_manifold_vertices);
  d["duplicate_faces"] = pairs(e.duplicate_faces);
  d["degenerate_faces"] = refs(e.degenerate_faces);
  d["faces_to_flip"] = refs(e.faces_to_flip);
  d["self_intersections"] = pairs(e.self_intersections);
  return d;
}

// (the report as check --json prints it, its defects as arrays).
// (the report as check --json prints it, its defects as arrays, and with
// `picture` (width, height) its defect picture, as check --picture draws it).
py::tuple check(const MeshSource& source, double time_limit_s, std::optional<std::pair<int, int>> picture) {
  PolygonSoup soup = read_source(source, ReadOptions::skip());
  MeshReport report;
  std::optional<Image> drawn;
  {
    py::gil_scoped_release released;
    CheckOptions options;
    options.self_intersection_seconds = time_limit_s;
    options.max_examples = SIZE_MAX;
    if (!picture) {
      report = check_mesh(std::move(soup), options);
    } else {
      report = check_mesh(soup, options);
      require_drawable_size(picture->first, picture->second, 1);
      const auto* path = std::get_if<std::string>(&source);
      const DefectPicture defects(soup, report, path ? up_axis_of_file(*path) : "+y", picture->first, picture->second);
      drawn = defects.draw(gl_with_environment(HeadlessGl::kAuto));
    }
  }
  std::ostringstream json;
  report.print_json(json);
  py::object image = py::none();
  if (drawn) image = rgba_array(std::move(*drawn));
  return py::make_tuple(json.str(), defect_arrays(report.examples), image);
}

// (vertices, faces, changes, the repaired mesh's check --json report).
py::tuple repair(const MeshSource& source, size_t max_hole_edges, double merge_tolerance, double time_limit_s) {
  const PolygonSoup soup = read_source(source, ReadOptions::skip());
  RepairedTriangles repaired;
  std::ostringstream json;
  {
    py::gil_scoped_release released;
    repaired = repair_to_triangles(soup, RepairOptions{max_hole_edges, merge_tolerance});
    PolygonSoup result;
    result.path = soup.path;
    result.format = soup.format;
    result.points = repaired.points;
    for (const auto& t : repaired.triangles) {
      result.corners.insert(result.corners.end(), t.begin(), t.end());
      result.polygon_starts.push_back(uint32_t(result.corners.size()));
    }
    CheckOptions options;
    options.self_intersection_seconds = time_limit_s;
    check_mesh(std::move(result), options).print_json(json);
  }
  std::vector<double> points;
  points.reserve(repaired.points.size() * 3);
  for (const glm::dvec3& p : repaired.points) points.insert(points.end(), {p.x, p.y, p.z});
  std::vector<uint32_t> faces;
  faces.reserve(repaired.triangles.size() * 3);
  for (const auto& t : repaired.triangles) faces.insert(faces.end(), t.begin(), t.end());
  const auto n = py::ssize_t(repaired.points.size()), m = py::ssize_t(repaired.triangles.size());
  return py::make_tuple(owned_array(std::move(points), {n, 3}), owned_array(std::move(faces), {m, 3}),
                        repaired.summary.changes, json.str());
}

// What a mesh file holds: its points as written, its polygons split into
// fans of triangles, which polygon each comes from, and what else it says.
py::dict load(const std::string& path) {
  PolygonSoup soup;
  {
    py::gil_scoped_release released;
    soup = read_polygon_soup(path, ReadOptions::skip());
  }
  std::vector<double> points;
  points.reserve(soup.points.size() * 3);
  for (const glm::dvec3& p : soup.points) points.insert(points.end(), {p.x, p.y, p.z});
  std::vector<uint32_t> faces, polygon_of_face;
  for (size_t p = 0; p < soup.polygon_count(); ++p) {
    const uint32_t* corners = soup.polygon(p);
    for (uint32_t k = 1; k + 1 < soup.corner_count(p); ++k) {
      faces.insert(faces.end(), {corners[0], corners[k], corners[k + 1]});
      polygon_of_face.push_back(uint32_t(p));
    }
  }
  py::dict d;
  const auto n = py::ssize_t(soup.points.size()), m = py::ssize_t(polygon_of_face.size());
  d["vertices"] = owned_array(std::move(points), {n, 3});
  d["faces"] = owned_array(std::move(faces), {m, 3});
  d["polygon_of_face"] = owned_array(std::move(polygon_of_face), {m});
  d["polygons"] = soup.polygon_count();
  d["format"] = soup.format;
  std::vector<float> colors;
  for (const glm::vec3& c : soup.point_colors) colors.insert(colors.end(), {c.r, c.g, c.b});
  d["vertex_colors"] = soup.point_colors.empty() ? py::object(py::none()) : py::object(owned_array(std::move(colors), {n, 3}));
  std::vector<std::string> materials, warnings;
  for (const SoupMaterial& material : soup.materials) materials.push_back(material.name);
  for (const ReadWarning& w : soup.warnings) warnings.push_back(path + (w.line ? ":" + std::to_string(w.line) : "") + ": " + w.message);
  d["materials"] = materials;
  d["warnings"] = warnings;
  return d;
}

}  // namespace
}  // namespace umbra

PYBIND11_MODULE(_umbra, m) {
  using namespace umbra;
  m.doc() = "umbra's compiled part; use the module umbra";
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<UsageError> option_error(m, "OptionError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      input_error(e.what());
    } catch (const UsageError& e) {
      option_error(e.what());
    } catch (const StagingChoiceError& e) {  // a camera keyword that the model's framing rules out
      option_error(e.what());
    }
  });
  py::class_<ArraysMesh>(m, "ArraysMesh").def(py::init<py::array, py::array, std::string>());
  py::class_<Renderer>(m, "Renderer")
      .def(py::init<std::string>(), py::arg("gl"))
      .def("render", &Renderer::render, py::arg("source"), py::arg("words"), py::arg("mask"), py::arg("depth"))
      .def("render_views", &Renderer::render_views, py::arg("source"), py::arg("words"), py::arg("count"), py::arg("spread"),
           py::arg("passes"), py::arg("cameras_text"), py::arg("cameras_name"), py::arg("turning"))
      .def("close", &Renderer::close)
      .def_property_readonly("platform", &Renderer::platform);
  m.def("check", &check, py::arg("source"), py::arg("time_limit"), py::arg("picture"));
  m.def("repair", &repair, py::arg("source"), py::arg("max_hole_edges"), py::arg("merge_tolerance"), py::arg("time_limit"));
  m.def("load", &load, py::arg("path"));
  // An OpenEXR file's channel names (sorted) and (h, w, channels) float32
  // values, through OpenEXR's own library: the tests read the passes back by it.
  m.def("read_exr", [](const std::string& path) {
    ExrPicture picture = read_exr(path);
    const auto h = py::ssize_t(picture.height), w = py::ssize_t(picture.width), c = py::ssize_t(picture.channels.size());
    return py::make_tuple(picture.channels, owned_array(std::move(picture.values), {h, w, c}));
  }, py::arg("path"));
  m.attr("max_hole_edges") = kDefaultMaxHoleEdges;
  m.attr("__version__") = UMBRA_VERSION;
  m.attr("largest_picture_side") = kLargestPictureSide;
}
