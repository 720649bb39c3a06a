// The command line as a user meets it: exit codes, exact messages, and no
// output file when anything is wrong.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <tuple>

#include "mesh/io/mesh_format.hpp"
#include "scene/scene_parser.hpp"
#include "image/image.hpp"
#include "reference/ray_cast.hpp"
#include "render/render_method.hpp"
#include "tests/tools/command_fixture.hpp"

namespace umbra {
namespace {

namespace fs = std::filesystem;
using test::CommandResult;

class RenderCommand : public test::CommandTest {};

TEST_F(RenderCommand, WritesImageAndMaskOfTheRequestedSize) {
  const CommandResult r = run("render " + std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene -o " + path("a.png") +
                    " --mask " + path("m.png") + " --size 64x48");
  EXPECT_EQ(r.status, 0) << r.err;
  const Image image = read_png(path("a.png"));
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 48);
  EXPECT_EQ(image.channels, 3);
  const Image mask = read_png(path("m.png"));
  EXPECT_EQ(mask.channels, 1);
  for (uint8_t v : mask.pixels) EXPECT_TRUE(v == kMaskLit || v == kMaskUnlit || v == kMaskNoSurface);
  EXPECT_EQ(r.out, "wrote " + path("a.png") + " (64x48) and mask " + path("m.png") + "\n");
}

TEST_F(RenderCommand, AMeshFileOnItsOwnIsStagedAndExplainPrintsTheSceneToSave) {
  const std::string mesh = write("tet", "v 0 0 0\nv 10 0 0\nv 0 10 0\nv 0 0 10\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const CommandResult r = run("render " + mesh + " -o " + path("a.png") + " --size 32x32 --explain");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::string header = "staged scene for " + mesh + " (--save-scene FILE saves it to render or edit):\n";
  ASSERT_EQ(r.out.substr(0, header.size()), header);
  const std::string text = r.out.substr(header.size(), r.out.find("\nrender plan for ") - header.size());
  EXPECT_NE(text.find("\nmesh \"tet\" fit rotate 1 0 0 90 smooth 30\n"), std::string::npos) << text;  // OBJ: +y up, turned to +z
  EXPECT_NE(r.out.find("render plan for " + mesh + " (staged)\n"), std::string::npos);
  EXPECT_EQ(read_png(path("a.png")).width, 32);
  // Saved beside the mesh, the text renders the same image, antialiased as
  // the staged render is by default (a scene file is not, unless asked).
  write("tet.scene", text);
  EXPECT_EQ(run("render " + path("tet.scene") + " -o " + path("b.png") + " --size 32x32 --antialias 3").status, 0);
  EXPECT_EQ(read_png(path("a.png")).pixels, read_png(path("b.png")).pixels);
  // Text that is no mesh is read as a scene, whose parser says why.
  const std::string neither = write("notes.txt", "hello\n");
  const CommandResult bad = run("render " + neither + " -o " + path("c.png"));
  EXPECT_EQ(bad.status, 1);
  EXPECT_EQ(bad.err, neither + ":1:1: unknown statement \"hello\" (expected light, material, sphere, triangle, mesh, camera, background, floor, "
                     "antialias, size, headlight, hemisphere or tone)\n");
}

// --up names the file's axis that points up; the staged scene turns it to +z.
TEST_F(RenderCommand, UpPicksTheAxisAMeshStandsOn) {
  const std::string mesh = write("tet.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 3\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const std::vector<std::pair<std::string, std::string>> turns = {
      {"+z", "mesh \"tet.obj\" fit smooth 30\n"},
      {"-z", "mesh \"tet.obj\" fit rotate 1 0 0 180 smooth 30\n"},
      {"+y", "mesh \"tet.obj\" fit rotate 1 0 0 90 smooth 30\n"},
      {"+x", "mesh \"tet.obj\" fit rotate 0 1 0 -90 smooth 30\n"}};
  for (const auto& [axis, statement] : turns) {
    const CommandResult r = run("render " + mesh + " -o " + path("a.png") + " --size 16x16 --explain --up " + axis);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("\n" + statement), std::string::npos) << axis << "\n" << r.out;
  }
  CommandResult r = run("render " + mesh + " -o " + path("a.png") + " --up +w");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--up must be +x, -x, +y, -y, +z or -z, got \"+w\""), std::string::npos) << r.err;
  r = run("render " + std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene -o " + path("a.png") + " --up +z");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra render: --up is for a mesh file on its own, which umbra stages; \"" + std::string(UMBRA_SOURCE_DIR) +
                       "/scenes/demo.scene\" is not one (a scene has its own camera and lights)\n(see umbra render --help)\n");
}

// The camera and light options place what umbra stages; each bad value, or
// two that contradict each other, is a usage error before any work.
TEST_F(RenderCommand, CameraAndLightOptionsAreCheckedBeforeAnyWork) {
  const std::string tet = write("t.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const std::string demo = std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {tet + " --camera-elevation 90", "--camera-elevation expects degrees from -89.9 to 89.9, got \"90\""},
      {tet + " --camera-zoom 0", "--camera-zoom expects a factor from 0.01 to 100, got \"0\""},
      {tet + " --camera-zoom 1e10", "--camera-zoom expects a factor from 0.01 to 100, got \"1e10\""},
      {tet + " --eye 3,3,3 --camera-zoom 2", "--camera-zoom scales the framing's distance, which --eye replaces: give one or the other"},
      {tet + " --fov 180", "--fov expects degrees from 1 to 170, got \"180\""},
      {tet + " --light-elevation -91", "--light-elevation expects degrees from -90 to 90, got \"-91\""},
      {tet + " --eye 1,2", "--eye expects X,Y,Z such as 0,-3,1.5, got \"1,2\""},
      {tet + " --target 1,2,3,4", "--target expects X,Y,Z such as 0,-3,1.5, got \"1,2,3,4\""},
      {tet + " --light 1,x,3", "--light expects a number, got \"x\""},
      {tet + " --light 1,2,3 --light-azimuth 10",
       "--light places the light outright; --light-azimuth and --light-elevation place it by angles: give one or the other"},
      {tet + " --eye 0,0,3 --target 0,0,0",
       "--eye is straight above or below --target: the staged camera keeps +z up, so it cannot look along it"},
      {demo + " --camera-azimuth 10",
       "--camera-azimuth is for a mesh file on its own, which umbra stages; \"" + demo +
           "\" is not one (a scene has its own camera and lights)"}};
  for (const auto& [arguments, message] : cases) {
    const CommandResult r = run("render " + arguments + " -o " + path("a.png"));
    EXPECT_EQ(r.status, 2) << arguments;
    EXPECT_EQ(r.err, "umbra render: " + message + "\n(see umbra render --help)\n") << arguments;
  }
  // An eye at the very point the framing looks at, or straight above it, is
  // known once the model is framed: said of the option all the same, never
  // of a line of the staged scene the user never wrote.
  const CommandResult staged = run("render " + tet + " --size 32x32 --explain -o " + path("framed.png"));
  ASSERT_EQ(staged.status, 0) << staged.err;
  const size_t at = staged.out.find(" target ") + 8;
  std::istringstream target(staged.out.substr(at, staged.out.find(" up ", at) - at));
  double x, y, z;
  target >> x >> y >> z;
  std::ostringstream eye, above;
  eye << x << "," << y << "," << z;
  above << x << "," << y << "," << z + 3;
  for (const auto& [given, said] : {std::pair{eye.str(), " is the point the staged camera looks at (the middle of the model and its "
                                                         "shadow): give --target as well, or put the eye elsewhere"},
                                    {above.str(), " is straight above or below the point the staged camera looks at, and the camera "
                                                  "keeps +z up: give --target as well, or move the eye sideways"}}) {
    const CommandResult r = run("render " + tet + " --size 32x32 --eye " + given + " -o " + path("a.png"));
    EXPECT_EQ(r.status, 2) << given;
    EXPECT_EQ(r.err, "umbra render: --eye " + given + said + "\n(see umbra render --help)\n");
  }
  EXPECT_FALSE(fs::exists(path("a.png")));
}

// The output's name says its format: PNG or JPEG, - for PNG on standard
// output; any other name is a usage error before any work, and a mask stays
// a PNG, as only a lossless format keeps it exact.
TEST_F(RenderCommand, TheOutputsNameSaysItsFormat) {
  const std::string demo = std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene";
  CommandResult r = run("render " + demo + " --size 40x30 -o " + path("a.jpg") + " --jpeg-quality 80");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read(path("a.jpg")).substr(0, 3), "\xff\xd8\xff");  // a JPEG's start of image
  EXPECT_EQ(run("render " + demo + " --size 40x30 -o " + path("b.JPEG")).status, 0);
  EXPECT_EQ(read(path("b.JPEG")).substr(0, 3), "\xff\xd8\xff");
  EXPECT_EQ(run("render " + demo + " --size 40x30 -o " + path("c.png")).status, 0);
  r = run("render " + demo + " --size 40x30 -o -");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, read(path("c.png")));  // standard output holds the PNG alone
  EXPECT_EQ(r.err, "wrote the picture to standard output (40x30)\n");
  const std::vector<std::pair<std::string, std::string>> refused = {
      {"-o " + path("d.webp"), "-o " + path("d.webp") + " names an animation, which --turntable N makes (or --views N); a picture is "
                                                       "a .png, .jpg or .jpeg file"},
      {"-o " + path("d.bmp"), "-o " + path("d.bmp") + ": umbra does not write .bmp pictures; name a .png, .jpg or .jpeg file, "
                                                     "or - for PNG on standard output"},
      {"-o " + path("d"), "-o " + path("d") + " has no extension; name a .png, .jpg or .jpeg file, or - for PNG on standard output"},
      {"-o " + path("d.png") + " --jpeg-quality 50",
       "--quality is for a JPEG picture, or a WebP animation (--turntable); -o " + path("d.png") + " is neither"},
      {"-o " + path("d.png") + " --quality 50",
       "--quality is for a JPEG picture, or a WebP animation (--turntable); -o " + path("d.png") + " is neither"},
      {"-o " + path("d.jpg") + " --jpeg-quality 101", "--jpeg-quality expects a whole number from 1 to 100, got \"101\""},
      {"-o " + path("d.png") + " --mask " + path("m.jpg"), "--mask writes a PNG file (a mask must stay exact), got \"" + path("m.jpg") + "\""},
      {"-o - --explain", "--explain prints to standard output, where -o - writes the picture: name a file with -o"}};
  for (const auto& [arguments, message] : refused) {
    r = run("render " + demo + " " + arguments);
    EXPECT_EQ(r.status, 2) << arguments;
    EXPECT_EQ(r.err, "umbra render: " + message + "\n(see umbra render --help)\n");
  }
  for (const char* never : {"d.webp", "d.bmp", "d", "d.png", "d.jpg", "m.jpg"}) EXPECT_FALSE(fs::exists(path(never))) << never;
}

// --floor, --color and --background change what they say and nothing else,
// and are written into the staged scene's text, which reads back as the
// same picture.
TEST_F(RenderCommand, FloorColorAndBackgroundOptions) {
  const std::string tet = write("t.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const std::string base = "render " + tet + " --size 48x48 --antialias 1 ";
  ASSERT_EQ(run(base + "-o " + path("plain.png")).status, 0);
  CommandResult r = run(base + "-o " + path("red.png") + " --color red --explain");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\nmaterial default ambient 1 0 0 diffuse 1 0 0\n"), std::string::npos) << r.out;
  const Image plain = read_png(path("plain.png")), red = read_png(path("red.png"));
  int redder = 0, changed = 0;
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 48; ++x) {
      changed += plain.at(x, y, 0) != red.at(x, y, 0) || plain.at(x, y, 1) != red.at(x, y, 1) || plain.at(x, y, 2) != red.at(x, y, 2);
      redder += red.at(x, y, 0) > red.at(x, y, 1) + 40;
    }
  EXPECT_GT(redder, 48 * 48 / 50) << "the model should turn red";
  EXPECT_EQ(changed, redder) << "only the model's pixels should change";
  // A model whose file colours every face keeps its colours.
  const std::string coloured = write("c.obj", "mtllib c.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nusemtl blue\n"
                                              "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  write("c.mtl", "newmtl blue\nKd 0.1 0.2 0.9\n");
  ASSERT_EQ(run("render " + coloured + " --size 48x48 --antialias 1 -o " + path("c1.png")).status, 0);
  ASSERT_EQ(run("render " + coloured + " --size 48x48 --antialias 1 -o " + path("c2.png") + " --color red").status, 0);
  EXPECT_EQ(read_png(path("c1.png")).pixels, read_png(path("c2.png")).pixels);
  // --plain draws it in --color alone, as the untextured model is drawn.
  r = run("render " + coloured + " --size 48x48 --antialias 1 -o " + path("c3.png") + " --color red --plain --explain");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\nmesh \"c.obj\" fit rotate 1 0 0 90 plain smooth 30\n"), std::string::npos) << r.out;
  EXPECT_EQ(read_png(path("c3.png")).pixels, read_png(path("red.png")).pixels);  // the same tetrahedron, red
  // Smooth across edges under --crease-angle (30 by default), or --flat.
  r = run(base + "-o " + path("s.png") + " --crease-angle 75 --explain");
  EXPECT_NE(r.out.find("\nmesh \"t.off\" fit rotate 1 0 0 90 smooth 75\n"), std::string::npos) << r.out;
  r = run(base + "-o " + path("s.png") + " --flat --explain");
  EXPECT_NE(r.out.find("\nmesh \"t.off\" fit rotate 1 0 0 90\n"), std::string::npos) << r.out;
  EXPECT_EQ(run(base + "-o " + path("s.png") + " --crease-angle 200").status, 2);
  // The floor: a colour, or none at all.
  r = run(base + "-o " + path("f.png") + " --floor '#ff8000' --explain");
  EXPECT_NE(r.out.find("\nmaterial floor ambient 1 0.501961 0 diffuse 1 0.501961 0\n"), std::string::npos) << r.out;
  r = run(base + "-o " + path("n.png") + " --floor none --background transparent --explain");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out.find("floor"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\nbackground transparent\n"), std::string::npos) << r.out;
  const Image alone = read_png(path("n.png"));
  EXPECT_EQ(alone.channels, 4);
  EXPECT_EQ(alone.at(0, 0, 3), 0);  // no floor: the corner sees nothing
  // A shadow catcher for a floor: said in the text; planar cannot keep its shadows.
  r = run(base + "-o " + path("s.png") + " --floor shadow-catcher --background transparent --explain");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\nmaterial floor shadow-catcher\nfloor "), std::string::npos) << r.out;
  r = run(base + "-o " + path("x.png") + " --floor shadow-catcher --method planar");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, tet + " (staged): material \"floor\" is a shadow catcher, whose shadows --method planar cannot keep (it marks "
                   "them in the stencil): use another method\n");
  // Mistakes: a colour that is none, a transparent JPEG, a floor for a scene.
  const std::string demo = std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene";
  r = run(base + "-o " + path("x.png") + " --background whte");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--background expects a colour, #rrggbb or a name (black, "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("got \"whte\" (did you mean white?)"), std::string::npos) << r.err;
  r = run(base + "-o " + path("x.jpg") + " --background transparent");
  EXPECT_EQ(r.err, "umbra render: --background transparent needs an alpha channel, which a JPEG picture has not: name a "
                   ".png\n(see umbra render --help)\n");
  EXPECT_EQ(run("render " + demo + " -o " + path("x.png") + " --floor red").status, 2);
  // A scene takes --background, in place of its own.
  ASSERT_EQ(run("render " + demo + " --size 32x32 -o " + path("d.png") + " --background transparent").status, 0);
  EXPECT_EQ(read_png(path("d.png")).channels, 4);
  EXPECT_FALSE(fs::exists(path("x.png")));
  EXPECT_FALSE(fs::exists(path("x.jpg")));
}

// --save-scene writes the staged scene, every option's part in it, naming
// the mesh from the saved file's folder: rendered from another folder, with
// no option but the size, it draws the same picture byte for byte, for
// every bundled mesh and every staging option.
TEST_F(RenderCommand, ASavedSceneDrawsTheSamePictureFromAnyFolder) {
  fs::create_directories(path("saved/deeper"));
  fs::create_directories(path("elsewhere"));
  const std::vector<std::string> options = {
      "",
      "--camera-azimuth 120 --camera-elevation 10 --camera-zoom 1.3 --fov 40",
      "--light-azimuth 80 --light-elevation 25 --up +z",
      "--light 1,-2,3 --eye 2,-3,2 --target 0,0,0.2",
      "--floor '#405060' --color orange --background white",
      "--floor none --background transparent",
      "--light-angle 150 --antialias 2",
      "--antialias 1",
      "--antialias-all"};
  int case_number = 0;
  for (const char* mesh : {"icosphere.obj", "open_box.obj", "pair.off", "torus.obj"})
    for (const std::string& option : options) {
      const std::string n = std::to_string(case_number++);
      SCOPED_TRACE(std::string(mesh) + " " + option);
      const std::string source = std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/" + mesh;
      const std::string scene = path("saved/deeper/" + n + ".scene");
      CommandResult r = run("render " + source + " --size 40x32 " + option + " -o " + path(n + ".png") + " --save-scene " + scene);
      ASSERT_EQ(r.status, 0) << r.err;
      EXPECT_EQ(r.out, "wrote " + path(n + ".png") + " (40x32), and saved its scene to " + scene + "\n");
      // With no options at all: the saved scene holds the size and the samples.
      r = run("render " + scene + " -o " + path("elsewhere/" + n + ".png"), "cd " + path("elsewhere") + " && ");
      ASSERT_EQ(r.status, 0) << r.err;
      EXPECT_EQ(read(path(n + ".png")), read(path("elsewhere/" + n + ".png")));
    }
  // Only a mesh file on its own has a staged scene to save.
  const std::string demo = std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene";
  CommandResult r = run("render " + demo + " -o " + path("d.png") + " --save-scene " + path("d.scene"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra render: --save-scene is for a mesh file on its own, which umbra stages; \"" + demo +
                       "\" is not one (a scene has its own camera and lights)\n(see umbra render --help)\n");
  EXPECT_FALSE(fs::exists(path("d.scene")));
}

// "-" reads the mesh from standard input, its format found by its content:
// the same picture as the file's, to a file or to standard output; check
// reads it too. An empty standard input says so.
TEST_F(RenderCommand, AMeshReadFromStandardInputIsTheFilesPicture) {
  const std::string pair = std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/pair.off";
  ASSERT_EQ(run("render " + pair + " --size 40x30 -o " + path("file.png")).status, 0);
  CommandResult r = run("render - --size 40x30 -o " + path("piped.png"), "cat " + pair + " | ");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read(path("file.png")), read(path("piped.png")));
  r = run("render - --size 40x30 -o -", "cat " + pair + " | ");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.out, read(path("file.png")));
  r = run("check - --json", "cat " + pair + " | ");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("\"format\":\"OFF\""), std::string::npos) << r.out;
  r = run("render - -o " + path("empty.png") + " < /dev/null");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "-: standard input is empty: pipe a file in, as in umbra render - -o out.png < model.stl\n");
  EXPECT_EQ(run("render - " + pair + " -o " + path("out")).err,
            "umbra render: - (standard input) is one file: render it on its own\n(see umbra render --help)\n");
  EXPECT_FALSE(fs::exists(path("empty.png")));
}

// Standard input's copy: its start is looked at before the rest is read, so
// that an endless stream of zeros (no scene, and no binary STL past the
// size its count allows) is refused at once, not copied until the disk is
// full; and the copy, in a folder of its own, goes however umbra is stopped.
TEST_F(RenderCommand, StandardInputIsLookedAtFirstAndItsCopyNeverLeftBehind) {
  fs::create_directories(path("tmp"));
  const std::string tmp = "TMPDIR=" + path("tmp") + " ";
  CommandResult r = run("render - -o " + path("zeros.png"), "cat /dev/zero | " + tmp + "timeout 60 ");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_NE(r.err.find("/standard-input: neither a scene nor a mesh file (" + mesh_format_names() + "): binary data\n"),
            std::string::npos)
      << r.err;
  r = run("check -", "cat /dev/zero | " + tmp + "timeout 60 ");
  EXPECT_EQ(r.status, 2) << r.err;
  for (const char* signal : {"TERM", "INT", "HUP"}) {
    // umbra waits on a FIFO that the shell itself holds open, with a line written.
    const std::string fifo = path(std::string("in-") + signal);
    const std::string script = "mkfifo " + fifo + "; " + tmp + std::string(UMBRA_EXECUTABLE) + " render - -o " + path("never.png") +
                               " < " + fifo + " & pid=$!; exec 3>" + fifo + "; echo OFF >&3; for i in $(seq 300); do ls " +
                               path("tmp") + " | grep -q umbra-stdin && break; sleep 0.1; done; sleep 0.2; kill -" + signal +
                               " $pid; wait $pid";
    r = run("-c " + shell_quoted(script), "", "bash");
    EXPECT_NE(r.status, 0) << signal;
    EXPECT_TRUE(fs::is_empty(path("tmp"))) << signal << ": the copy of standard input was left in TMPDIR";
  }
  EXPECT_FALSE(fs::exists(path("never.png")));
}

// A file that cannot be opened says why, and is not called a scene unless
// it is named as one.
TEST_F(RenderCommand, AMissingFileSaysWhy) {
  CommandResult r = run("render " + path("nothere.obj") + " -o " + path("a.png"));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, path("nothere.obj") + ": cannot open: No such file or directory\n");
  r = run("render " + path("nothere.scene") + " -o " + path("a.png"));
  EXPECT_EQ(r.err, path("nothere.scene") + ": cannot open the scene file: No such file or directory\n");
}

TEST_F(RenderCommand, AFileThatIsPlainlyNeitherASceneNorAMeshExitsWithTwo) {
  const std::string formats = "(" + mesh_format_names() + ")";
  const std::string jpeg = write("photo.jpg", std::string("\xff\xd8\xff\xe0\0\x10JFIF\0", 11));
  CommandResult r = run("render " + jpeg + " -o " + path("a.png"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, jpeg + ": neither a scene nor a mesh file " + formats + ": a JPEG image\n");
  const std::string xml = write("model.xml", "<?xml version=\"1.0\"?>\n<COLLADA></COLLADA>\n");
  r = run("render " + xml + " -o " + path("a.png"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, xml + ": neither a scene nor a mesh file " + formats + ": an XML document\n");
  // Named .dae, it is Collada, Assimp's: its importer says why it reads nothing.
  const std::string dae = write("model.dae", "<?xml version=\"1.0\"?>\n<COLLADA></COLLADA>\n");
  r = run("render " + dae + " -o " + path("a.png"));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err.substr(0, r.err.find(": ", dae.size() + 2)), dae + ": Assimp's Collada Importer cannot read it");
  const std::string binary = write("data.bin", std::string("\x01\x02\0\x03", 4));
  r = run("render " + binary + " -o " + path("a.png"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, binary + ": neither a scene nor a mesh file " + formats + ": binary data\n");
  EXPECT_FALSE(fs::exists(path("a.png")));
}

// An empty file (or one of blank lines) is said to be so, by render and
// check alike, not read as a scene without a light; an OBJ that opens with
// more than 64 KiB of comments is an OBJ all the same.
TEST_F(RenderCommand, AnEmptyFileIsSaidToBeAndCommentsFirstStillMakeAnObj) {
  for (const auto& [name, bytes, said] : {std::tuple{"empty.obj", "", "the file is empty"}, {"empty.stl", "", "the file is empty"},
                                         {"empty.scene", "", "the file is empty"},
                                         {"blank.obj", "\n \r\n\t\n", "the file holds only blank lines"}}) {
    const std::string file = write(name, bytes);
    CommandResult r = run("render " + file + " -o " + path("a.png"));
    EXPECT_EQ(r.status, 2) << name;
    EXPECT_EQ(r.err, file + ": " + said + "\n");
    r = run("check --brief " + file);
    EXPECT_EQ(r.status, 2) << name;
    EXPECT_EQ(r.out + r.err, file + ": " + said + "\n");
  }
  EXPECT_FALSE(fs::exists(path("a.png")));
  std::string comments;
  for (int line = 0; comments.size() < (1 << 17); ++line) comments += "# exported by a tool that says a lot, line " + std::to_string(line) + "\n";
  const std::string obj = write("commented.obj", comments + "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 1 4 3\n");
  const CommandResult r = run("render " + obj + " --size 16x16 -o " + path("a.png"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(run("check " + obj).status, 0);
}

TEST_F(RenderCommand, AMeshFileWithNoFacesExitsWithOneAndWritesNothing) {
  const std::string points = write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  CommandResult r = run("render " + points + " -o " + path("a.png"));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, points + ": has no faces with area to fit\n");
  // Corners on one line, each face distinct: no area either, said alike.
  const std::string collinear = write("collinear.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf 1 2 3\nf 2 3 4\n");
  r = run("render " + collinear + " -o " + path("a.png"));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, collinear + ": has no faces with area to fit\n");
  const std::string lines = write("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\n");
  r = run("render " + lines + " -o " + path("a.png"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(lines + ": "), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("a.png")));
}

TEST_F(RenderCommand, SceneErrorIsLocatedAndWritesNothing) {
  const std::string scene = write("bad.scene", "light 0 0 2\nsphere 0 0 0 O.5\n");
  const CommandResult r = run("render " + scene + " -o " + path("a.png") + " --mask " + path("m.png"));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, scene + ":2:14: expected a number for the sphere radius, got \"O.5\"\n");
  EXPECT_FALSE(fs::exists(path("a.png")));
  EXPECT_FALSE(fs::exists(path("m.png")));
}

TEST_F(RenderCommand, LightInsideASphereIsAnErrorAtTheSphere) {
  const std::string scene = write("inside.scene", "light 0 0 1.5\nsphere 0 0 1.2 0.5\n");
  const CommandResult r = run("render " + scene + " -o " + path("a.png"));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, scene + ":2:1: warning: sphere reaches outside the cube [-1,1]^3 that scenes are made for\n" +
                       scene + ":2:1: light 1 (line 1) is inside or on this sphere, which then has no shadow volume; "
                           "move the light outside the sphere\n");
  EXPECT_FALSE(fs::exists(path("a.png")));
}

TEST_F(RenderCommand, LightRotatedIntoASphereIsAnError) {
  const std::string scene = write("rot.scene", "light 1 0 2\nsphere -1 0 2 0.5\n");
  EXPECT_EQ(run("render " + scene + " -o " + path("a.png")).status, 0);
  const CommandResult r = run("render " + scene + " -o " + path("b.png") + " --light-angle 180");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(scene + ":2:1: light 1 (line 1) is inside or on this sphere"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("b.png")));
}

TEST_F(RenderCommand, UnwritableOutputLeavesNoFile) {
  const CommandResult r = run("render " + std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene --size 32x32 -o " +
                    path("no/such/dir/a.png"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(path("no/such/dir/a.png") + ": cannot write the image"), std::string::npos) << r.err;
}

// A shadow catcher over an opaque background is its transparent picture
// composited over that colour: the staged look's tone curve once took the
// catcher's darkened floor for the background, and the shadow was lost.
TEST_F(RenderCommand, AShadowCatcherOverAColourIsItsTransparentPictureOverIt) {
  const std::string torus = std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj";
  const glm::dvec3 colour(0xc0 / 255.0, 0x80 / 255.0, 0x40 / 255.0);
  for (const std::string method : {"auto", "raycast"}) {
    SCOPED_TRACE(method);
    const std::string base = "render " + torus + " --size 64x64 --floor shadow-catcher --method " + method;
    ASSERT_EQ(run(base + " --background transparent -o " + path("t.png")).status, 0);
    ASSERT_EQ(run(base + " --background '#c08040' -o " + path("o.png")).status, 0);
    const Image transparent = read_png(path("t.png")), opaque = read_png(path("o.png"));
    ASSERT_EQ(transparent.channels, 4);
    ASSERT_EQ(opaque.channels, 3);
    int shadow = 0;
    for (int y = 0; y < 64; ++y)
      for (int x = 0; x < 64; ++x) {
        const double alpha = transparent.at(x, y, 3) / 255.0;
        for (int c = 0; c < 3; ++c)
          EXPECT_NEAR(opaque.at(x, y, c), 255.0 * (transparent.at(x, y, c) / 255.0 * alpha + colour[c] * (1.0 - alpha)), 0.5)
              << x << ", " << y;
        // The floor's shadow: black in the transparent picture, the colour darkened in the opaque one.
        shadow += transparent.at(x, y, 0) == 0 && alpha > 0.2 && opaque.at(x, y, 0) < 0.8 * 0xc0;
      }
    EXPECT_GT(shadow, 100);
  }
}

// Every output is made before anything is drawn: one that cannot be written
// stops the run at once and leaves the files that were there as they were
// (a failing --mask once deleted the picture that -o named from an earlier
// run).
TEST_F(RenderCommand, AnOutputThatCannotBeWrittenLeavesEveryFileAsItWas) {
  const std::string tet = write("tet.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const std::string keep = write("keep.png", "an earlier picture"), mask = write("keep-mask.png", "an earlier mask");
  for (const std::string& options : {" --mask " + path("missing/m.png"), " --mask " + mask + " --save-scene " + path("missing/s.scene")}) {
    const CommandResult r = run("render " + tet + " --size 16x16 -o " + keep + options);
    EXPECT_EQ(r.status, 1) << options;
    EXPECT_NE(r.err.find(path("missing/")), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(": cannot write the "), std::string::npos) << r.err;
    EXPECT_EQ(read(keep), "an earlier picture") << options;
    EXPECT_EQ(read(mask), "an earlier mask") << options;
    EXPECT_FALSE(fs::exists(path("missing")));
    size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(path(""))) ++files;
    EXPECT_EQ(files, 5u) << "tet.off, keep.png, keep-mask.png, out.txt and err.txt, and no temporary file";
  }
}

// A picture written to standard output, by "-" or by the name of the file
// it goes to, stands alone there: the words go to stderr. Binary bytes are
// not written to a terminal.
TEST_F(RenderCommand, APictureOnStandardOutputStandsAloneThere) {
  const std::string tet = write("tet.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  // Through a pipe, as a user pipes it on: /dev/stdout then names no file.
  const auto piped = [&](const std::string& args) {
    return run("-o pipefail -c " + shell_quoted(std::string(UMBRA_EXECUTABLE) + " " + args + " | cat"), "", "bash");
  };
  for (const std::string output : {"-", "/dev/stdout"}) {
    CommandResult r = piped("render " + tet + " --size 16x16 -o " + output);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.substr(0, 8), "\x89PNG\r\n\x1a\n") << output;
    EXPECT_EQ(r.out.find("wrote"), std::string::npos) << output;
    EXPECT_NE(r.err.find("wrote "), std::string::npos) << r.err;
    r = piped("render " + tet + " --size 16x16 --explain -o " + output);
    EXPECT_EQ(r.status, 2) << output;
    EXPECT_EQ(r.err, "umbra render: --explain prints to standard output, where -o " + output +
                         " writes the picture: name a file with -o\n(see umbra render --help)\n");
  }
  if (std::system("script --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "no script(1) to give umbra a terminal";
  const CommandResult r = run("-qec " + shell_quoted(std::string(UMBRA_EXECUTABLE) + " render " + tet + " --size 16x16 -o -") +
                              " /dev/null", "", "script");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("umbra render: -o - writes the picture's bytes to standard output, which is a terminal here: redirect it "
                       "(> out.png) or name a file"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("PNG"), std::string::npos);
}

TEST_F(RenderCommand, UsageErrorsExitWithTwo) {
  const std::string demo = std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene";
  CommandResult r = run("render " + demo);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra render: no output image given (-o OUT.png)\n(see umbra render --help)\n");
  r = run("render " + demo + " -o x.png --size 10by10");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra render: --size expects WIDTHxHEIGHT such as 800x600, got \"10by10\"\n(see umbra render --help)\n");
  r = run("render " + demo + " -o x.png --segments 2");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra render: --segments expects a whole number from 3 to 4096, got \"2\"\n(see umbra render --help)\n");
  r = run("render " + demo + " -o x.png --light-angle nan");
  EXPECT_EQ(r.status, 2);
  r = run("render " + demo + " -o x.png --frobnicate");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra render: unknown option --frobnicate\n(see umbra render --help)\n");
  r = run("explode");
  EXPECT_EQ(r.status, 2);
}

// A frame past the GL's limit once supersampled is refused before any work,
// naming the supersampled size (a scene's spheres take samples at every pixel).
TEST_F(RenderCommand, AFrameTooLargeOnceSupersampledIsAUsageError) {
  const std::string demo = std::string(UMBRA_SOURCE_DIR) + "/scenes/demo.scene";
  CommandResult r = run("render " + demo + " -o " + path("x.png") + " --size 5000x5000 --antialias 4");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra render: --size 5000x5000 at 4 x 4 samples (--antialias 4) is a frame of 20000x20000, more than the "
                   "16384 along a side umbra draws: make --size or --antialias smaller\n(see umbra render --help)\n");
  const std::string tet = write("t.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  r = run("render " + tet + " -o " + path("x.png") + " --size 6000x100 --antialias-all");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("is a frame of 18000x300, more than the 16384"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("x.png")));
  // At edges alone, the GL's frame is the picture's size, and the rays need no frame.
  r = run("render " + tet + " -o " + path("x.png") + " --size 6000x100");
  EXPECT_EQ(r.status, 0) << r.err;
}

TEST_F(RenderCommand, HelpListsEveryOption) {
  const CommandResult r = run("render --help");
  EXPECT_EQ(r.status, 0);
  for (const char* option : {"-o", "--size", "--light-angle", "--segments", "--show-volumes", "--mask", "--explain"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
  EXPECT_EQ(run("--help").status, 0);
}

TEST_F(RenderCommand, ExplainPrintsThePlan) {
  const CommandResult r = run("render " + std::string(UMBRA_SOURCE_DIR) + "/scenes/two_spheres.scene --size 32x32 --segments 12 --method zfail --explain -o " +
                    path("a.png"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("camera: eye (0, 0, 3.4) target (0, 0, 0) up (0, 1, 0) fovy 45 deg (the default view)"),
            std::string::npos) << r.out;
  EXPECT_NE(r.out.find("method: zfail;"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("shadows: z-fail with caps (--method zfail)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sphere (line 7): tangent-circle 12-gon, 12 quads + 24 cap triangles"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("triangle (line 5): three side quads, 3 quads + 2 cap triangles"), std::string::npos);
}

TEST_F(RenderCommand, ExplainSaysWhichVolumeKindEachMeshGotAndWhy) {
  const CommandResult r = run("render " + std::string(UMBRA_SOURCE_DIR) + "/scenes/mesh_open_box.scene --size 32x32 --method zfail --explain -o " +
                              path("a.png"));
  EXPECT_EQ(r.status, 0) << r.err;
  // The open box, lit from above and outside its +y wall: the light sees the
  // inside of the bottom and of three walls, and the outside of the +y wall.
  // Once each face is oriented toward the light, the 4 rim edges have one
  // face (m = 1), the +y wall's bottom edge and its two corner edges have
  // two faces running the same way (m = 2, drawn twice), every other edge
  // two faces running opposite ways (m = 0): 4 + 3 * 2 = 10 quads, and both
  // caps of all 10 faces.
  EXPECT_NE(r.out.find("mesh (line 9): open, 1 hole: edge-multiplicity volume (10 triangles), 10 quads + 20 cap triangles "
                       "(static vertices, indices per frame)\n"),
            std::string::npos)
      << r.out;
  // The pair of closed pieces: 9 silhouette edges, the 7 faces turned away in each cap.
  EXPECT_NE(r.out.find("mesh (line 10): closed 2-manifold: silhouette volume (16 triangles), 9 quads + 14 cap triangles "
                       "(static vertices, indices per frame)\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.err.find("mesh_open_box.scene:9:1: warning: mesh \"meshes/open_box.obj\" is open, 1 hole: "
                       "edge-multiplicity volume\n"),
            std::string::npos)
      << r.err;
}

TEST_F(RenderCommand, AutoExplainsEachLightsCountAndDropsTheCaps) {
  const CommandResult r = run("render " + std::string(UMBRA_SOURCE_DIR) +
                              "/scenes/two_spheres.scene --size 32x32 --segments 12 --explain -o " + path("a.png"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("method: auto;"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("shadows: z-pass without caps: the near plane is outside every volume"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sphere (line 7): tangent-circle 12-gon, 12 quads\n"), std::string::npos) << r.out;
  const CommandResult in_shadow = run("render " + std::string(UMBRA_SOURCE_DIR) +
                                      "/scenes/camera_in_shadow.scene --size 32x32 --explain -o " + path("b.png"));
  EXPECT_NE(in_shadow.out.find("shadows: z-fail with caps: the caster at line 9 may shadow the near plane"),
            std::string::npos)
      << in_shadow.out;
}

TEST_F(RenderCommand, RaycastWritesTheReferenceImageAndMask) {
  const std::string scene = std::string(UMBRA_SOURCE_DIR) + "/scenes/two_spheres.scene";
  const CommandResult r = run("render " + scene + " --size 40x30 --method raycast -o " + path("r.png") + " --mask " + path("m.png"));
  ASSERT_EQ(r.status, 0) << r.err;
  const Image mask = read_png(path("m.png"));
  const Scene parsed = parse_scene_file(scene);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) ASSERT_EQ(mask.at(x, y), reference_mask_value(parsed, 40, 30, x, y, 0)) << x << ", " << y;
  EXPECT_EQ(read_png(path("r.png")).width, 40);
}

TEST_F(RenderCommand, UnknownMethodAndVolumesWithoutVolumesAreUsageErrors) {
  const std::string scene = std::string(UMBRA_SOURCE_DIR) + "/scenes/two_spheres.scene";
  const CommandResult bad = run("render " + scene + " --method zbuffer -o " + path("a.png"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.err.find("--method expects one of " + method_names() + ", got \"zbuffer\""), std::string::npos) << bad.err;
  const CommandResult shown = run("render " + scene + " --method raycast --show-volumes -o " + path("a.png"));
  EXPECT_EQ(shown.status, 2);
  EXPECT_NE(shown.err.find("--show-volumes needs shadow volumes; --method raycast has none"), std::string::npos) << shown.err;
  EXPECT_FALSE(std::filesystem::exists(path("a.png")));
}

// A folder of models: one picture each, at its path in the folder, the
// JPEG named like a mesh passed over, the broken file reported while the
// rest are drawn.
TEST_F(RenderCommand, AFolderRendersToOnePicturePerMeshAndShardsWriteTheSameSet) {
  fs::create_directories(path("models/parts"));
  const std::string tet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  write("models/tet.obj", tet);
  write("models/parts/tet.obj", tet);
  write("models/parts/box.off", "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                                "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
  write("models/parts/photo.obj", std::string("\xff\xd8\xff\xe0", 4));
  write("models/parts/broken.obj", "v 0 0 0\nf 1 2 3\n");
  const CommandResult r = run("render " + path("models") + " -o " + path("out") + " --size 120x90 --jobs 2 --sheet " + path("sheet.png"));
  EXPECT_EQ(r.status, 1) << r.err;  // broken.obj failed
  const std::vector<std::string> pictures = {"parts/box.off.png", "parts/tet.obj.png", "tet.obj.png"};
  std::vector<std::string> written;
  for (const auto& entry : fs::recursive_directory_iterator(path("out")))
    if (entry.is_regular_file()) written.push_back(entry.path().lexically_relative(path("out")).string());
  std::sort(written.begin(), written.end());
  EXPECT_EQ(written, pictures);
  EXPECT_EQ(read_png(path("out/tet.obj.png")).width, 120);
  EXPECT_NE(r.err.find("umbra render: passed over " + path("models/parts/photo.obj") + ": a JPEG image, not a mesh\n"),
            std::string::npos) << r.err;
  EXPECT_NE(r.err.find(path("models/parts/broken.obj") + ":2:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("umbra render: 4 files in "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(": 3 pictures in " + path("out") + ", 1 failed; 1 file passed over\n"), std::string::npos) << r.err;
  // The contact sheet: every file in file order, two to a row, each tile 6
  // pixels in from its cell, with a dark label line below it; the file that
  // failed a pale red tile that says so, in dark red.
  const Image sheet = read_png(path("sheet.png"));
  ASSERT_EQ(sheet.width, 2 * (120 + 12));
  ASSERT_EQ(sheet.height, 2 * (90 + 24 + 12));
  const std::vector<std::string> tiles = {"parts/box.off.png", "", "parts/tet.obj.png", "tet.obj.png"};  // broken.obj failed
  for (size_t k = 0; k < tiles.size(); ++k) {
    const int x0 = int(k % 2) * 132 + 6, y0 = int(k / 2) * 126 + 6;
    int differing = 0, ink = 0, pale = 0, red_ink = 0;
    const bool drawn = !tiles[k].empty();
    const Image picture = drawn ? read_png(path("out/" + tiles[k])) : Image();
    for (int y = 0; y < 90; ++y)
      for (int x = 0; x < 120; ++x) {
        if (drawn)
          for (int c = 0; c < 3; ++c) differing += sheet.at(x0 + x, y0 + y, c) != picture.at(x, y, c);
        pale += sheet.at(x0 + x, y0 + y, 0) > 240 && sheet.at(x0 + x, y0 + y, 1) < 230;
        red_ink += sheet.at(x0 + x, y0 + y, 0) > 120 && sheet.at(x0 + x, y0 + y, 1) < 40;
      }
    for (int y = y0 + 90; y < y0 + 90 + 24; ++y)
      for (int x = x0; x < x0 + 120; ++x) ink += sheet.at(x, y, 0) < 100;
    EXPECT_EQ(differing, 0) << tiles[k];
    EXPECT_GT(ink, 10) << tiles[k] << ": no label";
    if (!drawn) {
      EXPECT_GT(pale, 120 * 90 / 2) << "the failed file's tile is not pale red";
      EXPECT_GT(red_ink, 20) << "the failed file's tile does not say so";
    }
  }
  EXPECT_NE(r.err.find("umbra render: wrote the contact sheet " + path("sheet.png") + " (3 pictures, 1 failed)\n"), std::string::npos)
      << r.err;
  // Two shards write the same pictures as the one run, byte for byte.
  for (const char* shard : {"0/2", "1/2"})
    run("render " + path("models") + " -o " + path("sharded") + " --size 120x90 --shard " + shard);
  for (const std::string& picture : pictures)
    EXPECT_EQ(read(path("sharded/" + picture)), read(path("out/" + picture))) << picture;
  EXPECT_FALSE(fs::exists(path("sharded/parts/broken.obj.png")));
}

TEST_F(RenderCommand, SeveralFilesTakeAnOutputFolderAndNoSingleSceneOptions) {
  const std::string a = write("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string b = write("b.obj", "v 0 0 0\nv 1 0 0\nv 0 0 1\nf 1 2 3\n");
  CommandResult r = run("render " + a + " " + b + " -o " + path("out") + " --size 16x16");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("out/a.obj.png")));
  EXPECT_TRUE(fs::exists(path("out/b.obj.png")));
  r = run("render " + a + " " + b + " -o " + path("out") + " --mask " + path("m.png"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--mask writes one scene's mask; with several files there is none to choose"), std::string::npos) << r.err;
  r = run("render " + a + " -o " + path("one.png") + " --shard 0/2");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--shard splits several files; \"" + a + "\" is one"), std::string::npos) << r.err;
}


// Two inputs that would make one picture name each keep their own picture,
// named by as many of their folders as tell them apart, decided before
// anything is drawn; shards name alike.
TEST_F(RenderCommand, InputsThatShareAPictureNameKeepEveryPicture) {
  fs::create_directories(path("a")), fs::create_directories(path("b"));
  const std::string tet = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  write("a/x.obj", tet);
  write("b/x.obj", "v 0 0 0\nv 2 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  CommandResult r = run("render " + path("a/x.obj") + " " + path("b/x.obj") + " -o " + path("out") + " --size 40x30 --jobs 2");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find(": 2 pictures in "), std::string::npos) << r.err;
  ASSERT_TRUE(fs::exists(path("out/a/x.obj.png")) && fs::exists(path("out/b/x.obj.png")));
  EXPECT_NE(read(path("out/a/x.obj.png")), read(path("out/b/x.obj.png")));
  // The folders a and b, each holding x.obj; and one file named twice.
  r = run("render " + path("a") + " " + path("b") + " -o " + path("folders") + " --size 40x30");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read(path("folders/a/x.obj.png")), read(path("out/a/x.obj.png")));
  EXPECT_EQ(read(path("folders/b/x.obj.png")), read(path("out/b/x.obj.png")));
  r = run("render " + path("a/x.obj") + " " + path("a/x.obj") + " -o " + path("twice") + " --size 40x30 --shard 1/2");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("twice/x.obj (2).png")));
}

// A file that drew in an earlier run and fails now is not on this run's
// sheet: its tile says it failed.
TEST_F(RenderCommand, TheSheetShowsThisRunsPicturesOnly) {
  fs::create_directories(path("models"));
  write("models/t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  CommandResult r = run("render " + path("models") + " -o " + path("out") + " --size 40x30 --sheet " + path("sheet.png"));
  ASSERT_EQ(r.status, 0) << r.err;
  write("models/t.obj", "v 0 0 0\nf 1 2 3\n");
  r = run("render " + path("models") + " -o " + path("out") + " --size 40x30 --sheet " + path("sheet.png"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("umbra render: wrote the contact sheet " + path("sheet.png") + " (0 pictures, 1 failed)"), std::string::npos)
      << r.err;
}

// The contact sheet is written last, over whatever its name names: an input
// mesh or one of the run's own pictures was once overwritten, exit 0.
TEST_F(RenderCommand, TheSheetTakesThePlaceOfNoInputAndNoPicture) {
  fs::create_directories(path("models"));
  const std::string mesh = write("models/t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  // A mesh under a picture's name is read by its content, and is an input all the same.
  const std::string odd = write("models/odd.png", read(mesh));
  CommandResult r = run("render " + mesh + " " + odd + " -o " + path("out") + " --size 16x16 --sheet " + odd);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra render: --sheet would overwrite its input \"" + odd + "\"; name another file\n(see umbra render --help)\n");
  EXPECT_EQ(read(odd), read(mesh));
  r = run("render " + path("models") + " -o " + path("out") + " --size 16x16 --sheet " + path("out/../out/t.obj.png"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra render: --sheet " + path("out/../out/t.obj.png") + " is where the picture of \"" + mesh +
                       "\" goes; name another file\n(see umbra render --help)\n");
  EXPECT_FALSE(fs::exists(path("out")));
  r = run("render " + path("models") + " -o " + path("out") + " --size 16x16 --sheet " + path("sheet.gif"));
  EXPECT_EQ(r.status, 2);
  r = run("render " + path("models") + " -o " + path("out") + " --size 16x16 --sheet " + path("sheet.jpg"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read(path("sheet.jpg")).substr(0, 3), "\xff\xd8\xff");  // a JPEG, as its name says
}

// Outputs that would overwrite an input or cannot be a folder are usage
// errors, said before anything is drawn.
TEST_F(RenderCommand, AnOutputThatWouldOverwriteAnInputOrIsNoFolderIsRefused) {
  const std::string tet = write("tet.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const std::string before = read(tet);
  CommandResult r = run("render " + tet + " -o " + tet);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra render: -o would overwrite its input \"" + tet + "\"; name another file\n(see umbra render --help)\n");
  r = run("render " + tet + " -o " + path("./tet.off"));
  EXPECT_EQ(r.status, 2);
  const std::string scene = std::string(UMBRA_SOURCE_DIR) + "/scenes/two_spheres.scene";
  fs::copy_file(scene, path("s.scene"));
  r = run("render " + path("s.scene") + " -o " + path("x.png") + " --mask " + path("s.scene"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(read(path("s.scene")), read(scene));
  r = run("volume " + path("s.scene") + " -o " + path("s.scene"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra volume: -o would overwrite its input \"" + path("s.scene") + "\"; name another file\n(see umbra volume --help)\n");
  EXPECT_EQ(read(path("s.scene")), read(scene));
  EXPECT_EQ(read(tet), before);

  // Several inputs: an existing file, or a picture's name, is no folder.
  const std::string other = write("other.off", before);
  r = run("render " + tet + " " + other + " -o " + tet);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra render: -o " + tet + " is a file; several inputs make one picture each, in a folder: name a folder\n"
                   "(see umbra render --help)\n");
  r = run("render " + tet + " " + other + " -o " + path("two.png"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra render: -o " + path("two.png") + " names a picture, but several inputs make one picture each, in a folder: "
                   "name a folder (\"" + path("two.png") + "/\" makes one of that name)\n(see umbra render --help)\n");
  EXPECT_FALSE(fs::exists(path("two.png")));
  r = run("render " + tet + " " + other + " -o " + path("two.png/") + " --size 16x16");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(path("two.png/tet.off.png")));
}


// Assimp's one-quad regression file (a quad and the two triangles it splits
// into): the check finds no non-manifold edge among the file's faces, and a
// diagonal that lies along another edge once triangulated; the render's
// warning says the same in the same words.
TEST_F(RenderCommand, RenderAndCheckWordAMeshAlike) {
  const std::string quad = "/usr/share/assimp/models/OBJ/regr_3429812.obj";
  const CommandResult check = run("check " + quad);
  EXPECT_NE(check.out.find("non-manifold       0 edges, 0 vertices"), std::string::npos) << check.out;
  EXPECT_NE(check.out.find("1 diagonal along another edge once triangulated"), std::string::npos) << check.out;
  const CommandResult render = run("render " + quad + " -o " + path("q.png") + " --size 40x40");
  EXPECT_EQ(render.status, 0) << render.err;
  EXPECT_EQ(render.err.find("non-manifold"), std::string::npos) << render.err;
  EXPECT_NE(render.err.find("warning: mesh \"regr_3429812.obj\" is 1 diagonal along another edge once triangulated: "
                            "edge-multiplicity volume\n"),
            std::string::npos)
      << render.err;
}

}  // namespace
}  // namespace umbra
