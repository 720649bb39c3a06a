#pragma once
// `umbra render MESH --views N [--views-on sphere] [--passes LIST] -o DIR`:
// each view's picture and passes written into DIR as NNN.png,
// NNN.depth.exr, NNN.normal.exr, NNN.object.png and NNN.shadow.png (one
// per light, NNN.shadowK.png, where there are several), and the views'
// cameras as DIR/transforms.json (view_set.hpp).

#include <string>

#include "tools/picture_choices.hpp"
#include "tools/view_set.hpp"

namespace umbra {

// Returns the exit status: 0 written, 1 a file that cannot be read or
// written, 2 an option the model rules out. Each view's files are renamed
// into place together once drawn; transforms.json last, once every view is.
int write_view_set(const std::string& mesh_path, const std::string& folder, PictureChoices choices, const ViewSetRequest& request,
                   bool any_texture_path);

}  // namespace umbra
