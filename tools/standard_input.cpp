#include "tools/standard_input.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <vector>

#include "mesh/io/mesh_format.hpp"

namespace umbra {
namespace {

constexpr size_t kHeadBytes = 1 << 16;          // what a format is told by (mesh_format.hpp)
constexpr size_t kMostBytes = size_t(4) << 30;          // a copy's limit: more is a file to name, not a pipe
constexpr size_t kChunkBytes = size_t(1) << 20;

}  // namespace

StandardInputFile::StandardInputFile(const std::string& path) : path_(path) {
  if (path != "-") return;
  if (::isatty(STDIN_FILENO))
    throw std::runtime_error("-: standard input is a terminal: pipe a file in, as in umbra render - -o out.png < model.stl");
  std::string folder = (std::filesystem::temp_directory_path() / "umbra-stdin-XXXXXX").string();
  if (!::mkdtemp(folder.data())) throw std::runtime_error(std::string("-: cannot copy standard input: ") + std::strerror(errno));
  folder_ = folder;
  path_ = folder + "/standard-input";
  listed_folder_.emplace(folder_, RemovedOnSignals::Kind::kFolder);
  listed_copy_.emplace(path_);
  // Copied, since a pipe can be read once and the readers map files; its
  // start looked at first, so that input plainly no scene or mesh (a JPEG,
  // a stream of zeros: a binary file past the size a binary STL's count
  // allows) stops the copy there, and the readers refuse it at once.
  std::string failure;
  std::FILE* out = std::fopen(path_.c_str(), "wb");
  if (!out) failure = "cannot copy standard input to " + path_ + ": " + std::strerror(errno);
  std::string head;
  std::optional<size_t> most;
  bool looked = false;
  std::vector<char> chunk(kChunkBytes);
  for (size_t copied = 0; failure.empty();) {
    const ssize_t n = ::read(STDIN_FILENO, chunk.data(), chunk.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) failure = std::string("cannot read standard input: ") + std::strerror(errno);
    if (n <= 0) break;
    if (head.size() < kHeadBytes) head.append(chunk.data(), std::min(size_t(n), kHeadBytes - head.size()));
    const size_t keep = std::min(size_t(n), kMostBytes + 1 - copied);
    if (std::fwrite(chunk.data(), 1, keep, out) != keep) failure = "cannot copy standard input to " + path_ + ": " + std::strerror(errno);
    copied += keep;
    if (copied > kMostBytes) failure = "standard input holds more than 4 GiB: save it to a file and name the file";
    if (!looked && head.size() == kHeadBytes) {
      looked = true;
      if (!other_known_format(head).empty()) break;
      most = most_bytes_of_input(head);
    }
    if (most && copied > *most) break;
  }
  if (out && std::fclose(out) != 0 && failure.empty()) failure = "cannot copy standard input to " + path_ + ": " + std::strerror(errno);
  if (failure.empty() && head.empty()) failure = "standard input is empty: pipe a file in, as in umbra render - -o out.png < model.stl";
  if (!failure.empty()) {
    std::error_code ignored;
    std::filesystem::remove_all(folder_, ignored);
    throw std::runtime_error("-: " + failure);
  }
}

StandardInputFile::~StandardInputFile() {
  if (folder_.empty()) return;
  std::error_code ignored;
  std::filesystem::remove_all(folder_, ignored);
}

}  // namespace umbra
