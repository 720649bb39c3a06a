#include "scene/staged_scene.hpp"

#include <filesystem>

#include "mesh/input_error.hpp"
#include "mesh/io/mesh_format.hpp"

namespace umbra {

bool is_mesh_file(const std::string& path) {
  return std::filesystem::path(path).extension() != ".scene" && !detect_mesh_format_of_file(path).empty();
}

std::string staged_scene_text(const std::string& mesh_path) {
  const std::string name = std::filesystem::path(mesh_path).filename().string();
  return "# " + name + " on its own, as umbra stages a mesh file: fitted into the\n"
         "# cube [-1,1]^3 at 0.8 of its size, over the cube's back face as a floor.\n"
         "light 0.6 0.8 1.6\n"
         "material floor diffuse 0.7 0.7 0.72\n"
         "triangle -1 -1 -1   1 -1 -1   1 1 -1 material floor\n"
         "triangle -1 -1 -1   1 1 -1   -1 1 -1 material floor\n"
         "mesh \"" + name + "\" fit scale 0.8\n";
}

std::string staged_scene_name(const std::string& mesh_path) { return mesh_path + " (staged)"; }

Scene parse_scene_or_mesh_file(const std::string& path, const MeshLoadProgress& progress, std::string* staged) {
  if (!is_mesh_file(path)) {
    if (staged) staged->clear();
    return parse_scene_file(path, progress);
  }
  if (std::filesystem::path(path).filename().string().find('"') != std::string::npos)
    throw InputError({path}, "a scene cannot name a file whose name holds a double quote: rename it to stage it");
  const std::string text = staged_scene_text(path);
  if (staged) *staged = text;
  // What the staged scene's mesh statement says belongs to the file: no
  // line of a scene the user never wrote.
  const std::string name = staged_scene_name(path);
  const std::string about_the_file = "mesh file \"" + path + "\"";
  Scene scene;
  try {
    scene = parse_scene_text(text, name, progress);
  } catch (const InputError& e) {
    if (e.where().file != name) throw;
    std::string message = e.message();
    if (message.rfind(about_the_file, 0) == 0) message.erase(0, about_the_file.size() + (message[about_the_file.size()] == ':' ? 2 : 1));
    throw InputError({path}, message);
  }
  for (Warning& w : scene.warnings)
    if (w.where.file == name) w.where = {path};
  return scene;
}

}  // namespace umbra
