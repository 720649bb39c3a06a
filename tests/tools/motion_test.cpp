// umbra render --turntable N [--orbit light] -o OUT.mp4 | .webp | .gif | DIR/:
// a motion's frames, read back by the formats' own decoders (ffprobe,
// libwebp's demux, giflib); a turntable whose studio holds still; a light
// whose shadow sweeps exactly while the model holds still; and frames that
// --cameras draws again byte for byte.

#include <gif_lib.h>
#include <webp/demux.h>

#include <cstdio>
#include <memory>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "image/animation_file.hpp"
#include "image/image.hpp"
#include "render/render_plan.hpp"
#include "scene/motion.hpp"
#include "tests/mesh/mesh_builders.hpp"
#include "tests/render/mask_comparison.hpp"
#include "tests/tools/command_fixture.hpp"
#include "tools/picture_drawing.hpp"
#include "tools/view_preparation.hpp"

namespace umbra::test {
namespace {

using nlohmann::json;

const std::string kWuson = "/usr/share/assimp/models/OFF/Wuson.off";  // Debian's assimp-testmodels: a real scan

class Motion : public CommandTest {
 protected:
  // A torus lying flat (in the xy plane, --up +z): 24 quads round its ring, 12 round its tube.
  std::string flat_torus() const {
    std::ofstream(path("torus.obj")) << obj_text(quad_torus(24, 12));
    return path("torus.obj");
  }
  // What `command` prints on standard output.
  static std::string output_of(const std::string& command) {
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    std::string out;
    char buffer[256];
    while (pipe && fgets(buffer, sizeof buffer, pipe.get())) out += buffer;
    return out;
  }
  // The names in the scratch folder's `folder`, sorted.
  std::vector<std::string> names_in(const std::string& folder) const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(path(folder))) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

TEST_F(Motion, EveryFormatIsBuiltIn) {
  // ./build.sh test installs every format's library: a test build without one would pass over what it cannot read back.
  for (const AnimationFormatRow& row : kAnimationFormats) EXPECT_TRUE(row.built) << animation_unavailable(row.format);
}

// An MP4's frames as ffprobe (Debian's ffmpeg) counts them, decoding each.
TEST_F(Motion, AnMp4IsH264InYuv420pWithEveryFrameAtItsPace) {
  const CommandResult r = run("render " + flat_torus() + " --turntable 12 --fps 24 --size 96x64 -o " + path("spin.mp4"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, "wrote 12 frames of " + path("torus.obj") + " (96x64) to " + path("spin.mp4") + ", an MP4 video (H.264)\n");
  EXPECT_EQ(output_of("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                      "stream=codec_name,profile,width,height,pix_fmt,r_frame_rate,nb_read_frames -of default=noprint_wrappers=1 " +
                      shell_quoted(path("spin.mp4"))),
            "codec_name=h264\nprofile=High\nwidth=96\nheight=64\npix_fmt=yuv420p\nr_frame_rate=24/1\nnb_read_frames=12\n");
  // The index before the frames ("faststart"), so that a browser plays it while it loads.
  const std::string bytes = read(path("spin.mp4"));
  EXPECT_LT(bytes.find("moov"), bytes.find("mdat"));
}

// An animated WebP's frames as libwebp's demux reads them: their count,
// the canvas, looping forever, and each frame's start at its pace.
TEST_F(Motion, AnAnimatedWebpHasEveryFrameAtItsPace) {
  const CommandResult r = run("render " + flat_torus() + " --turntable 5 --fps 20 --size 80x60 -o " + path("spin.webp"));
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string bytes = read(path("spin.webp"));
  const WebPData data{reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()};
  WebPDemuxer* demux = WebPDemux(&data);
  ASSERT_NE(demux, nullptr);
  EXPECT_EQ(WebPDemuxGetI(demux, WEBP_FF_FRAME_COUNT), 5u);
  EXPECT_EQ(WebPDemuxGetI(demux, WEBP_FF_CANVAS_WIDTH), 80u);
  EXPECT_EQ(WebPDemuxGetI(demux, WEBP_FF_CANVAS_HEIGHT), 60u);
  EXPECT_EQ(WebPDemuxGetI(demux, WEBP_FF_LOOP_COUNT), 0u);  // forever
  WebPIterator frame;
  ASSERT_TRUE(WebPDemuxGetFrame(demux, 1, &frame));
  int frames = 0;
  do {
    EXPECT_EQ(frame.duration, 50) << frame.frame_num;  // 1000 ms / 20
    ++frames;
  } while (WebPDemuxNextFrame(&frame));
  EXPECT_EQ(frames, 5);
  WebPDemuxReleaseIterator(&frame);
  WebPDemuxDelete(demux);
}

// A GIF's frames as giflib reads them: one palette for the whole animation
// (none of its own in any frame), looping, each frame's delay.
TEST_F(Motion, AGifHasOnePaletteForEveryFrame) {
  const CommandResult r = run("render " + flat_torus() + " --turntable 6 --fps 25 --size 70x50 -o " + path("spin.gif"));
  ASSERT_EQ(r.status, 0) << r.err;
  int error = 0;
  GifFileType* gif = DGifOpenFileName(path("spin.gif").c_str(), &error);
  ASSERT_NE(gif, nullptr) << GifErrorString(error);
  ASSERT_EQ(DGifSlurp(gif), GIF_OK) << GifErrorString(gif->Error);
  EXPECT_EQ(gif->SWidth, 70);
  EXPECT_EQ(gif->SHeight, 50);
  EXPECT_EQ(gif->ImageCount, 6);
  ASSERT_NE(gif->SColorMap, nullptr);
  EXPECT_EQ(gif->SColorMap->ColorCount, 256);
  for (int i = 0; i < gif->ImageCount; ++i) {
    SCOPED_TRACE(i);
    EXPECT_EQ(gif->SavedImages[i].ImageDesc.ColorMap, nullptr);
    GraphicsControlBlock control;
    ASSERT_EQ(DGifSavedExtensionToGCB(gif, i, &control), GIF_OK);
    EXPECT_EQ(control.DelayTime, 4);  // hundredths of a second: 100 / 25
  }
  DGifCloseFile(gif, &error);
}

// Views round the model, and the views a cameras file names, make an
// animation too: the camera going round under a light that holds still.
TEST_F(Motion, ViewsAndCamerasFilesMakeAnimationsToo) {
  const std::string torus = flat_torus();
  ASSERT_EQ(run("render " + torus + " --views 3 --size 40x30 -o " + path("views/")).status, 0);
  for (const std::string& source : {std::string("--views 3"), "--cameras " + path("views/transforms.json")}) {
    SCOPED_TRACE(source);
    const CommandResult r = run("render " + torus + " " + source + " --size 40x30 -o " + path("views.gif"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "wrote 3 views of " + torus + " (40x30) to " + path("views.gif") + ", a GIF\n");
    int error = 0;
    GifFileType* gif = DGifOpenFileName(path("views.gif").c_str(), &error);
    ASSERT_NE(gif, nullptr);
    ASSERT_EQ(DGifSlurp(gif), GIF_OK);
    EXPECT_EQ(gif->ImageCount, 3);
    DGifCloseFile(gif, &error);
  }
}

// A torus lying flat, 24 quads round: turned by 45 degrees a frame (3 of
// its quads) under a studio that holds still, every frame is the same
// picture, pixel for pixel. Turned by 360/7 degrees, which no symmetry of
// it matches, they differ: the model does turn.
TEST_F(Motion, ATorusLyingFlatLooksTheSameInEveryTurntableFrame) {
  const std::string torus = flat_torus();
  ASSERT_EQ(run("render " + torus + " --up +z --turntable 8 --size 96x72 -o " + path("eight/")).status, 0);
  const Image first = read_png(path("eight/000.png"));
  for (int i = 1; i < 8; ++i) EXPECT_TRUE(read_png(path("eight/00" + std::to_string(i) + ".png")).pixels == first.pixels) << i;
  ASSERT_EQ(run("render " + torus + " --up +z --turntable 7 --size 96x72 -o " + path("seven/")).status, 0);
  const Image seven = read_png(path("seven/000.png"));
  for (int i = 1; i < 7; ++i) EXPECT_FALSE(read_png(path("seven/00" + std::to_string(i) + ".png")).pixels == seven.pixels) << i;
  // transforms.json says what the frames turned through.
  EXPECT_EQ(json::parse(read(path("eight/transforms.json")))["umbra_turning"], "model");
}

// The light orbits a real scan while the camera and model hold still: the
// model's outline (its object pass) is the same in every frame, its shadow
// is not; each frame's light stands where turning the first by 90 degrees
// a frame puts it; and each frame's shadow mask is the exact shadow (the
// ray-cast reference's) and the very mask a still render draws with the
// light there.
TEST_F(Motion, AnOrbitingLightSweepsTheExactShadowOfAModelThatHoldsStill) {
  if (!fs::exists(kWuson)) GTEST_SKIP() << kWuson << " is missing (apt-get install assimp-testmodels)";
  const std::string options = " --size 96x72 --turntable 4 --orbit light";
  const CommandResult r = run("render " + kWuson + options + " --passes object,shadow -o " + path("out/"));
  ASSERT_EQ(r.status, 0) << r.err;
  const json all = json::parse(read(path("out/transforms.json")));
  EXPECT_EQ(all["umbra_turning"], "light");
  const Image outline = read_png(path("out/000.object.png")), shadow = read_png(path("out/000.shadow.png"));
  // The same run, in this process: the scene staged and each frame's shot, as the command made them.
  std::vector<std::string> words = {"--size", "96x72"};
  PictureChoices choices = parse_picture_choices(words);
  ViewSetRequest request;
  request.count = 4, request.turning = Turning::kLight;
  std::string messages;
  PreparedViews prepared = prepare_views(kWuson, choices, request, {}, {}, messages);
  ASSERT_EQ(prepared.shots.size(), 4u);
  const glm::dvec3 light = prepared.shots[0].lights.at(0);
  std::optional<HeadlessContext> context;
  for (int i = 0; i < 4; ++i) {
    SCOPED_TRACE(i);
    const std::string stem = "00" + std::to_string(i);
    EXPECT_TRUE(read_png(path("out/" + stem + ".object.png")).pixels == outline.pixels);
    const Image mask = read_png(path("out/" + stem + ".shadow.png"));
    if (i > 0) {
      EXPECT_FALSE(mask.pixels == shadow.pixels);
    }
    // Turned by 90 degrees i times about the z axis: (x, y) -> (-y, x).
    glm::dvec3 turned = light;
    for (int k = 0; k < i; ++k) turned = {-turned.y, turned.x, turned.z};
    const Shot& shot = prepared.shots[size_t(i)];
    EXPECT_LT(glm::length(shot.lights.at(0) - turned), 1e-12);
    EXPECT_EQ(shot.camera, prepared.shots[0].camera);
    // The umbra_camera the file keeps for it is that shot.
    const json& placed = all["frames"][size_t(i)]["umbra_camera"]["lights"][0];
    EXPECT_EQ(glm::dvec3(placed[0], placed[1], placed[2]), shot.lights[0]);
    Scene scene = prepared.scene;
    place_shot(scene, shot);
    const DrawnPicture still = draw_picture(scene, prepared.settings, {false, true, false}, context, HeadlessGl::kAuto);
    EXPECT_TRUE(still.mask->pixels == mask.pixels);
    const MaskComparison m = compare_with_reference(scene, make_render_plan(scene, prepared.settings), mask, 0);
    EXPECT_EQ(m.unexplained, 0) << m.first_unexplained;
    EXPECT_TRUE(within_boundary_bound(m)) << m.excused_boundary << " of " << m.boundary_pixels;
  }
}

// --cameras of a motion's transforms.json draws its frames again, byte for
// byte, staged for the same motion; and so does a scene's orbiting light.
TEST_F(Motion, CamerasOfATurntablesTransformsRedrawItsFramesByteForByte) {
  const std::string torus = std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj";
  for (const std::string orbit : {"model", "light"}) {
    SCOPED_TRACE(orbit);
    ASSERT_EQ(run("render " + torus + " --turntable 3 --orbit " + orbit + " --size 64x48 --passes shadow -o " + path(orbit + "-a/")).status,
              0);
    const CommandResult again =
        run("render " + torus + " --cameras " + path(orbit + "-a/transforms.json") + " --passes shadow -o " + path(orbit + "-b"));
    ASSERT_EQ(again.status, 0) << again.err;
    EXPECT_EQ(names_in(orbit + "-a"), names_in(orbit + "-b"));
    for (const std::string& name : names_in(orbit + "-a"))
      EXPECT_TRUE(read(path(orbit + "-a/" + name)) == read(path(orbit + "-b/" + name))) << name;
  }
}

// A scene's own camera turns with its lights, or its lights alone: the
// spec's orbiting light, saved.
TEST_F(Motion, ASceneTurnsItsOwnCameraAndLights) {
  const std::string scene = std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene";
  const CommandResult r = run("render " + scene + " --turntable 4 --orbit light --size 64x64 -o " + path("demo/"));
  ASSERT_EQ(r.status, 0) << r.err;
  const json all = json::parse(read(path("demo/transforms.json")));
  ASSERT_EQ(all["frames"].size(), 4u);
  EXPECT_EQ(all["frames"][0]["transform_matrix"], all["frames"][2]["transform_matrix"]);
  EXPECT_NE(all["frames"][0]["light_positions"], all["frames"][2]["light_positions"]);
  EXPECT_FALSE(read(path("demo/000.png")) == read(path("demo/002.png")));
}

// A folder's models each make one animation, in worker processes as a
// folder's pictures are made; --skip-existing passes over those newer
// than their files.
TEST_F(Motion, AFoldersModelsEachMakeOneAnimation) {
  fs::create_directories(path("in"));
  fs::copy_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj", path("in/torus.obj"));
  fs::copy_file(std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/icosphere.obj", path("in/icosphere.obj"));
  const std::string command = "render " + path("in") + " --turntable 3 --format gif --size 40x30 --json -o " + path("out");
  const CommandResult r = run(command);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("2 animations in " + path("out")), std::string::npos) << r.err;
  for (const std::string name : {"torus.obj.gif", "icosphere.obj.gif"}) {
    SCOPED_TRACE(name);
    EXPECT_NE(r.out.find("\"picture\":\"" + path("out/" + name) + "\",\"status\":\"drawn\""), std::string::npos) << r.out;
    int error = 0;
    GifFileType* gif = DGifOpenFileName(path("out/" + name).c_str(), &error);
    ASSERT_NE(gif, nullptr);
    ASSERT_EQ(DGifSlurp(gif), GIF_OK);
    EXPECT_EQ(gif->ImageCount, 3);
    DGifCloseFile(gif, &error);
  }
  const CommandResult again = run(command + " --skip-existing");
  EXPECT_EQ(again.status, 0);
  EXPECT_NE(again.err.find("2 up to date (--skip-existing)"), std::string::npos) << again.err;
  const CommandResult one = run("render " + path("in/torus.obj") + " --turntable 3 --format gif -o " + path("one"));
  EXPECT_EQ(one.status, 2);
  EXPECT_EQ(one.err, "umbra render: --format says which animation --turntable makes of each of several files; -o names one file's\n"
                     "(see umbra render --help)\n");
}

// Bad input: the exact message, exit 2 for a usage error and 1 for a file
// that cannot be written, and no file left behind.
TEST_F(Motion, BadRequestsAreRefusedSayingWhyAndLeaveNoFile) {
  const std::string torus = flat_torus();
  fs::create_directories(path("out"));
  const std::pair<std::string, std::string> usage[] = {
      {"--turntable 0 -o " + path("out/a.mp4"), "--turntable expects a whole number from 1 to 100000, got \"0\""},
      {"--turntable 4 -o " + path("out/a.avi"),
       "-o " + path("out/a.avi") + ": --turntable writes .mp4, .webp or .gif, or each frame's files into a folder (a name ending in /)"},
      {"--turntable 4 --orbit sun -o " + path("out/a.mp4"), "--orbit takes model or light, got \"sun\""},
      {"--orbit light -o " + path("out/a.png"), "--orbit says what --turntable turns: give --turntable N"},
      {"--fps 30 -o " + path("out/a.png"), "--fps is an animation's pace: name one with -o (.mp4, .webp or .gif)"},
      {"--turntable 4 --fps 0.5 -o " + path("out/a.mp4"), "--fps must be from 1 to 240 frames a second, got \"0.5\""},
      {"--turntable 4 --quality 80 -o " + path("out/a.gif"), "--quality is for a .jpg or .webp; a GIF takes none"},
      {"--turntable 4 --passes depth -o " + path("out/a.mp4"),
       "--passes writes each picture's data files, which an MP4 video (H.264) has no room for: name a folder"},
      {"--turntable 4 --background transparent -o " + path("out/a.mp4"),
       "--background transparent needs an alpha channel, which an MP4 video (H.264) has not: name a .webp"},
      {"--turntable 4 --size 65x48 -o " + path("out/a.mp4"),
       "an MP4 video's frames (yuv420p) have an even width and height; the picture is 65x48: give --size with even sides"},
      {"--turntable 4 --views 3 -o " + path("out/"),
       "--turntable draws a motion's frames; --views, --views-on and --cameras place views of their own: give one or the other"},
  };
  for (const auto& [options, message] : usage) {
    SCOPED_TRACE(options);
    const CommandResult r = run("render " + torus + " " + options);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "umbra render: " + message + "\n(see umbra render --help)\n");
  }
  EXPECT_TRUE(names_in("out").empty());
  // A folder that is not there: the encoder cannot write, nothing is left.
  const CommandResult r = run("render " + torus + " --turntable 2 --size 32x32 -o " + path("missing/a.webp"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(path("missing/a.webp") + ": cannot write the animation"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("missing")));
}

}  // namespace
}  // namespace umbra::test
