#include "tools/standard_input.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace umbra {

StandardInputFile::StandardInputFile(const std::string& path) : path_(path) {
  if (path != "-") return;
  if (::isatty(STDIN_FILENO))
    throw std::runtime_error("-: standard input is a terminal: pipe a file in, as in umbra render - -o out.png < model.stl");
  std::string folder = (std::filesystem::temp_directory_path() / "umbra-stdin-XXXXXX").string();
  if (!::mkdtemp(folder.data())) throw std::runtime_error(std::string("-: cannot copy standard input: ") + std::strerror(errno));
  folder_ = folder;
  path_ = folder + "/standard-input";
  const int out = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (out < 0) throw std::runtime_error(std::string("-: cannot copy standard input: ") + std::strerror(errno));
  std::vector<char> buffer(1 << 20);
  std::string failure;
  size_t copied = 0;
  for (;;) {
    const ssize_t got = ::read(STDIN_FILENO, buffer.data(), buffer.size());
    if (got == 0) {
      if (copied == 0) failure = "standard input is empty: pipe a file in, as in umbra render - -o out.png < model.stl";
      break;
    }
    copied += size_t(std::max<ssize_t>(got, 0));
    if (got < 0) {
      if (errno == EINTR) continue;
      failure = std::string("cannot read standard input: ") + std::strerror(errno);
      break;
    }
    for (ssize_t written = 0; written < got && failure.empty();) {
      const ssize_t n = ::write(out, buffer.data() + written, size_t(got - written));
      if (n < 0 && errno != EINTR) failure = std::string("cannot copy standard input: ") + std::strerror(errno);
      if (n > 0) written += n;
    }
    if (!failure.empty()) break;
  }
  ::close(out);
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
