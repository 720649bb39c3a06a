// umbra bench as a user meets it: the table, the CSV, the plot, and what a
// bad scene or option does.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "render/render_method.hpp"
#include "tests/tools/command_fixture.hpp"

namespace umbra {
namespace {

namespace fs = std::filesystem;
using test::CommandResult;

class BenchCommand : public test::CommandTest {};

const std::string kTwoSpheres = std::string(UMBRA_SOURCE_DIR) + "/scenes/two_spheres.scene";

// CSV as RFC 4180 reads it: a quoted field may hold commas, doubled quotes
// and line breaks.
std::vector<std::vector<std::string>> read_csv(const std::string& path) {
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::vector<std::string>> rows(1);
  std::string cell;
  bool quoted = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted && c == '"' && i + 1 < text.size() && text[i + 1] == '"') cell += '"', ++i;
    else if (c == '"') quoted = !quoted;
    else if (!quoted && c == ',') rows.back().push_back(cell), cell.clear();
    else if (!quoted && c == '\n') rows.back().push_back(cell), cell.clear(), rows.emplace_back();
    else cell += c;
  }
  if (rows.back().empty()) rows.pop_back();
  return rows;
}

TEST_F(BenchCommand, WritesATableAndACsvRowPerMethodAndN) {
  const CommandResult r = run("bench " + kTwoSpheres + " --size 96x96 --frames 1 --segments 8,32 --map-sizes 32,512 --csv " +
                              path("b.csv"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("| scene | method | parameter | wrong pixels | of 96x96 surface | median frame (ms) | vs zfail |"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("| two_spheres.scene | zfail | N = 8 | "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| two_spheres.scene | shadowmap | map 512 | "), std::string::npos) << r.out;
  // The reference is labelled as such: it has no error of its own to report.
  EXPECT_NE(r.out.find("| two_spheres.scene | raycast | - | reference | - of "), std::string::npos) << r.out;
  const auto rows = read_csv(path("b.csv"));
  // The header, then the method table's rows in its order, each as it is
  // swept: at N = 8 and 32, or (this scene has no mesh) not at all for the
  // per-mesh sweep, or at maps of 32 and 512, or once as the reference.
  size_t expected = 1;
  std::vector<std::string> order;
  for (const RenderMethod m : all_methods()) {
    const BenchSweep sweep = method_bench_sweep(m);
    const size_t swept = sweep == BenchSweep::kSegmentsWithMeshes ? 0 : sweep == BenchSweep::kReference ? 1 : 2;
    expected += swept;
    for (size_t k = 0; k < swept; ++k) order.push_back(method_name(m));
  }
  ASSERT_EQ(rows.size(), expected);
  for (size_t k = 0; k < order.size(); ++k) EXPECT_EQ(rows[k + 1][1], order[k]) << "row " << k + 1;
  EXPECT_EQ(rows[0][0], "scene");
  EXPECT_EQ(rows[0][6], "error");
  // A row by its method and its parameter's value.
  const auto row = [&](const std::string& method, const std::string& value) {
    for (const auto& r : rows)
      if (r[1] == method && (r[2] == value || r[3] == value)) return r;
    ADD_FAILURE() << "no row for " << method << " at " << value;
    return rows[0];
  };
  // The N-gon sits inside the true cone: N = 8 gets more pixels wrong than 32.
  EXPECT_GT(std::stol(row("zfail", "8")[4]), std::stol(row("zfail", "32")[4]));
  // A 32-texel map is far coarser than a 512 one.
  EXPECT_GT(std::stol(row("shadowmap", "32")[4]), std::stol(row("shadowmap", "512")[4]));
  EXPECT_EQ(rows[0][11], "reference");
  EXPECT_EQ(rows[1][11], "0");
  EXPECT_EQ(rows.back()[1], "raycast");
  EXPECT_EQ(rows.back()[4], "");   // wrong pixels: none measured
  EXPECT_EQ(rows.back()[6], "");   // error
  EXPECT_EQ(rows.back()[11], "1");
}

// Without options, a few points of each curve; --full, the whole sweep;
// an option given beside --full still says its own.
TEST_F(BenchCommand, TheDefaultMeasuresAFewPointsAndFullTheWholeSweep) {
  const auto parameters = [&](const std::string& options, const std::string& method) {
    const CommandResult r = run("bench " + kTwoSpheres + " --size 16x16 --frames 1 " + options + " --csv " + path("p.csv"));
    EXPECT_EQ(r.status, 0) << r.err;
    std::vector<std::string> found;
    for (const auto& row : read_csv(path("p.csv")))
      if (row[1] == method) found.push_back(method == "shadowmap" ? row[3] : row[2]);
    return found;
  };
  EXPECT_EQ(parameters("", "zfail"), (std::vector<std::string>{"16", "64", "256"}));
  EXPECT_EQ(parameters("", "shadowmap"), (std::vector<std::string>{"512", "2048"}));
  EXPECT_EQ(parameters("--full --map-sizes 16", "zfail"), (std::vector<std::string>{"8", "16", "32", "64", "128", "256"}));
  EXPECT_EQ(parameters("--full --map-sizes 16", "shadowmap"), (std::vector<std::string>{"16"}));
}

TEST_F(BenchCommand, PlotsAsText) {
  if (std::system("gnuplot --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot is not installed";
  const CommandResult r =
      run("bench " + kTwoSpheres + " --size 48x48 --frames 1 --segments 8 --map-sizes 64 --plot " + path("p.txt"));
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream in(path("p.txt"));
  const std::string plot((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(plot.find("two_spheres.scene"), std::string::npos);
  EXPECT_NE(plot.find("median frame time"), std::string::npos);
  EXPECT_FALSE(fs::exists(path("p.txt.gnuplot")));
}

// A scene's file name is data: a line break or a backquote in it once ended
// the plot's gnuplot string and ran a shell command, and a comma or a line
// break split the CSV's rows.
TEST_F(BenchCommand, AHostileSceneNameRunsNothingAndStaysOneCsvField) {
  if (std::system("gnuplot --version >/dev/null 2>&1") != 0) GTEST_SKIP() << "gnuplot is not installed";
  const std::string scene = read(kTwoSpheres);
  const std::vector<std::string> names = {"a\nsystem 'touch pwned-by-newline'\n#, b.scene", "`touch pwned-by-backquote`.scene",
                                          "c\"'d.scene"};
  std::string given;
  for (const std::string& name : names) given += " " + shell_quoted(write(name, scene));
  for (const std::string plot : {"p.png", "p.txt"}) {
    const CommandResult r = run("bench" + given + " --size 16x16 --frames 1 --segments 8 --map-sizes 16 --csv b.csv --plot " + plot,
                                "cd " + shell_quoted(path("")) + " && ");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_FALSE(fs::exists(path("pwned-by-newline")));
    EXPECT_FALSE(fs::exists(path("pwned-by-backquote")));
    EXPECT_GT(fs::file_size(path(plot)), 100u);
  }
  const auto rows = read_csv(path("b.csv"));
  ASSERT_GT(rows.size(), 3u);
  std::vector<std::string> scenes;
  for (size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i].size(), rows[0].size()) << "row " << i;
    if (scenes.empty() || scenes.back() != rows[i][0]) scenes.push_back(rows[i][0]);
  }
  EXPECT_EQ(scenes, names);
  // The text plot shows each name, a control character as '?'.
  const std::string text = read(path("p.txt"));
  EXPECT_NE(text.find("`touch pwned-by-backquote`.scene"), std::string::npos) << text;
  EXPECT_NE(text.find("c\"'d.scene"), std::string::npos) << text;
}

TEST_F(BenchCommand, ABadSceneStopsItBeforeAnythingIsMeasured) {
  const std::string bad = write("bad.scene", "light 0 0 2\nsphere 0 0 0\n");
  const CommandResult r = run("bench " + kTwoSpheres + " " + bad + " --csv " + path("b.csv"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("bad.scene:2:"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(fs::exists(path("b.csv")));
}

TEST_F(BenchCommand, AnUnwritableCsvIsAnErrorNamingIt) {
  const CommandResult r =
      run("bench " + kTwoSpheres + " --size 16x16 --frames 1 --segments 8 --map-sizes 16 --csv /nonexistent/dir/b.csv");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("/nonexistent/dir/b.csv: cannot write"), std::string::npos) << r.err;
}

TEST_F(BenchCommand, UsageErrors) {
  EXPECT_EQ(run("bench " + kTwoSpheres + " --plot out.jpg").status, 2);
  const CommandResult r = run("bench " + kTwoSpheres + " --segments 8,2");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("--segments expects a whole number from 3 to 4096, got \"2\""), std::string::npos) << r.err;
  EXPECT_EQ(run("bench --help").status, 0);
}

}  // namespace
}  // namespace umbra
