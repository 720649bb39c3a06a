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

// What kind of problem an input has, for those who count them over a corpus
// (umbra render --json): one name each, in input_problem_name.
enum class InputProblem {
  kMalformed,          // the file's content is wrong (the default)
  kUnreadable,         // the file cannot be opened or read
  kUnsupportedFormat,  // no scene and no mesh format umbra reads
  kEmpty,              // no bytes, or blank lines alone
  kNoFaces,            // a mesh with no face to show
};
// "malformed", "unreadable", "unsupported-format", "empty", "no-faces".
const char* input_problem_name(InputProblem problem);

class InputError : public std::runtime_error {
 public:
  InputError(FileLoc where, const std::string& message, InputProblem problem = InputProblem::kMalformed)
      : std::runtime_error(where.str() + ": " + message), where_(std::move(where)), message_(message), problem_(problem) {}
  const FileLoc& where() const { return where_; }
  const std::string& message() const { return message_; }  // without the location
  InputProblem problem() const { return problem_; }

 private:
  FileLoc where_;
  std::string message_;
  InputProblem problem_;
};

}  // namespace umbra
