#pragma once
// `umbra render MESH --views N [--views-on sphere] [--passes LIST] -o DIR`:
// each view's picture and passes written into DIR as NNN.png,
// NNN.depth.exr, NNN.normal.exr, NNN.object.png and NNN.shadow.png (one
// per light, NNN.shadowK.png, where there are several), and the views'
// cameras as DIR/transforms.json (view_set.hpp). `--turntable N` writes a
// motion's frames so, or as one animation (animation_file.hpp).

#include <functional>
#include <optional>
#include <string>

#include "image/animation_file.hpp"
#include "render/headless_context.hpp"
#include "scene/mesh_loader.hpp"
#include "tools/picture_choices.hpp"
#include "tools/view_preparation.hpp"
#include "tools/view_set.hpp"

namespace umbra {

// The views of `mesh_path` into `folder`, made where missing, drawn in
// `context` (made on first use and kept). Each view's files are renamed
// into place together once drawn; transforms.json last, once every view
// is. Throws as prepare_views and drawing throw (InputError, UsageError,
// StagingChoiceError, FrameTooLarge, ...).
WrittenViews write_view_files(const std::string& mesh_path, const std::string& folder, const PictureChoices& choices,
                              const ViewSetRequest& request, const ReadOptions& maps, std::optional<HeadlessContext>& context,
                              const ViewProgress& progress, std::string& messages);

// An animation's format and pace (--fps, --quality).
struct AnimationRequest {
  AnimationFormat format = AnimationFormat::kMp4;
  double fps = 30.0;
  std::optional<int> quality;
};
// The request's pictures of `path` as one animation file, `output`: each
// frame encoded on another thread while the next is drawn, the file
// renamed into place once whole (none is left where anything fails).
WrittenViews write_animation_file(const std::string& path, const std::string& output, const PictureChoices& choices,
                                  const ViewSetRequest& request, const AnimationRequest& animation, const ReadOptions& maps,
                                  std::optional<HeadlessContext>& context, const ViewProgress& progress, std::string& messages);

// The command's: an animation where `animation` is given, else each
// picture's files in the folder `output`. Returns the exit status: 0
// written, 1 a file that cannot be read or written, 2 an option the model
// rules out. `shown` names the file in what it says ("standard input" for
// a copy of it).
int write_view_set(const std::string& path, const std::string& output, PictureChoices choices, const ViewSetRequest& request,
                   const std::optional<AnimationRequest>& animation, const ReadOptions& maps, const std::string& shown);

}  // namespace umbra
