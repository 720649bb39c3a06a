#include "tools/nearest_word.hpp"

#include <algorithm>

namespace umbra {
namespace {

// The optimal string alignment distance: Levenshtein's, with a swap of two
// neighbouring letters counting as one edit.
size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

}  // namespace

std::string nearest_word(const std::string& typed, const std::vector<std::string>& known) {
  std::string best;
  size_t best_distance = 0;
  for (const std::string& word : known) {
    const size_t distance = edit_distance(typed, word);
    if (3 * distance > std::max(typed.size(), word.size())) continue;
    if (best.empty() || distance < best_distance) best = word, best_distance = distance;
  }
  return best;
}

std::string did_you_mean(const std::string& typed, const std::vector<std::string>& known) {
  const std::string word = nearest_word(typed, known);
  return word.empty() ? "" : " (did you mean " + word + "?)";
}

}  // namespace umbra
