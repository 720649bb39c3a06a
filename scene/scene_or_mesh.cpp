#include "scene/staged_scene.hpp"

#include <filesystem>
#include <string>
#include <string_view>

#include "mesh/input_error.hpp"
#include "mesh/io/mapped_file.hpp"
#include "mesh/io/mesh_format.hpp"

namespace umbra {

bool is_mesh_file(const std::string& path) {
  return std::filesystem::path(path).extension() != ".scene" && !detect_mesh_format_of_file(path).empty();
}

std::optional<InputError> neither_scene_nor_mesh(const std::string& path) {
  try {
    const MappedFile file(path);
    const std::string_view bytes = file.bytes();
    // No statement at all: nothing to say of it but that, whatever its name.
    if (const std::string blank = blank_content(bytes); !blank.empty()) return InputError({path}, blank, InputProblem::kEmpty);
    if (std::filesystem::path(path).extension() == ".scene" || !detect_mesh_format(bytes, path).empty()) return std::nullopt;
    std::string what = other_known_format(bytes);
    if (what.empty() && !looks_like_text(bytes.substr(0, 1 << 16))) what = "binary data";
    if (what.empty()) return std::nullopt;
    return InputError({path}, "neither a scene nor a mesh file (" + mesh_format_names() + "): " + what, InputProblem::kUnsupportedFormat);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

}  // namespace umbra
