#pragma once
// Reads the mesh files a scene names, once the whole scene has parsed: each
// file is read and checked (mesh/check/), then placed, and the scene keeps
// only what rendering needs of it (Scene::Mesh). The parser reads statements;
// this builds their meshes.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mesh/io/polygon_soup.hpp"
#include "scene/scene.hpp"

namespace umbra {

// Called before each mesh file is read, with how many came before and how
// many the scene has: large meshes take seconds, and a caller may show that.
using MeshLoadProgress = std::function<void(size_t loaded, size_t total, const std::string& path)>;

// A mesh statement as parsed: its path as written, its material and
// placement, where it is, and where its path is.
struct MeshStatement {
  Mesh mesh;
  FileLoc path_at;
  // Given: the mesh itself, taken instead of reading mesh.path (a mesh
  // handed over as arrays: array_soup.hpp).
  std::shared_ptr<const PolygonSoup> soup;
  // Written by umbra (a staged scene), not by the user: an error in the
  // file is said of the file alone, never of this statement's line.
  bool staged = false;
};

// Reads every statement's file, its path taken relative to the folder of the
// scene file (scene.path), on every core, each file on its own. Appends the
// meshes, the files' own materials and the warnings to `scene` in statement
// order; throws the first InputError in statement order, located in the mesh
// file where it has a line, else at the statement's path. `maps` says where
// the files' texture maps may be read from.
void load_scene_meshes(std::vector<MeshStatement> statements, Scene& scene, const MeshLoadProgress& progress,
                       const ReadOptions& maps = {});

// For a caller that draws one scene from many views (umbra view's window).
// Loading leaves a closed mesh's self-crossings to the picture
// (BackFaces::kHiddenUnlessSeen): an occlusion query at each new view,
// whose answer a frame waits for. Instead, each such mesh is searched
// once, on every core: kHidden where no two of its triangles cross, kDrawn
// where some do (drawn whole, as the picture would draw it where a back
// face showed). The pictures are the same either way.
void settle_back_faces_by_search(Scene& scene);

}  // namespace umbra
