#pragma once
// Words joined as a sentence lists them: "a, b or c". Messages and usage
// texts that list formats, methods or keywords all join them this way.

#include <string>
#include <string_view>
#include <vector>

namespace umbra {

template <typename Word>
std::string word_list(const std::vector<Word>& words, std::string_view last_joiner = "or") {
  std::string s;
  for (size_t i = 0; i < words.size(); ++i) {
    if (i > 0) s += i + 1 == words.size() ? " " + std::string(last_joiner) + " " : std::string(", ");
    s += std::string_view(words[i]);
  }
  return s;
}

}  // namespace umbra
