// `umbra check` over many meshes: folders, JSON Lines in order under --jobs,
// shards that split the list exactly, exit codes for a mix, and the same
// reports as before on CGAL's data meshes.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "mesh/io/mesh_format.hpp"
#include "tests/mesh/mesh_builders.hpp"
#include "tests/tools/command_fixture.hpp"

namespace umbra {
namespace {

using test::CommandResult;
using test::obj_text;
namespace fs = std::filesystem;

class BatchCheck : public test::CommandTest {
 protected:
  // A folder of meshes in subfolders, with files that are no mesh beside them.
  std::string mesh_folder() {
    fs::create_directories(path("meshes/b/deep"));
    write("meshes/a-closed.obj", obj_text(test::unit_cube()));
    write("meshes/b/open.obj", obj_text(test::without_faces(test::unit_cube(), {4, 5})));
    write("meshes/b/deep/tet", obj_text(test::tetrahedron()));  // no extension: found by content
    write("meshes/b/deep/tet.mtl", "newmtl red\nKd 1 0 0\n");
    write("meshes/README.txt", "These are test meshes.\n");
    return path("meshes");
  }

  // Paths and verdicts of JSON Lines, one "name closed_manifold" line per object.
  std::string verdicts(const std::string& json_lines) {
    std::ofstream(path("lines.json")) << json_lines;
    std::ofstream(path("verdicts.py")) << "import json,sys\n"
                                          "for line in open(sys.argv[1]):\n"
                                          "  o = json.loads(line)\n"
                                          "  print(o['path'].split('/meshes/')[-1], o.get('closed_manifold', o.get('kind', 'error')))\n";
    EXPECT_EQ(std::system(("python3 " + path("verdicts.py") + " " + path("lines.json") + " >" + path("v.txt")).c_str()), 0);
    return read(path("v.txt"));
  }

  static std::string without_time(const std::string& text) {
    return std::regex_replace(text, std::regex(" in [0-9]+\\.[0-9] s:"), " in T s:");
  }
  // JSON Lines with every "seconds" value blanked, for comparing runs.
  static std::string without_seconds(const std::string& text) {
    return std::regex_replace(text, std::regex("\"seconds\":[0-9.e+-]+"), "\"seconds\":0");
  }
};

TEST_F(BatchCheck, AFolderIsSearchedRecursivelyForMeshesByContentInSortedOrder) {
  const CommandResult r = run("check --json " + mesh_folder());
  EXPECT_EQ(r.status, 1);
  // Every file found has its line: a README and an OBJ's materials are in no format umbra reads.
  EXPECT_EQ(verdicts(r.out), "README.txt unsupported-format\nb/deep/tet.mtl unsupported-format\n"
                             "a-closed.obj True\nb/deep/tet True\nb/open.obj False\n");
  EXPECT_NE(r.out.find("{\"path\":\"" + path("meshes/README.txt") + "\",\"passed_over\":\"no format umbra reads (" + mesh_format_names() +
                       ")\",\"kind\":\"unsupported-format\"}\n"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(without_time(r.err), "umbra check: passed over 2 files in no format umbra reads: 1 .mtl, 1 .txt\n"
                                 "umbra check: 3 meshes in T s: 2 closed 2-manifolds, 1 not, 0 unreadable; 2 files passed over\n");
}

TEST_F(BatchCheck, FilesThatAreNoMeshInAFolderArePassedOverAndNamed) {
  // A JPEG saved as .obj and a zip without a model named .3mf are no meshes:
  // a folder of them is not unreadable (exit 1 for the open mesh, not 2).
  // Named on the command line, the JPEG is still an error.
  const std::string folder = mesh_folder();
  const std::string photo = write("meshes/photo.obj", std::string("\xff\xd8\xff\xe0\0\x10JFIF", 10));
  const std::string zip = write("meshes/notes.3mf", std::string("PK\x03\x04", 4) + "notes.txt");
  const CommandResult r = run("check --json " + folder);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(verdicts(r.out), "README.txt unsupported-format\nb/deep/tet.mtl unsupported-format\n"
                             "a-closed.obj True\nb/deep/tet True\nb/open.obj False\n");
  EXPECT_EQ(without_time(r.err), "umbra check: passed over " + zip + ": a zip archive without a 3D model part, not a mesh\n"
                                 "umbra check: passed over " + photo + ": a JPEG image, not a mesh\n"
                                 "umbra check: passed over 2 files in no format umbra reads: 1 .mtl, 1 .txt\n"
                                 "umbra check: 3 meshes in T s: 2 closed 2-manifolds, 1 not, 0 unreadable; 4 files passed over\n");
  EXPECT_EQ(run("check " + photo).status, 2);
}

TEST_F(BatchCheck, AMixOfGoodOpenAndUnreadableMeshesIsAllReportedAndExitsTwo) {
  const std::string folder = mesh_folder();
  const std::string broken = write("meshes/broken.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
  const CommandResult r = run("check --json " + folder);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(verdicts(r.out), "README.txt unsupported-format\nb/deep/tet.mtl unsupported-format\n"
                             "a-closed.obj True\nb/deep/tet True\nb/open.obj False\nbroken.off error\n");
  EXPECT_EQ(without_time(r.err), "umbra check: passed over 2 files in no format umbra reads: 1 .mtl, 1 .txt\n" + broken +
                                     ":4: the file ends before vertex 2 of 3\n"
                                     "umbra check: 4 meshes in T s: 2 closed 2-manifolds, 1 not, 1 unreadable; 2 files passed over\n");
  // Without the unreadable one, the open one decides: exit 1; with only closed ones, 0.
  EXPECT_EQ(run("check " + folder + "/a-closed.obj " + folder + "/b").status, 1);
  EXPECT_EQ(run("check " + folder + "/a-closed.obj " + folder + "/b/deep").status, 0);
}

// One definition, one count: a closed tetrahedron with a degenerate face is
// a solid but no closed 2-manifold (not clean). The summary counts what the
// reports say, as the JSON and the page do, --solid or not, in one process
// or in workers; --solid adds the solids, and --brief --solid prints the
// solid verdict.
TEST_F(BatchCheck, TheSummaryCountsWhatTheReportsSay) {
  fs::create_directories(path("meshes"));
  write("meshes/degenerate.off", "OFF\n4 5 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 0 0 1\n");
  write("meshes/cube.obj", obj_text(test::unit_cube()));
  EXPECT_EQ(verdicts(run("check --json " + path("meshes")).out), "cube.obj True\ndegenerate.off False\n");
  for (const std::string workers : {"", " --timeout 30"}) {
    CommandResult r = run("check --brief --solid " + path("meshes") + workers);
    EXPECT_EQ(r.status, 0) << r.err;  // both are solids
    EXPECT_EQ(r.out, path("meshes/cube.obj") + ": OBJ, 12 triangles, 1 component: solid\n" + path("meshes/degenerate.off") +
                         ": OFF, 4 triangles, 1 component: solid\n");
    EXPECT_EQ(without_time(r.err), "umbra check: 2 meshes in T s: 1 closed 2-manifold, 1 not, 0 unreadable; 2 solids\n");
    r = run("check --brief " + path("meshes") + workers);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(without_time(r.err), "umbra check: 2 meshes in T s: 1 closed 2-manifold, 1 not, 0 unreadable\n");
  }
}

// A skipped search (--time-limit 0) proves nothing clean, and finds nothing
// wrong: "not known to be clean", exit 1, as --help says.
TEST_F(BatchCheck, ASkippedSearchLeavesAMeshNotKnownToBeClean) {
  const std::string cube = write("cube.obj", obj_text(test::unit_cube()));
  const CommandResult r = run("check --brief --time-limit 0 " + cube);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.out, cube + ": OBJ, 12 triangles, 1 component: closed and consistently oriented, not known to be clean "
                          "(self-intersections not checked): still casts its shadow from silhouette edges\n");
  // --help as one line of words, however it wraps.
  const std::string help = std::regex_replace(run("check --help").out, std::regex("\\s+"), " ");
  EXPECT_NE(help.find("A mesh whose search was skipped or stopped is \"not known to be clean\""), std::string::npos);
}

TEST_F(BatchCheck, JsonLinesUnderJobsAreInInputOrderAndComplete) {
  // Meshes of very different sizes, so that they finish out of order.
  fs::create_directories(path("meshes"));
  std::string expected;
  for (int i = 0; i < 24; ++i) {
    const std::string name = "m" + std::string(i < 10 ? "0" : "") + std::to_string(i) + ".obj";
    const bool open = i % 3 == 0;
    const PolygonSoup sphere = test::uv_sphere(i % 4 == 1 ? 96 : 6, i % 4 == 1 ? 96 : 6);
    write("meshes/" + name, obj_text(open ? test::without_faces(sphere, {1}) : sphere));
    expected += name + (open ? " False\n" : " True\n");
  }
  const CommandResult one = run("check --json --jobs 1 " + path("meshes"));
  const CommandResult two = run("check --json --jobs 2 " + path("meshes"));
  const CommandResult many = run("check --json --jobs 7 " + path("meshes"));
  EXPECT_EQ(verdicts(two.out), expected);
  EXPECT_EQ(without_seconds(two.out), without_seconds(one.out));
  EXPECT_EQ(without_seconds(many.out), without_seconds(one.out));
  EXPECT_EQ(two.status, 1);
}

TEST_F(BatchCheck, ShardsSplitTheListIntoDisjointPartsThatConcatenateToTheWhole) {
  fs::create_directories(path("meshes"));
  for (int i = 0; i < 11; ++i) write("meshes/t" + std::to_string(i) + ".obj", obj_text(test::tetrahedron()));
  const std::string whole = without_seconds(run("check --json " + path("meshes")).out);
  ASSERT_EQ(std::count(whole.begin(), whole.end(), '\n'), 11);
  for (const int count : {1, 2, 3, 4, 11, 15}) {
    std::string joined;
    for (int k = 0; k < count; ++k) {
      const CommandResult part = run("check --json --shard " + std::to_string(k) + "/" + std::to_string(count) + " " + path("meshes"));
      EXPECT_EQ(part.status, 0) << part.err;
      joined += without_seconds(part.out);
    }
    EXPECT_EQ(joined, whole) << count << " shards";
  }
  const CommandResult summary = run("check --shard 1/4 " + path("meshes"));
  EXPECT_EQ(without_time(summary.err), "umbra check: 3 meshes (shard 1/4 of 11) in T s: 3 closed 2-manifolds, 0 not, 0 unreadable\n");
}

TEST_F(BatchCheck, TheGnuParallelRecipeRunsShardsAtOnceAndConcatenatesToTheWhole) {
  ASSERT_EQ(std::system("command -v parallel >/dev/null"), 0) << "GNU parallel is missing: ./build.sh installs it";
  const std::string folder = mesh_folder();
  const std::string whole = without_seconds(run("check --json " + folder).out);
  // docs/batch-checks.md: -k keeps the shards' outputs in the order of K.
  const std::string recipe = "parallel -k --will-cite " + std::string(UMBRA_EXECUTABLE) + " check --json --shard {}/3 " +
                             folder + " ::: 0 1 2 >" + path("sharded.jsonl") + " 2>/dev/null";
  EXPECT_EQ(WEXITSTATUS(std::system(recipe.c_str())), 1);  // parallel exits with the number of failed jobs: one shard holds the open mesh
  EXPECT_EQ(without_seconds(read(path("sharded.jsonl"))), whole);
}

TEST_F(BatchCheck, AProgressBarShowsOnATerminalOnlyOnceTheCheckHasRunForASecond) {
  // 16 spheres of 180,000 triangles: well over a second's work on one core.
  fs::create_directories(path("meshes"));
  write("meshes/s0.obj", obj_text(test::uv_sphere(300, 300)));
  for (int i = 1; i < 16; ++i) fs::copy_file(path("meshes/s0.obj"), path("meshes/s" + std::to_string(i) + ".obj"));
  // script(1) gives umbra a terminal; its output holds what was drawn there.
  const std::string command = "script -qec '" + std::string(UMBRA_EXECUTABLE) + " check --jobs 1 " + path("meshes") +
                              " >/dev/null' " + path("typescript") + " >/dev/null";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const std::string terminal = read(path("typescript"));
  EXPECT_NE(terminal.find("] "), std::string::npos) << terminal;
  EXPECT_NE(terminal.find("/16 "), std::string::npos) << terminal;
  EXPECT_NE(terminal.find("\r\033[K"), std::string::npos);  // each redraw erases the line first
  // Without a terminal, stderr holds the summary alone (the other tests check it exactly).
  const CommandResult piped = run("check --jobs 1 " + path("meshes"));
  EXPECT_EQ(piped.err.find('['), std::string::npos);
}

// --timeout: the meshes in worker processes. In the test build that hangs
// or crashes on purpose (fault_injection.hpp), the mesh that hangs is
// stopped and the one that crashes reported; every other report is as
// without --timeout, in order, and every mesh has its line.
TEST_F(BatchCheck, WithATimeoutAHangOrACrashCostsOnlyItsOwnReport) {
  const std::string meshes = mesh_folder();
  const CommandResult unisolated = run("check " + meshes + " --json --jobs 2");
  write("meshes/b/hang.obj", obj_text(test::unit_cube()));
  write("meshes/b/crash.obj", obj_text(test::unit_cube()));
  const CommandResult r = run("check " + meshes + " --json --jobs 2 --timeout 2", "", UMBRA_FAULT_INJECTED_EXECUTABLE);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(verdicts(r.out), "README.txt unsupported-format\nb/deep/tet.mtl unsupported-format\n"
                             "a-closed.obj True\nb/crash.obj error\nb/deep/tet True\nb/hang.obj error\nb/open.obj False\n");
  EXPECT_NE(r.out.find("{\"path\":\"" + path("meshes/b/hang.obj") + "\",\"error\":\"" + path("meshes/b/hang.obj") +
                       ": timed out after 2 s (--timeout)\"}\n"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.err.find(path("meshes/b/crash.obj") + ": crashed (SIGABRT)\n"), std::string::npos) << r.err;
  // The others' lines are those of a check in one process, but for the
  // seconds the search took.
  const std::regex seconds("\"seconds\":[-0-9.e+]+");
  const std::string expected = std::regex_replace(unisolated.out, seconds, "\"seconds\":0");
  std::string others;
  for (std::istringstream in(r.out); std::getline(in, others);) {
    if (others.find("hang.obj") != std::string::npos || others.find("crash.obj") != std::string::npos) continue;
    EXPECT_NE(expected.find(std::regex_replace(others, seconds, "\"seconds\":0") + "\n"), std::string::npos) << others;
  }
}

// Links in a folder: a linked folder is searched (once, however many links
// lead to it, a link to a folder above included), a linked mesh is checked,
// and a link to nothing or a second way into a folder is said, not skipped
// in silence.
TEST_F(BatchCheck, LinksAreFollowedOnceAndDanglingOnesAreSaid) {
  fs::create_directories(path("shared/parts"));
  write("shared/parts/tet.obj", obj_text(test::tetrahedron()));
  fs::create_directories(path("meshes"));
  write("meshes/cube.obj", obj_text(test::unit_cube()));
  fs::create_directory_symlink(path("shared"), path("meshes/linked"));
  fs::create_directory_symlink(path("shared"), path("meshes/again"));
  fs::create_directory_symlink(path("meshes"), path("meshes/loop"));
  fs::create_symlink(path("shared/parts/tet.obj"), path("meshes/tet-link.obj"));
  fs::create_symlink(path("gone.obj"), path("meshes/gone.obj"));
  const CommandResult r = run("check " + path("meshes") + " --json");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(verdicts(r.out), "again/parts/tet.obj True\ncube.obj True\ntet-link.obj True\n") << r.out;
  EXPECT_NE(r.err.find("umbra check: passed over " + path("meshes/gone.obj") + ": a link to nothing (" + path("gone.obj") + ")\n"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("umbra check: passed over " + path("meshes/linked") + ": a link to the folder " +
                       fs::canonical(path("shared")).string() + ", searched once already\n"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("umbra check: passed over " + path("meshes/loop") + ": a link to the folder " +
                       fs::canonical(path("meshes")).string() + ", searched once already\n"),
            std::string::npos)
      << r.err;
}

// A FIFO named as a mesh or a scene is never opened for reading (it would
// wait for a writer for ever): named on its own it is an error at once, in
// a folder it is passed over and said.
TEST_F(BatchCheck, AFifoIsNeverWaitedFor) {
  fs::create_directories(path("meshes"));
  write("meshes/tet.obj", obj_text(test::tetrahedron()));
  ASSERT_EQ(::mkfifo(path("meshes/pipe.obj").c_str(), 0600), 0);
  CommandResult r = run("check " + path("meshes/pipe.obj"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, path("meshes/pipe.obj") + ": is not a regular file (a FIFO)\n");
  r = run("check " + path("meshes"));
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("umbra check: passed over " + path("meshes/pipe.obj") + ": a FIFO, not a mesh file\n"), std::string::npos)
      << r.err;
  r = run("render " + path("meshes/pipe.obj") + " -o " + path("p.png"));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, path("meshes/pipe.obj") + ": is not a regular file (a FIFO)\n");
}

TEST_F(BatchCheck, AFolderWithNoMeshExitsTwoAndSaysSo) {
  fs::create_directories(path("empty/inner"));
  write("empty/notes.txt", "no meshes here\n");
  const CommandResult empty = run("check " + path("empty"));
  EXPECT_EQ(empty.status, 2);
  EXPECT_EQ(empty.err, "umbra check: no mesh files in " + path("empty") + " (passed over 1 file in no format umbra reads: 1 .txt)\n");
}

TEST_F(BatchCheck, UsageErrorsForJobsAndShards) {
  const std::string mesh = write("t.obj", obj_text(test::tetrahedron()));
  EXPECT_EQ(run("check --shard 3/3 " + mesh).err,
            "umbra check: --shard counts parts from 0: K must be below N, got \"3/3\"\n(see umbra check --help)\n");
  EXPECT_EQ(run("check --shard 2 " + mesh).err,
            "umbra check: --shard expects K/N such as 0/4 (the first of four parts), got \"2\"\n(see umbra check --help)\n");
  EXPECT_EQ(run("check --jobs 0 " + mesh).err,
            "umbra check: --jobs expects a whole number from 1 to 4096, got \"0\"\n(see umbra check --help)\n");
  EXPECT_EQ(run("check --jobs 0 " + mesh).status, 2);
}

TEST_F(BatchCheck, JobsCapsTheThreadsOfTheWholeProcess) {
  // CGAL's 143 data meshes, checked for about a second; the process's
  // threads sampled every 2 ms (/proc/PID/status) never number more than
  // --jobs (no terminal here, so no progress bar's thread).
  const std::string folder = std::string(UMBRA_CGAL_DATA) + "/meshes";
  for (const int jobs : {1, 2}) {
    const std::string script = std::string(UMBRA_EXECUTABLE) + " check --jobs " + std::to_string(jobs) + " " + folder +
                               " >/dev/null 2>&1 & pid=$!; most=0\n"
                               "while kill -0 $pid 2>/dev/null; do\n"
                               "  n=$(awk '/^Threads:/ {print $2}' /proc/$pid/status 2>/dev/null)\n"
                               "  [ -n \"$n\" ] && [ \"$n\" -gt $most ] && most=$n\n"
                               "  sleep 0.002\n"
                               "done\n"
                               "echo $most >" + path("most.txt") + "\n";
    std::ofstream(path("sample.sh")) << script;
    ASSERT_EQ(std::system(("sh " + path("sample.sh")).c_str()), 0);
    const int most = std::stoi(read(path("most.txt")));
    EXPECT_GE(most, 1) << jobs;
    EXPECT_LE(most, jobs) << jobs;
  }
}

// The reports of every mesh in CGAL's data, checked as one folder on every
// core, field by field as tests/data/cgal_check_reports.tsv (made by
// tests/tools/report_fields.py) lists them.
TEST_F(BatchCheck, CgalDataMeshesGetTheSameReportsAsBefore) {
  const std::string folder = std::string(UMBRA_CGAL_DATA) + "/meshes";
  const std::string command = std::string(UMBRA_EXECUTABLE) + " check --json " + folder + " 2>/dev/null | python3 " +
                              UMBRA_SOURCE_DIR + "/tests/tools/report_fields.py " + folder + " >" + path("reports.tsv");
  std::system(command.c_str());
  EXPECT_EQ(read(path("reports.tsv")), read(std::string(UMBRA_SOURCE_DIR) + "/tests/data/cgal_check_reports.tsv"));
}

}  // namespace
}  // namespace umbra
