#pragma once
// A located error in user input, printed like a compiler's:
// "scenes/two.scene:7:12: expected a number for the sphere radius, got "O.5"".

#include <stdexcept>
#include <string>

namespace umbra {

struct FileLoc {
  std::string file;
  int line = 0;    // 1-based; 0 when the error concerns the whole file
  int column = 0;  // 1-based; 0 when unknown

  std::string str() const;  // "file:line:col", "file:line" or "file"
};

class InputError : public std::runtime_error {
 public:
  InputError(FileLoc where, const std::string& message)
      : std::runtime_error(where.str() + ": " + message), where_(std::move(where)), message_(message) {}
  const FileLoc& where() const { return where_; }
  const std::string& message() const { return message_; }  // without the location

 private:
  FileLoc where_;
  std::string message_;
};

}  // namespace umbra
