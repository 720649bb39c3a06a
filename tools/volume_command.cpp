#include "tools/volume_command.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>

#include <glm/geometric.hpp>

#include "mesh/file_extension.hpp"
#include "image/partial_file.hpp"
#include "scene/scene_checks.hpp"
#include "scene/scene_parser.hpp"
#include "scene/staged_scene.hpp"
#include "render/render_plan.hpp"
#include "scene/scene_text.hpp"
#include "tools/command_line.hpp"

namespace umbra {

const std::string kVolumeUsage =
    R"(usage: umbra volume SCENE -o OUT.obj [options]
       umbra volume MESH -o OUT.obj [options]

Writes the shadow volumes of one light as an OBJ file, to look at in any mesh
viewer: one group per caster, named for its kind and line, and faces
oriented outward. A mesh file (umbra formats lists the formats) is
staged as umbra render stages it, and only its own volume is written (not
the floor's). A volume reaches infinity; here its vertices at infinity
(P - L, 0) are put at P + D (P - L) / |P - L|, a finite distance D beyond
the caster.

options:
{options})";

namespace {

struct VolumeOptions {
  std::string scene_path, output;
  int light = 1;
  double light_angle_deg = 0.0;
  double far = 3.0;
  std::string up;  // for a mesh file: "" for its format's own
  RenderSettings settings;
};

VolumeOptions parse_volume_options(const std::vector<std::string>& argv) {
  VolumeOptions o;
  std::vector<std::string> scenes;
  CommandOptions options;
  add_output_option(options, o.output, {"OUT.obj", "the file to write (required)"});
  options.value("--light", {"N", "which light, counting from 1 (default " + std::to_string(o.light) + ")"},
                [&](const std::string& n, const std::string& t) { o.light = parse_int_in(n, t, 1, 1 << 20); });
  add_light_angle_option(options, o.light_angle_deg, "rotate every light about the z axis by DEG degrees");
  add_segments_option(options, o.settings.sphere_segments);
  options.value("--far", {"D", "distance of the far vertices beyond the caster (default " + number_text(o.far) + ")"},
                [&](const std::string& n, const std::string& t) {
                  o.far = parse_finite_number(n, t);
                  if (o.far <= 0) throw UsageError("--far must be positive");
                });
  std::vector<std::string> up_given;
  add_up_option(options, o.up, up_given);
  options.help_option();
  options.positionals(scenes);
  options.parse(argv);
  if (scenes.size() > 1) throw UsageError("one scene at a time (got \"" + scenes[0] + "\" and \"" + scenes[1] + "\")");
  if (!scenes.empty()) o.scene_path = scenes[0];
  if (o.scene_path.empty()) throw UsageError("no scene or mesh file given");
  require_staged(up_given, o.scene_path);
  if (o.output.empty()) throw UsageError("no output file given (-o OUT.obj)");
  require_other_than_input("-o", o.output, o.scene_path);
  // An OBJ file under another format's name (x.png, x.stl) would mislead
  // whatever opens it by its name.
  const std::string extension = lowercase_extension(o.output);
  struct stat there {};
  const bool device = ::stat(o.output.c_str(), &there) == 0 && (S_ISFIFO(there.st_mode) || S_ISCHR(there.st_mode));
  if (extension != ".obj" && !device)
    throw UsageError("-o " + o.output + ": umbra volume writes an OBJ file; name a .obj file");
  return o;
}

// The volume with every vertex finite, ready for a mesh file.
std::vector<glm::dvec3> finite_vertices(const ShadowVolume& volume, const glm::dvec3& light, double far) {
  std::vector<glm::dvec3> points;
  for (const glm::dvec4& v : volume.vertices) {
    if (v.w != 0.0) {
      points.push_back(glm::dvec3(v) / v.w);
    } else {
      // (P - L, 0): P is light + direction, so this is `far` beyond P.
      const glm::dvec3 direction = glm::dvec3(v);
      points.push_back(light + direction + far * glm::normalize(direction));
    }
  }
  return points;
}

void write_group(std::ostream& out, const std::string& name, const std::vector<glm::dvec3>& points,
                 const std::vector<std::array<uint32_t, 3>>& triangles, size_t& written_vertices) {
  out << "g " << name << "\n";
  char line[128];
  for (const glm::dvec3& p : points) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
    out << line;
  }
  for (const auto& t : triangles)
    out << "f " << written_vertices + t[0] + 1 << " " << written_vertices + t[1] + 1 << " " << written_vertices + t[2] + 1 << "\n";
  written_vertices += points.size();
}

}  // namespace

int run_volume_command(const std::vector<std::string>& argv) {
  VolumeOptions options;
  if (const auto exit_status = parse_command_line("volume", kVolumeUsage, argv, parse_volume_options, options))
    return *exit_status;
  if (const std::optional<InputError> error = neither_scene_nor_mesh(options.scene_path)) {
    std::cerr << error->what() << "\n";
    return 2;
  }
  try {
    StagingOptions staging;
    staging.up = options.up;
    staging.view.light_turn_deg = options.light_angle_deg;
    std::string staged;
    Scene scene = parse_scene_or_mesh_file(options.scene_path, {}, &staged, staging);
    for (const Warning& w : scene.warnings) std::cerr << w.where.str() << ": warning: " << w.message << "\n";
    if (size_t(options.light) > scene.lights.size())
      throw InputError({scene.path}, "--light " + std::to_string(options.light) + ": the scene has " +
                                         std::to_string(scene.lights.size()) + " light(s)");
    require_lights_off_casters(scene);
    // The whole closed volume, caps included, whatever count a render would choose.
    RenderSettings settings = options.settings;
    settings.method = RenderMethod::kZFail;
    const RenderPlan plan = make_render_plan(scene, settings);
    const LightPlan& lp = plan.lights[size_t(options.light - 1)];
    const glm::dvec3 light = scene.lights[size_t(options.light - 1)].position;

    PartialFile partial(options.output, "the volume file");
    std::ofstream out(partial.temporary_path());
    out << "# shadow volumes of light " << options.light << " of " << scene.path << ", made by umbra volume\n"
        << "# vertices at infinity are drawn " << options.far << " beyond the caster\n";
    size_t written = 0, groups = 0, triangles = 0;
    for (const CasterEntry& e : lp.casters) {
      if (!staged.empty() && e.kind != "mesh") continue;  // the stage's floor
      ShadowVolume volume = e.volume;
      if (e.mesh_volume >= 0) {
        // A mesh volume: indices over the mesh's points, then the same points at infinity.
        const MeshVolumePlan& m = lp.mesh_volumes[size_t(e.mesh_volume)];
        const std::vector<glm::dvec3>& positions = scene.meshes[m.mesh].positions;
        const uint32_t base = uint32_t(volume.vertices.size());
        for (const glm::dvec3& p : positions) volume.vertices.emplace_back(p, 1.0);
        for (const glm::dvec3& p : positions) volume.vertices.emplace_back(p - light, 0.0);
        const uint32_t* indices = m.volume.buffer.data();
        for (size_t i = 0; i < m.volume.count; i += 3)
          volume.triangles.push_back({base + indices[i], base + indices[i + 1], base + indices[i + 2]});
      }
      if (volume.triangles.empty()) continue;
      write_group(out, e.kind + "_line_" + std::to_string(e.where.line), finite_vertices(volume, light, options.far),
                  volume.triangles, written);
      ++groups;
      triangles += volume.triangles.size();
    }
    out.close();
    if (!out) throw InputError({options.output}, "cannot write the volume file");
    partial.commit();
    std::cout << "wrote " << options.output << ": " << groups << " volume(s), " << triangles << " triangles\n";
    return 0;
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
}

}  // namespace umbra
