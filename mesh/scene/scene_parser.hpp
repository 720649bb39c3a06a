#pragma once
// Parses a scene file (scene-format.md) into a validated Scene. Every error is
// an InputError located at FILE:LINE:COL; nothing is returned half-built.

#include <functional>
#include <string>

#include "mesh/scene/scene.hpp"

namespace umbra {

// Called before each mesh file is read, with how many came before and how
// many the scene has: large meshes take seconds, and a caller may show that.
using MeshLoadProgress = std::function<void(size_t loaded, size_t total, const std::string& path)>;

// Reads and parses the file at `path`; throws InputError.
Scene parse_scene_file(const std::string& path, const MeshLoadProgress& progress = {});

// Parses scene text; `name` is the file name used in messages.
Scene parse_scene_text(const std::string& text, const std::string& name, const MeshLoadProgress& progress = {});

}  // namespace umbra
