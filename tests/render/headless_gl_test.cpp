// The two headless platforms: EGL (here Mesa's software device; a GPU where
// there is one) and OSMesa. On the same Mesa driver they must draw the same
// picture, byte for byte; what each is called comes from one table.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "render/headless_context.hpp"
#include "render/shadow_renderer.hpp"
#include "scene/scene_parser.hpp"

namespace umbra {
namespace {

Image render_on(const Scene& scene, HeadlessGl gl, RenderMethod method) {
  RenderSettings settings;
  settings.width = 160;
  settings.height = 120;
  settings.method = method;
  const RenderPlan plan = make_render_plan(scene, settings);
  HeadlessContext context(settings.width, settings.height, gl);
  ShadowRenderer renderer(scene, plan);
  return renderer.render_image(true);  // the volumes too, so their every pixel is compared
}

TEST(HeadlessGl, EglAndOsMesaDrawEveryBundledSceneAlike) {
  // Both are Mesa's llvmpipe on a machine with no GPU; on one with a GPU,
  // EGL draws with it and the pictures may differ in edge pixels.
  if (HeadlessContext(8, 8, HeadlessGl::kEgl).platform().find("software") == std::string::npos)
    GTEST_SKIP() << "EGL draws on a GPU here";
  int scenes = 0;
  for (const auto& entry : std::filesystem::directory_iterator(std::string(UMBRA_SOURCE_DIR) + "/scenes")) {
    if (entry.path().extension() != ".scene") continue;
    const Scene scene = parse_scene_file(entry.path().string());
    for (const RenderMethod method : {RenderMethod::kAuto, RenderMethod::kShadowMap}) {
      const Image egl = render_on(scene, HeadlessGl::kEgl, method);
      const Image osmesa = render_on(scene, HeadlessGl::kOsMesa, method);
      EXPECT_TRUE(egl.pixels == osmesa.pixels) << entry.path() << " with --method " << method_name(method);
    }
    ++scenes;
  }
  EXPECT_GE(scenes, 10);
}

TEST(HeadlessGl, EachPlatformSaysWhatItIs) {
  EXPECT_EQ(HeadlessContext(8, 8, HeadlessGl::kOsMesa).platform(), "OSMesa");
  const HeadlessContext egl(8, 8, HeadlessGl::kEgl);
  EXPECT_EQ(egl.platform().rfind("EGL 1.", 0), 0u) << egl.platform();
  EXPECT_NE(egl.description().find("OpenGL"), std::string::npos) << egl.description();
}

TEST(HeadlessGl, NamesComeFromTheTable) {
  EXPECT_EQ(headless_gl_names(), "auto, egl or osmesa");
  for (const HeadlessGlRow& row : kHeadlessGlTable) EXPECT_EQ(headless_gl_from_name(row.name), row.gl);
  EXPECT_FALSE(headless_gl_from_name("glx"));
}

// UMBRA_GL as it was, put back however the test ends: on a machine without
// OSMesa the test throws, and every later test in the process would have
// asked for OSMesa.
struct UmbraGlRestored {
  const char* before = std::getenv("UMBRA_GL");
  const std::string saved = before ? before : "";
  ~UmbraGlRestored() {
    if (before) setenv("UMBRA_GL", saved.c_str(), 1);
    else unsetenv("UMBRA_GL");
  }
};

TEST(HeadlessGl, AnUnknownUmbraGlIsAnErrorNotAGuess) {
  const UmbraGlRestored restored;
  setenv("UMBRA_GL", "vulkan", 1);
  try {
    HeadlessContext context(8, 8);
    ADD_FAILURE() << "made a context on " << context.platform();
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "UMBRA_GL must be auto, egl or osmesa, not \"vulkan\"");
  }
  setenv("UMBRA_GL", "osmesa", 1);
  EXPECT_EQ(HeadlessContext(8, 8).platform(), "OSMesa");
}

TEST(HeadlessGl, ATooLargeImageIsRefusedWithItsLimit) {
  for (const HeadlessGlRow& row : kHeadlessGlTable) {
    if (row.gl == HeadlessGl::kAuto) continue;
    try {
      HeadlessContext context(1 << 20, 16, row.gl);
      ADD_FAILURE() << row.name << " made a context of 1048576x16";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("the image may be at most "), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace umbra
