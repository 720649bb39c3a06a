#pragma once
// "Did you mean": the known word nearest a mistyped one, for unknown
// commands and options.

#include <string>
#include <vector>

namespace umbra {

// The word of `known` nearest `typed` by edit distance (insertions,
// deletions, substitutions and swaps of neighbours, each 1: Damerau 1964),
// when it is at most a third of the longer word's length away, so that only
// a slip of the fingers is corrected; "" when none is that near.
std::string nearest_word(const std::string& typed, const std::vector<std::string>& known);

// " (did you mean WORD?)" for nearest_word's answer, or "".
std::string did_you_mean(const std::string& typed, const std::vector<std::string>& known);

}  // namespace umbra
