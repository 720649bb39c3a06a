#pragma once
// `umbra render MESH --views N [--views-on sphere] [--passes LIST] -o DIR`:
// each view's picture and passes written into DIR as NNN.png,
// NNN.depth.exr, NNN.normal.exr, NNN.object.png and NNN.shadow.png (one
// per light, NNN.shadowK.png, where there are several), and the views'
// cameras as DIR/transforms.json (view_set.hpp).

#include <functional>
#include <optional>
#include <string>

#include "render/headless_context.hpp"
#include "scene/mesh_loader.hpp"
#include "tools/picture_choices.hpp"
#include "tools/view_set.hpp"

namespace umbra {

// What was written: how many views, of what size, of how many triangles.
struct WrittenViews {
  int views = 0, width = 0, height = 0;
  size_t triangles = 0;
};
// Told how far the drawing is: done of total, and what is under way.
using ViewProgress = std::function<void(size_t done, size_t total, const std::string& what)>;

// The views of the mesh file `mesh_path` (a scene is an InputError) into
// `folder`, made where missing, drawn in `context` (made on first use and
// kept); its warnings' lines added to `messages`. Each view's files are
// renamed into place together once drawn; transforms.json last, once every
// view is. Throws as loading and drawing throw (InputError,
// UsageError, StagingChoiceError, FrameTooLarge, ...).
WrittenViews write_view_files(const std::string& mesh_path, const std::string& folder, PictureChoices choices,
                              const ViewSetRequest& request, const TextureMaps& maps, std::optional<HeadlessContext>& context,
                              const ViewProgress& progress, std::string& messages);

// The command's: returns the exit status: 0 written, 1 a file that cannot
// be read or written, 2 an option the model rules out. `shown` names the
// mesh in what it says ("standard input" for a copy of it).
int write_view_set(const std::string& mesh_path, const std::string& folder, PictureChoices choices, const ViewSetRequest& request,
                   bool any_texture_path, const std::string& shown);

}  // namespace umbra
