// Folder renders over corpora of downloaded models, some broken or hostile:
// files drawn in worker processes, a time limit per file, a record of
// every file, a run that resumes, and nothing overwritten or lost.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <sstream>
#include <tuple>

#include "tests/tools/command_fixture.hpp"

namespace umbra {
namespace {

namespace fs = std::filesystem;
using test::CommandResult;

class CorpusRender : public test::CommandTest {
 protected:
  // The one JSON line whose "path" is `path`, or "" (compact JSON, as umbra
  // check writes it; these paths are ASCII without escapes).
  static std::string line_of(const std::string& json, const std::string& path) {
    std::istringstream in(json);
    std::string line, found;
    size_t count = 0;
    while (std::getline(in, line))
      if (line.find("{\"path\":\"" + path + "\",") == 0) found = line, ++count;
    EXPECT_LE(count, 1u) << path << " has " << count << " lines";
    return found;
  }
  static size_t lines(const std::string& text) { return size_t(std::count(text.begin(), text.end(), '\n')); }
  // The "kind" of a failure, "null" where none is.
  static std::string kind_of(const std::string& line) {
    const size_t at = line.find("\"kind\":");
    if (at == std::string::npos) return "";
    if (line.compare(at + 7, 4, "null") == 0) return "null";
    return line.substr(at + 8, line.find('"', at + 8) - at - 8);
  }
  static std::string status_of(const std::string& line) {
    const size_t at = line.find("\"status\":\"");
    return at == std::string::npos ? "" : line.substr(at + 10, line.find('"', at + 10) - at - 10);
  }
  static std::string copy_in(const std::string& from, const fs::path& to) {
    fs::create_directories(to.parent_path());
    fs::copy(from, to, fs::copy_options::recursive);
    return to.string();
  }
  // The temporary files under `folder` (NAME.XXXXXX.partial), at any depth.
  static size_t temporaries_in(const std::string& folder) {
    size_t count = 0;
    for (const auto& entry : fs::recursive_directory_iterator(folder))
      count += entry.path().filename().string().find(".partial") != std::string::npos;
    return count;
  }
  // A PNG's signature and header alone, claiming `side` x `side` grey pixels.
  static std::string png_header(uint32_t side) {
    std::string out = "\x89PNG\r\n\x1a\n";
    for (const uint32_t v : {13u}) out += {char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    out += "IHDR";
    for (int k = 0; k < 2; ++k) out += {char(side >> 24), char(side >> 16), char(side >> 8), char(side)};
    out += std::string("\x08\x00\x00\x00\x00", 5) + std::string(4, '\0');  // stb_image reads no CRC
    return out;
  }
};

const std::string kTetrahedron = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

// Real models from Debian's packages, with a hanging file, a huge texture,
// a FIFO map and two colliding names among them (the fault-injected build
// hangs on a file named "hang"): every good file drawn, every bad one on its
// own line, nothing overwritten, exit 1; and a second run with
// --skip-existing draws nothing new.
TEST_F(CorpusRender, AMixedFolderRendersEveryGoodFileAndRecordsEveryFile) {
  const fs::path models = folder_ / "models";
  const std::string assimp = "/usr/share/assimp/models/";
  for (const char* file : {"glTF2/BoxTextured-glTF", "STL/Wuson.stl", "OBJ/spider.obj", "OBJ/spider.mtl", "OBJ/SpiderTex.jpg",
                           "OBJ/drkwood2.jpg", "OBJ/engineflare1.jpg"})
    copy_in(assimp + file, models / "assimp" / fs::path(file).filename());
  copy_in(std::string(UMBRA_CGAL_DATA) + "/meshes/anchor.off", models / "cgal" / "anchor.off");
  for (const char* folder : {"a", "b", "maps"}) fs::create_directories(models / folder);
  write("models/a/x.off", kTetrahedron);
  write("models/b/x.off", kTetrahedron.substr(0, kTetrahedron.find("1 0 0")) + "2 0 0" +
                              kTetrahedron.substr(kTetrahedron.find("1 0 0") + 5));
  write("models/hang.off", kTetrahedron);
  // A huge map and a FIFO map: each drawn in its material's colour, said once.
  const std::string textured = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nusemtl huge\nf 1/1 2/1 3/1\n"
                               "usemtl fifo\nf 1/1 3/1 2/1\n";
  write("models/maps/textured.obj", textured);
  write("models/maps/m.mtl", "newmtl huge\nmap_Kd huge.png\nnewmtl fifo\nmap_Kd fifo.png\n");
  write("models/maps/huge.png", png_header(16384));
  ASSERT_EQ(::mkfifo(path("models/maps/fifo.png").c_str(), 0600), 0);
  write("models/broken.obj", "v 0 0 0\nf 1 2 3\n");

  const std::string out = path("out");
  const std::string command = "render " + models.string() + " -o " + out + " --size 160x120 --antialias 1 --jobs 2 " +
                              "--timeout 5 --json --sheet " + path("sheet.png");
  const CommandResult first = run(command, "", UMBRA_FAULT_INJECTED_EXECUTABLE);
  EXPECT_EQ(first.status, 1) << first.err;
  const std::map<std::string, std::string> expected = {
      {"assimp/BoxTextured-glTF/BoxTextured.gltf", "drawn"}, {"assimp/Wuson.stl", "drawn"}, {"assimp/spider.obj", "drawn"},
      {"cgal/anchor.off", "drawn"}, {"a/x.off", "drawn"}, {"b/x.off", "drawn"}, {"maps/textured.obj", "drawn"},
      {"hang.off", "timed out"}, {"broken.obj", "failed"}};
  // Every file found has its line: the models' companions (3 .jpg, 2 .mtl,
  // 2 .png, a .bin: materials, buffers, maps) are in no format umbra reads.
  const size_t unsupported = 8;
  const std::vector<std::string> companions = {"assimp/BoxTextured-glTF/BoxTextured0.bin", "assimp/BoxTextured-glTF/CesiumLogoFlat.png",
                                               "assimp/SpiderTex.jpg", "assimp/drkwood2.jpg"};
  EXPECT_EQ(lines(first.out), expected.size() + unsupported) << first.out;
  for (const std::string& file : companions) {
    const std::string line = line_of(first.out, (models / file).string());
    EXPECT_EQ(status_of(line), "passed over") << line;
    EXPECT_EQ(kind_of(line), "unsupported-format") << line;
  }
  EXPECT_NE(first.err.find("umbra render: passed over " + std::to_string(unsupported) + " files in no format umbra reads: "),
            std::string::npos)
      << first.err;
  for (const auto& [file, status] : expected) {
    const std::string line = line_of(first.out, (models / file).string());
    EXPECT_EQ(status_of(line), status) << file << ": " << line;
    EXPECT_EQ(kind_of(line), status == "timed out" ? "timeout" : status == "failed" ? "malformed" : "null") << line;
    if (status == "drawn") {
      EXPECT_TRUE(fs::exists(out + "/" + file + ".png")) << file;
      EXPECT_NE(line.find("\"error\":null"), std::string::npos) << line;
    }
  }
  EXPECT_NE(line_of(first.out, (models / "hang.off").string()).find("timed out after 5 s (--timeout)"), std::string::npos);
  EXPECT_NE(first.err.find("models/maps/huge.png\": the image is 16384x16384 pixels"), std::string::npos) << first.err;
  EXPECT_NE(first.err.find("fifo.png\": is not a regular file (a FIFO)"), std::string::npos) << first.err;
  EXPECT_NE(first.err.find(": 7 pictures in " + out + ", 2 failed (1 timed out); " + std::to_string(unsupported) +
                           " files passed over\n"),
            std::string::npos)
      << first.err;
  EXPECT_NE(read(out + "/a/x.off.png"), read(out + "/b/x.off.png"));
  EXPECT_EQ(temporaries_in(out), 0u) << "the timed-out worker's picture, made before it hung, is removed";

  // Resumed: nothing drawn again, the failures tried again.
  const auto written_at = fs::last_write_time(out + "/cgal/anchor.off.png");
  const CommandResult second = run(command + " --skip-existing", "", UMBRA_FAULT_INJECTED_EXECUTABLE);
  EXPECT_EQ(second.status, 1);
  EXPECT_EQ(lines(second.out), expected.size() + unsupported);
  for (const auto& [file, status] : expected)
    EXPECT_EQ(status_of(line_of(second.out, (models / file).string())), status == "drawn" ? "skipped" : status) << file;
  EXPECT_EQ(fs::last_write_time(out + "/cgal/anchor.off.png"), written_at);
  EXPECT_NE(second.err.find(": 0 pictures in " + out + ", 7 up to date (--skip-existing), 2 failed (1 timed out); " +
                            std::to_string(unsupported) + " files passed over\n"),
            std::string::npos)
      << second.err;
}

// A crash, a failed allocation and the kernel's OOM killer, each in one file
// of a folder: every other file keeps its picture and its line.
TEST_F(CorpusRender, ACrashOrRunningOutOfMemoryCostsOnlyItsOwnFile) {
  fs::create_directories(folder_ / "models");
  for (const char* name : {"a.off", "crash.off", "b.off", "out-of-memory.off", "c.off", "oom-killed.off", "d.off"})
    write(std::string("models/") + name, kTetrahedron);
  const CommandResult r =
      run("render " + path("models") + " -o " + path("out") + " --size 32x32 --jobs 2 --json", "", UMBRA_FAULT_INJECTED_EXECUTABLE);
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(lines(r.out), 7u) << r.out;
  for (const char* good : {"a.off", "b.off", "c.off", "d.off"}) {
    EXPECT_EQ(status_of(line_of(r.out, path(std::string("models/") + good))), "drawn") << good;
    EXPECT_TRUE(fs::exists(path(std::string("out/") + good + ".png"))) << good;
  }
  EXPECT_NE(line_of(r.out, path("models/crash.off")).find("\"status\":\"crashed\",\"kind\":\"crashed\",\"seconds\":"),
            std::string::npos)
      << r.out;
  // Each failure's kind, to count them by: a failed allocation and the OOM killer alike.
  EXPECT_EQ(kind_of(line_of(r.out, path("models/out-of-memory.off"))), "out-of-memory");
  EXPECT_EQ(kind_of(line_of(r.out, path("models/oom-killed.off"))), "out-of-memory");
  EXPECT_EQ(kind_of(line_of(r.out, path("models/a.off"))), "null");
  // A file with no picture names none (its path would lead nowhere, or to an older picture).
  for (const char* bad : {"crash.off", "out-of-memory.off", "oom-killed.off"})
    EXPECT_NE(line_of(r.out, path(std::string("models/") + bad)).find("\"picture\":null,"), std::string::npos) << bad;
  EXPECT_NE(line_of(r.out, path("models/a.off")).find("\"picture\":\"" + path("out/a.off.png") + "\","), std::string::npos);
  EXPECT_NE(line_of(r.out, path("models/crash.off")).find(": crashed (SIGABRT)\"}"), std::string::npos) << r.out;
  EXPECT_NE(line_of(r.out, path("models/out-of-memory.off")).find("\"status\":\"failed\""), std::string::npos) << r.out;
  EXPECT_NE(line_of(r.out, path("models/out-of-memory.off")).find("not enough memory to render it"), std::string::npos) << r.out;
  EXPECT_NE(line_of(r.out, path("models/oom-killed.off")).find(": killed (SIGKILL: out of memory?)\"}"), std::string::npos)
      << r.out;
  EXPECT_NE(r.err.find(": 4 pictures in " + path("out") + ", 3 failed\n"), std::string::npos) << r.err;
  for (const auto& entry : fs::directory_iterator(path("out")))
    EXPECT_EQ(entry.path().extension(), ".png") << entry.path();  // no temporary file left by the crashes
}

// Each failure's line has a kind beside its message, so that a corpus's
// failures can be counted; a located error names the file's line alone,
// not the line of the scene that umbra staged for it.
TEST_F(CorpusRender, EachFailureHasAKindToCountBy) {
  fs::create_directories(folder_ / "models");
  write("models/empty.obj", "");
  write("models/points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  write("models/broken.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n");
  write("models/photo.obj", std::string("\xff\xd8\xff\xe0\0\x10JFIF\0", 11));
  write("models/good.off", kTetrahedron);
  const CommandResult r = run("render " + path("models") + " -o " + path("out") + " --size 16x16 --json");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(lines(r.out), 5u) << r.out;
  const std::map<std::string, std::string> kinds = {{"empty.obj", "empty"}, {"points.obj", "no-faces"}, {"broken.obj", "malformed"},
                                                    {"photo.obj", "unsupported-format"}, {"good.off", "null"}};
  for (const auto& [file, kind] : kinds) EXPECT_EQ(kind_of(line_of(r.out, path("models/" + file))), kind) << file;
  EXPECT_NE(line_of(r.out, path("models/broken.obj"))
                .find("\"error\":\"" + path("models/broken.obj") + ":4:7: expected a vertex index (as in \\\"f 1 2 3\\\" or "
                      "\\\"f 1/1/1 2/2/2 3/3/3\\\"), got \\\"x\\\"\"}"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.err.find("(staged)"), std::string::npos) << r.err;
}

// Ctrl-C (SIGINT to the whole process group) or SIGTERM to umbra alone stop
// a folder run: the workers are stopped and waited for, and remove their
// temporary files, before umbra says what was drawn and what was not, and
// exits as the signal asks (128 + its number).
TEST_F(CorpusRender, AStoppedRunSaysWhatItDrewAndLeavesNoTemporaryFile) {
  fs::create_directories(folder_ / "models");
  for (const char* name : {"a.off", "hang-1.off", "hang-2.off", "z.off"}) write(std::string("models/") + name, kTetrahedron);
  for (const auto& [kill, signal, status] : {std::tuple{"kill -INT -- -$pid", "SIGINT", 130}, {"kill -TERM $pid", "SIGTERM", 143}}) {
    fs::remove_all(path("out"));
    // Each worker hangs on a file whose picture's temporary file it has made;
    // setsid makes umbra a process group's leader, as a shell's job is.
    const std::string script = "setsid " + std::string(UMBRA_FAULT_INJECTED_EXECUTABLE) + " render " + path("models") + " -o " +
                               path("out") + " --size 16x16 --jobs 2 --json & pid=$!; " +
                               "for i in $(seq 600); do [ -e " + path("out/a.off.png") + " ] && [ $(ls " + path("out") +
                               " | grep -c partial) = 2 ] && break; " +
                               "sleep 0.1; done; ls " + path("out") + " | grep -c partial >&2; " + kill + "; wait $pid";
    const CommandResult r = run("-c " + shell_quoted(script), "", "bash");
    EXPECT_EQ(r.status, status) << r.err;
    EXPECT_EQ(r.err.substr(0, 2), "2\n") << "both hanging workers had a temporary file: " << r.err;
    EXPECT_EQ(temporaries_in(path("out")), 0u) << signal;
    EXPECT_TRUE(fs::exists(path("out/a.off.png")));
    EXPECT_EQ(lines(r.out), 4u) << r.out;
    EXPECT_EQ(status_of(line_of(r.out, path("models/a.off"))), "drawn");
    for (const char* name : {"hang-1.off", "hang-2.off", "z.off"})
      EXPECT_NE(line_of(r.out, path(std::string("models/") + name))
                    .find("\"status\":\"stopped\",\"kind\":\"stopped\",\"seconds\":0.0,\"triangles\":0,\"error\":\"" + path(std::string("models/") + name) +
                          ": not drawn: umbra was stopped (" + signal + ")\"}"),
                std::string::npos)
          << r.out;
    EXPECT_NE(r.err.find(": 1 picture in " + path("out") + ", 0 failed\numbra render: stopped (" + std::string(signal) +
                         "): 3 of 4 files not drawn; the same command with --skip-existing draws only those\n"),
              std::string::npos)
        << r.err;
  }
}

TEST_F(CorpusRender, TheCorpusOptionsAreForSeveralFiles) {
  const std::string tet = write("t.off", kTetrahedron);
  for (const char* option : {"--timeout 3", "--skip-existing", "--json"}) {
    const CommandResult r = run("render " + tet + " -o " + path("t.png") + " " + option);
    EXPECT_EQ(r.status, 2) << option;
    EXPECT_EQ(r.err, "umbra render: " + std::string(option).substr(0, std::string(option).find(' ')) +
                         " is for several files or a folder; \"" + tet + "\" is one\n(see umbra render --help)\n");
  }
  const CommandResult zero = run("render " + tet + " " + tet + " -o " + path("out") + " --timeout 0");
  EXPECT_EQ(zero.status, 2);
  EXPECT_EQ(zero.err, "umbra render: --timeout must be a number of seconds above 0, got \"0\"\n(see umbra render --help)\n");
}

}  // namespace
}  // namespace umbra
