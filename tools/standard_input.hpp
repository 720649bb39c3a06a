#pragma once
// "-" named as an input file: standard input, copied whole into a private
// temporary file, since its format is found by its content and the readers
// map files. The copy is named "standard-input" in a folder of its own, so
// that messages about it say where it came from.

#include <string>

namespace umbra {

class StandardInputFile {
 public:
  // For "-", copies standard input (throws std::runtime_error when it is a
  // terminal or empty, or cannot be read or copied); any other path is used
  // as it is.
  explicit StandardInputFile(const std::string& path);
  ~StandardInputFile();  // removes the copy and its folder
  StandardInputFile(const StandardInputFile&) = delete;
  StandardInputFile& operator=(const StandardInputFile&) = delete;

  // Where to read the input from.
  const std::string& path() const { return path_; }

 private:
  std::string path_, folder_;
};

}  // namespace umbra
