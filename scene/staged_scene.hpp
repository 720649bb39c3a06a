#pragma once
// A mesh file shown on its own, without a scene written for it: umbra builds
// the scene that `umbra render MESH` and `umbra view MESH` draw, as scene
// text the user can save and edit.

#include <string>

#include "scene/scene.hpp"
#include "scene/scene_parser.hpp"

namespace umbra {

// Whether `path` is a mesh file (by its content; see mesh_format.hpp) rather
// than a scene. False for a file that cannot be read: the scene parser then
// says why.
bool is_mesh_file(const std::string& path);

// The stage for the mesh at `mesh_path`: the mesh fitted into the cube
// [-1,1]^3 (and shrunk a little, so that it does not touch the floor), the
// cube's back face z = -1 as a floor, one light above and in front (z > 1),
// and the default camera. The mesh is named by its file name alone, relative
// to the folder that staged_scene_name puts the scene in.
std::string staged_scene_text(const std::string& mesh_path);

// The name the staged scene goes by in messages: "MESH (staged)", in the mesh's folder.
std::string staged_scene_name(const std::string& mesh_path);

// parse_scene_file for a scene, or the staged scene for a mesh file; `staged`
// (when given) receives the staged scene's text, or "" for a scene file.
Scene parse_scene_or_mesh_file(const std::string& path, const MeshLoadProgress& progress = {}, std::string* staged = nullptr);

}  // namespace umbra
