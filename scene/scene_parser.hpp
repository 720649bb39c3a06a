#pragma once
// Parses a scene file (scene-format.md) into a validated Scene. Every error is
// an InputError located at FILE:LINE:COL; nothing is returned half-built.

#include <string>

#include "scene/mesh_loader.hpp"
#include "scene/scene.hpp"

namespace umbra {

// Reads and parses the file at `path`; throws InputError. `maps` says where
// its meshes' texture maps may be read from.
Scene parse_scene_file(const std::string& path, const MeshLoadProgress& progress = {}, const ReadOptions& maps = {});

// Parses scene text; `name` is the file name used in messages.
Scene parse_scene_text(const std::string& text, const std::string& name, const MeshLoadProgress& progress = {},
                       const ReadOptions& maps = {});

}  // namespace umbra
