// Options as users write them: --opt=value and --opt value alike, in any
// order, with umbra's own messages for what is wrong; --version.
#include <gtest/gtest.h>
#include <utility>
#include <sstream>
#include <set>
#include <regex>
#include <iterator>
#include <fstream>

#include "tests/mesh/mesh_builders.hpp"
#include "tests/tools/command_fixture.hpp"

namespace umbra {
namespace {

using test::CommandResult;

class Options : public test::CommandTest {
 protected:
  const std::string scene = std::string(UMBRA_SOURCE_DIR) + "/scenes/two_spheres.scene";
};

TEST_F(Options, EqualsAndSpaceFormsGiveTheSameImage) {
  const CommandResult spaced = run("render " + scene + " -o " + path("a.png") + " --size 64x48 --light-angle -30 --method zfail");
  const CommandResult joined = run("render --method=zfail --light-angle=-30 --size=64x48 --output=" + path("b.png") + " " + scene);
  ASSERT_EQ(spaced.status, 0) << spaced.err;
  ASSERT_EQ(joined.status, 0) << joined.err;
  EXPECT_EQ(joined.out, "wrote " + path("b.png") + " (64x48)\n");
  EXPECT_EQ(read(path("a.png")), read(path("b.png")));
}

TEST_F(Options, EveryCommandTakesEqualsForms) {
  const std::string mesh = write("t.obj", test::obj_text(test::tetrahedron()));
  EXPECT_EQ(run("check --time-limit=5 --jobs=1 " + mesh).status, 0);
  EXPECT_EQ(run("volume " + scene + " --segments=8 --light=1 --far=2 -o " + path("v.obj")).status, 0);
  EXPECT_EQ(run("bench " + scene + " --size=32x32 --frames=1 --segments=8 --map-sizes=16 --csv=" + path("b.csv")).status, 0);
  EXPECT_FALSE(read(path("b.csv")).empty());
}

TEST_F(Options, DoubleDashEndsTheOptions) {
  // A file whose name starts with "-" is reached after "--"; before it, it is an unknown option.
  const std::string dash = write("-dash.obj", test::obj_text(test::unit_cube()));
  EXPECT_EQ(run("check -- " + dash).status, 0);
  const CommandResult check = run("check --jobs 1 -- -dash.obj", "cd " + folder_.string() + " && ");
  EXPECT_EQ(check.status, 0) << check.err;
  EXPECT_EQ(run("check -dash.obj", "cd " + folder_.string() + " && ").err, "umbra check: unknown option -dash.obj\n(see umbra check --help)\n");
  EXPECT_EQ(run("render -o " + path("a.png") + " --size 32x32 -- " + scene).status, 0);
  EXPECT_TRUE(test::fs::exists(path("a.png")));
}

TEST_F(Options, MistakesAreNamedInUmbrasWords) {
  EXPECT_EQ(run("render " + scene + " -o x.png --size").err, "umbra render: --size needs a value\n(see umbra render --help)\n");
  EXPECT_EQ(run("render " + scene + " -o x.png --size=10by10").err,
            "umbra render: --size expects WIDTHxHEIGHT such as 800x600, got \"10by10\"\n(see umbra render --help)\n");
  EXPECT_EQ(run("render " + scene + " -o x.png --frobnicate=3").err, "umbra render: unknown option --frobnicate\n(see umbra render --help)\n");
  EXPECT_EQ(run("check --jobs=many x.obj").err,
            "umbra check: --jobs expects a whole number from 1 to 4096, got \"many\"\n(see umbra check --help)\n");
  EXPECT_EQ(run("view " + scene + " --segments=2").err,
            "umbra view: --segments expects a whole number from 3 to 4096, got \"2\"\n(see umbra view --help)\n");
  EXPECT_EQ(run("render " + scene + " -o x.png --segments=2").status, 2);
  EXPECT_EQ(run("render " + scene + " -o x.png --gl=glx").err,
            "umbra render: --gl expects auto, egl or osmesa, got \"glx\"\n(see umbra render --help)\n");
}

TEST_F(Options, GlPicksThePlatformThatExplainNames) {
  const CommandResult egl = run("render " + scene + " -o " + path("egl.png") + " --size 64x48 --gl egl --explain");
  const CommandResult osmesa = run("render " + scene + " -o " + path("osmesa.png") + " --size 64x48 --gl=osmesa --explain");
  ASSERT_EQ(egl.status, 0) << egl.err;
  ASSERT_EQ(osmesa.status, 0) << osmesa.err;
  EXPECT_NE(egl.out.find("\n  OpenGL: EGL 1."), std::string::npos) << egl.out;
  EXPECT_NE(osmesa.out.find("\n  OpenGL: OSMesa: "), std::string::npos) << osmesa.out;
  const CommandResult chosen = run("render " + scene + " -o " + path("env.png") + " --size 64x48 --explain", "UMBRA_GL=osmesa ");
  EXPECT_NE(chosen.out.find("\n  OpenGL: OSMesa: "), std::string::npos) << chosen.out;
  // A bad UMBRA_GL is a usage error, said once before any work, as a bad --gl is.
  const std::string bad_gl = "umbra render: UMBRA_GL must be auto, egl or osmesa, not \"glx\"\n(see umbra render --help)\n";
  CommandResult bad = run("render " + scene + " -o " + path("bad.png") + " --size 64x48", "UMBRA_GL=glx ");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err, bad_gl);
  EXPECT_FALSE(test::fs::exists(path("bad.png")));
  bad = run("render " + scene + " " + scene + " -o " + path("bad") + " --size 64x48", "UMBRA_GL=glx ");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err, bad_gl);
  EXPECT_FALSE(test::fs::exists(path("bad")));
  EXPECT_EQ(run("render " + scene + " -o " + path("bad.png") + " --gl osmesa --size 64x48", "UMBRA_GL=glx ").status, 0);
}

TEST_F(Options, AntialiasingIsOnForAStagedMeshAndOffForASceneUnlessAsked) {
  const std::string mesh = std::string(UMBRA_SOURCE_DIR) + "/scenes/meshes/torus.obj";
  const auto image_line = [&](const std::string& args) {
    const CommandResult r = run("render " + args + " -o " + path("a.png") + " --size 40x40 --explain");
    EXPECT_EQ(r.status, 0) << r.err;
    const size_t at = r.out.find("  image: ");
    return at == std::string::npos ? r.out : r.out.substr(at, r.out.find('\n', at) - at);
  };
  EXPECT_EQ(image_line(mesh), "  image: 40x40, one sample per pixel, and 3 x 3 exact rays averaged at each that differs from a "
                              "neighbour (--antialias)");
  EXPECT_EQ(image_line(mesh + " --antialias-all"), "  image: 40x40, 3 x 3 samples per pixel, averaged (--antialias)");
  EXPECT_EQ(image_line(mesh + " --method shadowmap"), "  image: 40x40, 3 x 3 samples per pixel, averaged (--antialias)");
  // More triangles (the torus's 576 and the floor's 2) than pixels: the larger frame costs less than the rays.
  const CommandResult small = run("render " + mesh + " -o " + path("a.png") + " --size 20x20 --explain");
  EXPECT_NE(small.out.find("  image: 20x20, 3 x 3 samples per pixel, averaged (--antialias)\n"), std::string::npos) << small.out;
  EXPECT_EQ(image_line(scene), "  image: 40x40, one sample per pixel, at its centre (--antialias)");
  EXPECT_EQ(image_line(scene + " --antialias 2"), "  image: 40x40, 2 x 2 samples per pixel, averaged (--antialias)");
  EXPECT_EQ(image_line(mesh + " --method raycast"), "  image: 40x40, one sample per pixel, and 3 x 3 exact rays averaged at "
                                                    "each that differs from a neighbour (--antialias)");
  EXPECT_EQ(image_line(mesh + " --antialias=1 --method raycast"), "  image: 40x40, one sample per pixel, at its centre (--antialias)");
  EXPECT_EQ(run("render " + scene + " -o x.png --antialias 5").err,
            "umbra render: --antialias expects a whole number from 1 to 4, got \"5\"\n(see umbra render --help)\n");
}

TEST_F(Options, WithoutAnEglDeviceAutoFallsBackToOsMesaAndEglSaysWhy) {
  // libglvnd with no vendor library to hand EGL to: as on a machine without Mesa's EGL.
  const std::string no_egl = "__EGL_VENDOR_LIBRARY_FILENAMES=" + path("none.json") + " ";
  const CommandResult version = run("--version", no_egl);
  EXPECT_NE(version.out.find("\nheadless OpenGL: OSMesa: "), std::string::npos) << version.out;
  const CommandResult egl = run("render " + scene + " -o " + path("egl.png") + " --size 32x32 --gl egl", no_egl);
  EXPECT_EQ(egl.status, 1);
  EXPECT_EQ(egl.err.rfind("EGL: ", 0), 0u) << egl.err;
  EXPECT_FALSE(test::fs::exists(path("egl.png")));
  EXPECT_EQ(run("render " + scene + " -o " + path("auto.png") + " --size 32x32", no_egl).status, 0);
  EXPECT_TRUE(test::fs::exists(path("auto.png")));
}

TEST_F(Options, VersionAndHelp) {
  const CommandResult version = run("--version");
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.out.rfind("umbra ", 0), 0u);
  EXPECT_EQ(version.out.back(), '\n');
  EXPECT_NE(version.out.find("\nheadless OpenGL: "), std::string::npos) << version.out;
  for (const char* command : {"render", "check", "view", "volume", "bench"}) {
    const CommandResult help = run(std::string(command) + " --help");
    EXPECT_EQ(help.status, 0) << command;
    EXPECT_EQ(help.out.rfind(std::string("usage: umbra ") + command, 0), 0u) << command;
    EXPECT_EQ(run(std::string(command) + " -h").out, help.out);
    EXPECT_EQ(run(std::string("help ") + command).out, help.out);
  }
  // The top-level help leads with what most users come for: a mesh file, a folder.
  const CommandResult top = run("--help");
  EXPECT_EQ(top.status, 0);
  EXPECT_NE(top.out.find("\n  umbra render model.glb -o model.png "), std::string::npos) << top.out;
  EXPECT_NE(top.out.find("\n  umbra render models/ -o pictures/ "), std::string::npos) << top.out;
  EXPECT_NE(top.out.find("\n  render MESH|SCENE|FOLDER... -o OUT\n"), std::string::npos) << top.out;
  EXPECT_NE(top.out.find("\n  volume MESH|SCENE -o OUT.obj\n"), std::string::npos) << top.out;
}

// docs/options.md is what the options' definitions say: umbra writes it
// (`umbra --list-options=markdown`), so an option added, renamed or given a
// new range fails this test until the page is written again.
TEST_F(Options, DocsOptionsMdIsWhatTheDefinitionsSay) {
  std::ifstream in(std::string(UMBRA_SOURCE_DIR) + "/docs/options.md");
  const std::string page(std::istreambuf_iterator<char>(in), {});
  const CommandResult written = run("--list-options=markdown");
  ASSERT_EQ(written.status, 0) << written.err;
  // The first line that differs, rather than two pages.
  std::istringstream was(page), now(written.out);
  std::string old_line, new_line;
  for (int line = 1; std::getline(now, new_line); ++line)
    if (!std::getline(was, old_line) || old_line != new_line) {
      ADD_FAILURE() << "docs/options.md is out of date at line " << line << ": it says\n  " << old_line << "\nand the options say\n  "
                    << new_line << "\n(write it again: ./build/umbra --list-options=markdown > docs/options.md)";
      break;
    }
  EXPECT_EQ(page.size(), written.out.size()) << "docs/options.md is out of date: ./build/umbra --list-options=markdown > docs/options.md";
  // Each command's section holds every name its parser takes, --help's
  // first spelling of each.
  for (const char* command : {"render", "check", "view", "volume", "bench", "formats"}) {
    std::istringstream names(run(std::string(command) + " --list-options").out);
    const size_t section = page.find(std::string("\n## umbra ") + command);
    ASSERT_NE(section, std::string::npos) << command;
    const std::string own = page.substr(section, page.find("\n## ", section + 1) - section);
    for (std::string name; std::getline(names, name);)
      EXPECT_NE(own.find(name), std::string::npos) << command << " " << name << " is parsed but not in docs/options.md";
  }
}

// The docs' prose names only options that exist: a renamed or removed option
// fails this test until the sentences that name it follow. Names are taken
// where they start a code span ("`--camera-azimuth 150`"); "`--camera-*`"
// stands for every option it begins.
TEST_F(Options, TheDocsNameOnlyOptionsThatExist) {
  std::set<std::string> options = {"--version", "--list-options"};
  for (const char* command : {"render", "check", "view", "volume", "bench", "formats"}) {
    std::istringstream names(run(std::string(command) + " --list-options").out);
    for (std::string name; std::getline(names, name);) options.insert(name);
  }
  // Other programs' options the docs show: CMake's `--component`, mypy's `--strict`.
  const std::set<std::string> others = {"--component", "--strict"};
  const std::regex named("`(--[a-z][a-z0-9-]*)(\\*?)");
  std::vector<test::fs::path> files = {std::string(UMBRA_SOURCE_DIR) + "/README.md"};
  for (const auto& file : test::fs::directory_iterator(std::string(UMBRA_SOURCE_DIR) + "/docs"))
    if (file.path().extension() == ".md") files.push_back(file.path());
  for (const test::fs::path& file : files) {
    std::ifstream in(file);
    const std::string text(std::istreambuf_iterator<char>(in), {});
    for (auto it = std::sregex_iterator(text.begin(), text.end(), named); it != std::sregex_iterator(); ++it) {
      const std::string name = (*it)[1];
      const bool stem = (*it)[2].length() > 0;
      const bool known = options.count(name) || others.count(name) ||
                         (stem && options.lower_bound(name) != options.end() && options.lower_bound(name)->rfind(name, 0) == 0);
      EXPECT_TRUE(known) << file.filename() << " names " << name << ", which no command takes";
    }
  }
}

// A mistyped command or option is named with the nearest one, where one is near.
TEST_F(Options, AMistypedCommandOrOptionGetsADidYouMean) {
  CommandResult r = run("rendr " + scene);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra: unknown command \"rendr\" (did you mean render?)\n(see umbra --help)\n");
  r = run("help chekc");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra: unknown command \"chekc\" (did you mean check?)\n(see umbra --help)\n");
  EXPECT_EQ(run("explode").err, "umbra: unknown command \"explode\"\n(see umbra --help)\n");
  r = run("render " + scene + " -o " + path("a.png") + " --antialais 2");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "umbra render: unknown option --antialais (did you mean --antialias?)\n(see umbra render --help)\n");
  EXPECT_EQ(run("check --jbos 2 " + scene).err, "umbra check: unknown option --jbos (did you mean --jobs?)\n(see umbra check --help)\n");
}

}  // namespace
}  // namespace umbra
