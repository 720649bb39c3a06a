#pragma once
// `umbra render PATH... -o OUTDIR`: one picture per scene or mesh file, for
// folders (searched for meshes by their content, as `umbra check` searches
// them) and lists of files, on several cores and in shards.

#include <optional>
#include <string>
#include <vector>

#include "render/headless_context.hpp"
#include "render/render_plan.hpp"
#include "scene/staged_scene.hpp"
#include "tools/mesh_paths.hpp"
#include "tools/view_set_files.hpp"

namespace umbra {

struct BatchRenderOptions {
  std::vector<std::string> paths;  // files and folders, as given
  std::string out_dir;
  RenderSettings settings;
  StagingOptions staging;  // for mesh files, with each format's own up unless it says; its light turn for scenes too
  HeadlessGl gl = HeadlessGl::kAuto;
  std::optional<int> antialias;  // unset: each file's default_antialias
  bool antialias_all = false;    // samples at every pixel, not at edges alone (antialiased_pixels)
  bool show_volumes = false;
  bool size_given = false;  // --size: else each scene's own size statement
  size_t jobs = 1;  // pictures drawn at a time, each in its own GL context
  std::optional<Shard> shard;
  std::optional<std::string> sheet;  // also one PNG of every picture, labelled with its file's name
  ReadOptions reading;               // texture maps from any folder, not only the one each file was found in (root aside); CAD tessellation
  double timeout_s = 0.0;            // a file's render stopped after this long (0: no limit)
  bool skip_existing = false;        // a picture newer than its file is not drawn again
  bool json = false;                 // a line of JSON on stdout per input file
  // --views or --cameras: each mesh file's views and their data into
  // OUT_DIR/NAME/ (view_set_files.hpp), in place of one picture; its
  // transforms.json, written last, stands for the file's output.
  std::optional<ViewSetRequest> views;
  // --turntable with --format: each file's frames as one animation,
  // OUT_DIR/NAME.EXT, in place of its folder of frames.
  std::optional<AnimationRequest> animation;
};

// Writes OUT_DIR/NAME.png for each file, NAME its path relative to the
// folder it was found in (or its file name), so that a.obj and a.stl do not
// meet; where two files would still share a NAME (a/x.off and b/x.off), each
// NAME takes as many of its folders' names as tell them apart, all decided
// before anything is drawn. Files are drawn in worker processes
// (isolated_runs.hpp): one that fails, hangs past `timeout_s`, crashes or
// runs out of memory is reported on stderr (and in its JSON line) and the
// rest go on. With `sheet`, also a contact sheet of this run's pictures in
// file order. Returns 0 when every picture was written (or was up to date),
// 1 when any file failed, 2 when there is nothing to render.
int run_batch_render(const BatchRenderOptions& options);

}  // namespace umbra
