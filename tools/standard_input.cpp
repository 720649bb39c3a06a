#include "tools/standard_input.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace umbra {

StandardInputFile::StandardInputFile(const std::string& path) : path_(path) {
  if (path != "-") return;
  if (::isatty(STDIN_FILENO))
    throw std::runtime_error("-: standard input is a terminal: pipe a file in, as in umbra render - -o out.png < model.stl");
  std::string folder = (std::filesystem::temp_directory_path() / "umbra-stdin-XXXXXX").string();
  if (!::mkdtemp(folder.data())) throw std::runtime_error(std::string("-: cannot copy standard input: ") + std::strerror(errno));
  folder_ = folder;
  path_ = folder + "/standard-input";
  // Copied whole: a pipe can be read once, and the readers map files.
  std::string failure;
  {
    std::ofstream out(path_, std::ios::binary);
    if (std::cin.peek() == std::char_traits<char>::eof())
      failure = "standard input is empty: pipe a file in, as in umbra render - -o out.png < model.stl";
    else if (!(out << std::cin.rdbuf()) || !out.flush())
      failure = "cannot copy standard input to " + path_;
  }
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
