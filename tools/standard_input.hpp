#pragma once
// "-" named as an input file: standard input, copied into a private
// temporary file, since its format is found by its content and the readers
// map files. The copy is named "standard-input" in a folder of its own, so
// that messages about it say where it came from, and removed with its
// folder however umbra ends but by SIGKILL. At most 4 GiB is copied, and
// less where its start shows it is no scene or mesh.

#include <optional>
#include <string>

#include "image/partial_file.hpp"

namespace umbra {

class StandardInputFile {
 public:
  // For "-", copies standard input (throws std::runtime_error when it is a
  // terminal, empty or over 4 GiB, or cannot be read or copied); any other
  // path is used as it is.
  explicit StandardInputFile(const std::string& path);
  ~StandardInputFile();  // removes the copy and its folder
  StandardInputFile(const StandardInputFile&) = delete;
  StandardInputFile& operator=(const StandardInputFile&) = delete;

  // Where to read the input from.
  const std::string& path() const { return path_; }

 private:
  std::string path_, folder_;
  std::optional<RemovedOnSignals> listed_folder_, listed_copy_;
};

}  // namespace umbra
