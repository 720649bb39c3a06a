#pragma once
// What one picture looks like, as `umbra render`'s options say it: size,
// method, samples, the GL, and for a mesh on its own its camera, light,
// floor and background. Defined once, here, for the command and for the
// Python module, whose keyword arguments are these options by another
// spelling (camera_azimuth=20 is --camera-azimuth 20).

#include <optional>
#include <string>
#include <vector>

#include "render/headless_context.hpp"
#include "render/render_settings.hpp"
#include "scene/scene.hpp"
#include "scene/staged_scene.hpp"
#include "tools/command_line.hpp"

namespace umbra {

struct PictureChoices {
  RenderSettings settings;
  StagingOptions staging;                  // for a mesh on its own
  std::vector<std::string> staging_given;  // the staging options named
  double light_angle_deg = 0.0;
  HeadlessGl gl = HeadlessGl::kAuto;
  std::optional<int> antialias;  // unset: by what is rendered (default_antialias)
  bool antialias_all = false;
  bool show_volumes = false;
  bool size_given = false;  // --size: else a scene's `size`, else the default
};

// --size, --light-angle, --segments, --method, --map-size, --gl,
// --antialias, --antialias-all, --show-volumes and the staging options
// (add_staging_options).
void add_picture_choices(CommandOptions& options, PictureChoices& choices);
// Once parsed: the GL with UMBRA_GL's say (gl_with_environment), the staging
// options checked against each other and its flags noted, the light's turn
// set. Throws UsageError.
void settle_picture_choices(PictureChoices& choices);
// The choices that `words` (options as umbra render takes them, without a
// file or an output) make, settled. Throws UsageError.
PictureChoices parse_picture_choices(const std::vector<std::string>& words);

// Samples per pixel along each side that a picture of `path` gets unless
// --antialias says: 3 for a mesh file staged on its own (a picture to show),
// 1 for a scene file, whose pictures stay as they always were.
int default_antialias(const std::string& path);
// Where a picture's samples are taken: at every pixel where `all`
// (--antialias-all) asks it, where volumes are drawn over the picture
// (--show-volumes: rays would leave them out), where the GL's shadows are
// not the rays' (draws_exact_shadows, and a sphere's volume is its
// N-gon's), or where the GL draws more triangles than the picture has
// pixels (the rays' hierarchy over them would cost more than the larger
// frame: docs/performance.md, "Antialiasing at edges"; `views` pictures of
// one scene share one hierarchy, so the triangles are weighed against all
// their pixels); else at edge pixels alone. Without a scene, as for a small
// one with no sphere.
AntialiasedPixels antialiased_pixels(bool all, bool show_volumes, const RenderSettings& settings, const Scene* scene = nullptr,
                                     size_t views = 1);
// The picture's size, in `settings`: --size where given, else the scene's
// `size` statement, else the default already there.
void set_picture_size(RenderSettings& settings, bool size_given, const Scene& scene);
// The samples a picture of `scene` takes, in `settings`: as many per side
// as --antialias `asked` says, else as the scene's `antialias` statement (a
// staged mesh's says 3), else 1; at every pixel where --antialias-all `all`
// or the statement's `all` says, else where antialiased_pixels says.
void set_picture_samples(RenderSettings& settings, const std::optional<int>& asked, bool all, bool show_volumes,
                         const Scene& scene, size_t views = 1);

}  // namespace umbra
