// `umbra view` under Xvfb (a real window, Mesa's GLX): a scripted run's
// screenshot is pixel for pixel the headless render of the same frame.
#include <gtest/gtest.h>
#include <webp/demux.h>

#include <regex>
#include <vector>

#include "mesh/word_list.hpp"
#include "render/render_method.hpp"
#include "image/image.hpp"
#include "tests/tools/command_fixture.hpp"

namespace umbra {
namespace {

using test::CommandResult;

class ViewCommand : public test::CommandTest {
 protected:
  // The viewer in a virtual X display of its own. Its authority file lives in
  // the test's folder: left to make a temporary folder of its own, xvfb-run
  // removes that folder while the server it has yet to stop may still be in
  // it, and now and then fails with status 5 after the viewer has finished.
  CommandResult run_in_xvfb(const std::string& args) const {
    return run(args, "xvfb-run -a -f " + path("Xauthority") + " -s '-screen 0 640x480x24' ");
  }
  static std::string scene(const std::string& name) { return std::string(UMBRA_SOURCE_DIR) + "/scenes/" + name; }
};

void expect_same_pixels(const Image& a, const Image& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.channels, b.channels);
  size_t differing = 0;
  for (size_t i = 0; i < a.pixels.size(); ++i) differing += a.pixels[i] != b.pixels[i];
  EXPECT_EQ(differing, 0u);
}

TEST_F(ViewCommand, PausedScreenshotIsTheHeadlessRender) {
  const CommandResult view = run_in_xvfb("view " + scene("demo.scene") +
                                         " --size 160x120 --paused --light-angle 30 --frames 3 --screenshot " + path("v.png"));
  ASSERT_EQ(view.status, 0) << view.err;
  // The screenshot's line, then the frame times of the frames before the last.
  const std::string wrote = "wrote " + path("v.png") + " (frame 3, light at 30 deg)\n";
  ASSERT_EQ(view.out.substr(0, wrote.size()), wrote);
  const std::string times = view.out.substr(wrote.size());
  EXPECT_TRUE(std::regex_match(times, std::regex(R"(2 frames \(all but the last\): median [0-9]+\.[0-9] ms, worst [0-9]+\.[0-9] ms )"
                                                 R"(a frame \(plan, drawing and swap\)\n)")))
      << times;
  ASSERT_EQ(run("render " + scene("demo.scene") + " --size 160x120 --light-angle 30 -o " + path("h.png")).status, 0);
  expect_same_pixels(read_png(path("v.png")), read_png(path("h.png")));
}

// An orthographic scene in the window is its headless render too.
TEST_F(ViewCommand, AnOrthographicScenesScreenshotIsTheHeadlessRender) {
  const CommandResult view = run_in_xvfb("view " + scene("orthographic.scene") + " --size 160x120 --paused --frames 2 --screenshot " +
                                         path("v.png"));
  ASSERT_EQ(view.status, 0) << view.err;
  ASSERT_EQ(run("render " + scene("orthographic.scene") + " --size 160x120 -o " + path("h.png")).status, 0);
  expect_same_pixels(read_png(path("v.png")), read_png(path("h.png")));
}

TEST_F(ViewCommand, AMeshFileIsStagedAsRenderStagesIt) {
  const std::string mesh = std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj";
  const CommandResult view = run_in_xvfb("view " + mesh + " --size 160x120 --paused --frames 2 --screenshot " + path("v.png"));
  ASSERT_EQ(view.status, 0) << view.err;
  // Still from the first frame on, so the second is drawn with the staged
  // model's 3 x 3 samples at every pixel.
  ASSERT_EQ(run("render " + mesh + " --size 160x120 --antialias-all -o " + path("h.png")).status, 0);
  expect_same_pixels(read_png(path("v.png")), read_png(path("h.png")));
}

// A view that moves is drawn one sample a pixel; one that stands still, with
// its samples (the scene's antialias statement, or --antialias) at every
// pixel.
TEST_F(ViewCommand, AStillViewTakesItsSamplesAndAMovingOneOne) {
  const std::string torus = write("torus.scene", "antialias 3\nlight 0.5 0.9 1.8\n"
                                                 "triangle -1 -1 -1   1 -1 -1   1 1 -1\ntriangle -1 -1 -1   1 1 -1   -1 1 -1\n"
                                                 "mesh " + std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj scale 0.5 "
                                                 "rotate 1 0.3 0 50 translate 0 0 -0.25\n");
  const auto expect_view_is_render = [&](const std::string& view_options, const std::string& render_options) {
    SCOPED_TRACE(view_options);
    const CommandResult view = run_in_xvfb("view " + torus + " --size 120x90 " + view_options + " --screenshot " + path("v.png"));
    ASSERT_EQ(view.status, 0) << view.err;
    ASSERT_EQ(run("render " + torus + " --size 120x90 " + render_options + " -o " + path("h.png")).status, 0);
    expect_same_pixels(read_png(path("v.png")), read_png(path("h.png")));
  };
  // 60 degrees a second at 1/60 s a frame: frame 3 is drawn with the light at 2 degrees.
  expect_view_is_render("--speed 60 --frames 3", "--light-angle 2 --antialias 1");
  expect_view_is_render("--paused --frames 3", "--antialias-all");
  expect_view_is_render("--paused --frames 3 --antialias 2", "--antialias 2 --antialias-all");
  expect_view_is_render("--paused --frames 3 --antialias 1", "--antialias 1");
}

TEST_F(ViewCommand, OrbitingLightScreenshotIsTheHeadlessRenderAtItsAngle) {
  // 60 degrees a second at 1/60 s a frame: frame 7 is drawn with the light at 6 degrees.
  const CommandResult view = run_in_xvfb("view " + scene("mesh_torus.scene") +
                                         " --size 160x120 --speed 60 --frames 7 --screenshot " + path("v.png"));
  ASSERT_EQ(view.status, 0) << view.err;
  EXPECT_EQ(view.out.substr(0, view.out.find('\n') + 1), "wrote " + path("v.png") + " (frame 7, light at 6 deg)\n");
  ASSERT_EQ(run("render " + scene("mesh_torus.scene") + " --size 160x120 --light-angle 6 -o " + path("h.png")).status, 0);
  expect_same_pixels(read_png(path("v.png")), read_png(path("h.png")));
}

// --record with --frames: every frame drawn, none of the overlay, read
// back by libwebp's animation decoder: the first frame is the headless
// render with the light where it starts, the last the screenshot (and so
// the headless render at 6 degrees).
TEST_F(ViewCommand, ARecordingHoldsEveryFrameTheWindowDrew) {
  const CommandResult view = run_in_xvfb("view " + scene("mesh_torus.scene") + " --size 160x120 --speed 60 --frames 7 --record " +
                                         path("rec.webp") + " --screenshot " + path("v.png"));
  ASSERT_EQ(view.status, 0) << view.err;
  EXPECT_EQ(view.out.substr(0, view.out.find("\nwrote " + path("v.png"))),
            "recording to " + path("rec.webp") + " (c stops)\nwrote " + path("rec.webp") + " (7 frames at 160x120)");
  ASSERT_EQ(run("render " + scene("mesh_torus.scene") + " --size 160x120 -o " + path("h0.png")).status, 0);
  const std::string bytes = read(path("rec.webp"));
  const WebPData data{reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()};
  WebPAnimDecoderOptions options;
  ASSERT_TRUE(WebPAnimDecoderOptionsInit(&options));
  options.color_mode = MODE_RGBA;
  WebPAnimDecoder* decoder = WebPAnimDecoderNew(&data, &options);
  ASSERT_NE(decoder, nullptr);
  std::vector<Image> frames;
  while (WebPAnimDecoderHasMoreFrames(decoder)) {
    uint8_t* rgba = nullptr;
    int timestamp = 0;
    ASSERT_TRUE(WebPAnimDecoderGetNext(decoder, &rgba, &timestamp));
    Image frame(160, 120, 3);
    for (size_t i = 0; i < 160 * 120; ++i)
      for (size_t c = 0; c < 3; ++c) frame.pixels[i * 3 + c] = rgba[i * 4 + c];
    frames.push_back(frame);
  }
  WebPAnimDecoderDelete(decoder);
  ASSERT_EQ(frames.size(), 7u);
  expect_same_pixels(frames.front(), read_png(path("h0.png")));
  expect_same_pixels(frames.back(), read_png(path("v.png")));
  // A name that is no animation's is refused before any window opens.
  const CommandResult bad = run("view " + scene("demo.scene") + " --record " + path("rec.avi"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err, "umbra view: --record records into .mp4, .webp or .gif, got \"" + path("rec.avi") + "\"\n(see umbra view --help)\n");
}

TEST_F(ViewCommand, OverlayIsDrawnInTheTopLeftCornerOnly) {
  const CommandResult view = run_in_xvfb("view " + scene("demo.scene") +
                                         " --size 640x480 --paused --frames 2 --overlay-in-screenshot --screenshot " + path("v.png"));
  ASSERT_EQ(view.status, 0) << view.err;
  ASSERT_EQ(run("render " + scene("demo.scene") + " --size 640x480 -o " + path("h.png")).status, 0);
  const Image v = read_png(path("v.png")), h = read_png(path("h.png"));
  int inside = 0, outside = 0;
  for (int y = 0; y < h.height; ++y)
    for (int x = 0; x < h.width; ++x) {
      const bool differs = v.at(x, y, 0) != h.at(x, y, 0) || v.at(x, y, 1) != h.at(x, y, 1) || v.at(x, y, 2) != h.at(x, y, 2);
      (y < 160 ? inside : outside) += differs;
    }
  EXPECT_GT(inside, 5000) << "seven lines of text in a translucent box";
  EXPECT_EQ(outside, 0);
}

TEST_F(ViewCommand, LightOrbitingIntoASphereStopsOutsideIt) {
  // 90 degrees a frame: frame 2 would put the light at (0, 1, 2), inside the sphere.
  const std::string s = write("orbit.scene", "light 1 0 2\nsphere 0 1 2 0.3\ntriangle -1 -1 -1 1 -1 -1 0 1 -1\n");
  const CommandResult view = run_in_xvfb("view " + s + " --size 80x60 --speed 5400 --frames 4 --screenshot " + path("v.png"));
  ASSERT_EQ(view.status, 0) << view.err;
  EXPECT_EQ(view.out.substr(0, view.out.find('\n') + 1), "wrote " + path("v.png") + " (frame 4, light at 0 deg)\n");
  ASSERT_EQ(run("render " + s + " --size 80x60 -o " + path("h.png")).status, 0);
  expect_same_pixels(read_png(path("v.png")), read_png(path("h.png")));
}

TEST_F(ViewCommand, BadSceneExitsOneWithItsLocatedError) {
  const std::string bad = write("bad.scene", "light 0 0 2\nsphere 0 0 0 O.5\n");
  const CommandResult r = run_in_xvfb("view " + bad + " --frames 1");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, bad + ":2:14: expected a number for the sphere radius, got \"O.5\"\n");
}

TEST_F(ViewCommand, WithoutADisplayItSaysSo) {
  const CommandResult r = run("view " + scene("demo.scene") + " --frames 1", "env -u DISPLAY -u WAYLAND_DISPLAY ");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("GLFW: cannot start (is there a display? try xvfb-run)"), std::string::npos) << r.err;
}

TEST_F(ViewCommand, UsageErrors) {
  const CommandResult r = run("view " + scene("demo.scene") + " --screenshot x.png");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra view: --screenshot needs --frames N\n(see umbra view --help)\n");
  const CommandResult help = run("view --help");
  EXPECT_EQ(help.status, 0);
  EXPECT_NE(help.out.find("  v             show or hide the shadow volumes\n"), std::string::npos);
  // The methods from the method table: a new row breaks no string here.
  std::vector<std::string> interactive;
  for (const RenderMethod m : all_methods())
    if (is_interactive(m)) interactive.push_back(method_name(m));
  EXPECT_NE(help.out.find("  m             switch method:\n                " + word_list(interactive) + "\n"), std::string::npos)
      << help.out;
}

}  // namespace
}  // namespace umbra
