// Replays the fuzzers' seed corpus and every input they crashed on through
// the same entry points, in the ordinary build: each must return normally.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz/format_byte.hpp"
#include "fuzz/fuzz_entries.hpp"
#include "mesh/io/mesh_file.hpp"
#include "mesh/io/mesh_format.hpp"

namespace umbra {
namespace {

namespace fs = std::filesystem;

std::vector<uint8_t> bytes_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Git keeps no empty folder, so a target with no regressions yet has none.
std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  if (!fs::is_directory(dir)) return files;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
  return files;
}

const fs::path kSource = UMBRA_SOURCE_DIR;

TEST(FuzzRegressions, SceneInputsReturnNormally) {
  const auto regressions = files_in(kSource / "fuzz/regressions/scene");
  auto inputs = regressions;
  for (const fs::path& p : files_in(kSource / "scenes"))
    if (p.extension() == ".scene") inputs.push_back(p);
  for (const fs::path& p : inputs) {
    SCOPED_TRACE(p.string());
    const std::vector<uint8_t> bytes = bytes_of(p);
    fuzz::scene_input(bytes.data(), bytes.size());
  }
  EXPECT_GT(inputs.size(), regressions.size());
}

TEST(FuzzRegressions, CamerasInputsReturnNormally) {
  auto inputs = files_in(kSource / "fuzz/regressions/cameras");
  const auto seeds = files_in(kSource / "fuzz/seeds/cameras");
  ASSERT_FALSE(seeds.empty());
  inputs.insert(inputs.end(), seeds.begin(), seeds.end());
  for (const fs::path& p : inputs) {
    SCOPED_TRACE(p.string());
    const std::vector<uint8_t> bytes = bytes_of(p);
    fuzz::cameras_input(bytes.data(), bytes.size());
  }
}

// The regressions and the seeds are stored as files under their own names,
// and given to the fuzzer as it sees them: the format's byte, then the file.
TEST(FuzzRegressions, MeshInputsReturnNormally) {
  std::vector<std::vector<uint8_t>> inputs;
  const std::vector<fs::path> regressions = files_in(kSource / "fuzz/regressions/mesh");
  ASSERT_FALSE(regressions.empty());
  std::vector<fs::path> seeds = regressions;
  for (const fs::path& p : files_in(kSource / "scenes/meshes")) seeds.push_back(p);
  for (const fs::path& p : files_in(kSource / "fuzz/seeds/mesh")) seeds.push_back(p);
  for (const fs::path& p : seeds) {
    const std::optional<uint8_t> byte = fuzz::mesh_format_byte_of(p.string());
    const bool regression = std::find(regressions.begin(), regressions.end(), p) != regressions.end();
    EXPECT_TRUE(byte || !regression) << p << " is named as no format the fuzzer reads";
    if (!byte) continue;
    EXPECT_EQ(mesh_format_of(fuzz::mesh_format_name_of_byte(*byte)), mesh_format_of(p.string()));
    std::vector<uint8_t> bytes = bytes_of(p);
    bytes.insert(bytes.begin(), *byte);
    inputs.push_back(bytes);
  }
  ASSERT_GE(inputs.size(), 7u);
  for (const auto& bytes : inputs) fuzz::mesh_input(bytes.data(), bytes.size());
}

// A format added to the table takes its own byte and a share of the bytes
// below it; every other byte keeps its meaning (a fuzzer's corpus and its
// regressions mean what they meant), and every extension's own byte names it.
TEST(FuzzFormatByte, ARowAddedMovesOnlyTheBytesItTakes) {
  const std::vector<std::string_view> formats{".obj", ".off", ".ply", ".stl", ".gltf", ".3mf"};
  std::vector<std::string_view> more = formats;
  more.push_back(".vtk");
  const auto before = fuzz::byte_meanings(formats), after = fuzz::byte_meanings(more);
  int moved = 0;
  for (size_t byte = 0; byte < 256; ++byte) {
    EXPECT_TRUE(after[byte] == before[byte] || after[byte] == ".vtk") << byte;
    moved += after[byte] != before[byte];
  }
  EXPECT_GT(moved, 0);
  EXPECT_LT(moved, 128) << "a new row should take a share of the bytes, not most of them";
  for (const std::string_view extension : formats) EXPECT_NE(std::count(before.begin(), before.end(), extension), 0) << extension;
  for (const MeshFormat& format : mesh_formats()) {
    if (const auto byte = fuzz::mesh_format_byte_of("a" + std::string(format.extensions.front())); byte && format.fuzzed) {
      EXPECT_EQ(fs::path(fuzz::mesh_format_name_of_byte(*byte)).extension(), format.extensions.front());
    }
  }
}

// Stored as files under their own name: library_fuzzer's numbering of
// extensions depends on the libraries a build has.
TEST(FuzzRegressions, LibraryInputsReturnNormally) {
  const auto inputs = files_in(kSource / "fuzz/regressions/library");
  ASSERT_FALSE(inputs.empty());
  for (const fs::path& p : inputs) {
    SCOPED_TRACE(p.string());
    const std::optional<uint8_t> byte = fuzz::mesh_format_byte_of(p.string(), fuzz::Readers::kEvery);
    if (!byte) continue;  // a format this build does not read
    EXPECT_EQ(fs::path(fuzz::mesh_format_name_of_byte(*byte, fuzz::Readers::kEvery)).extension(), p.extension());
    std::vector<uint8_t> bytes = bytes_of(p);
    bytes.insert(bytes.begin(), *byte);
    fuzz::library_input(bytes.data(), bytes.size());
  }
}

}  // namespace
}  // namespace umbra
