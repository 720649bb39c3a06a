#include "tools/output_paths.hpp"

#include <filesystem>

#include "image/animation_file.hpp"
#include "image/picture_file.hpp"
#include "tools/command_options.hpp"

namespace umbra {

bool same_file(const std::string& a, const std::string& b) {
  std::error_code ec, ea, eb;
  if (a == b || std::filesystem::equivalent(a, b, ec)) return true;
  // Names of files that need not exist yet (a picture about to be drawn):
  // the same once made absolute and resolved as far as they exist.
  const std::filesystem::path ca = std::filesystem::weakly_canonical(std::filesystem::absolute(a, ea), ea);
  const std::filesystem::path cb = std::filesystem::weakly_canonical(std::filesystem::absolute(b, eb), eb);
  return !ea && !eb && ca == cb;
}

void require_other_than_input(const std::string& option, const std::string& output, const std::string& input) {
  if (input == "-") return;  // standard input, read whole before anything is written
  if (same_file(output, input)) throw UsageError(option + " would overwrite its input \"" + input + "\"; name another file");
}

void require_picture_name(const std::string& option, const std::string& path) {
  if (picture_format_of(path)) return;
  const std::string extension = std::filesystem::path(path).extension().string();
  // An animation's name, for a picture: the option that makes one is missing.
  if (animation_format_of(path))
    throw UsageError(option + " " + path + " names an animation, which --turntable N makes (or --views N); a picture is a " +
                     picture_extensions() + " file");
  throw UsageError(option + " " + path + (extension.empty() ? " has no extension" : ": umbra does not write " + extension + " pictures") +
                   "; name a " + picture_extensions() + " file, or - for PNG on standard output");
}

}  // namespace umbra
