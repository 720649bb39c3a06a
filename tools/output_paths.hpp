#pragma once
// What an output's name may be: a picture umbra writes, and never the input.

#include <string>

namespace umbra {

// A UsageError when `path`, given to `option`, is not a picture's name that
// umbra writes (picture_file.hpp): .png, .jpg, .jpeg, or - for standard output.
void require_picture_name(const std::string& option, const std::string& path);

// Whether `a` and `b` name one file: the same words, or one file by two
// names (links, "./"), or, where one does not exist yet, the same path once
// made absolute and resolved as far as it exists.
bool same_file(const std::string& a, const std::string& b);
// A UsageError when the output `option` names would overwrite the input `input`.
void require_other_than_input(const std::string& option, const std::string& output, const std::string& input);

}  // namespace umbra
