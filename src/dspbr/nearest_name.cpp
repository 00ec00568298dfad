#include "dspbr/nearest_name.h"

#include <algorithm>
#include <cctype>

namespace dspbr {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string nearest_name(const std::string& word, const std::vector<std::string>& names, std::size_t max_edits) {
  // `n` begins with `word`, ignoring case (n at least as long).
  const auto begins_with_word = [&](const std::string& n) {
    const auto lower = [](unsigned char c) { return static_cast<char>(std::tolower(c)); };
    return n.size() >= word.size() &&
           std::equal(word.begin(), word.end(), n.begin(), [&](char a, char b) { return lower(a) == lower(b); });
  };
  // The name itself in another case first (the tenth fresh tester's pass: 'ggx_e' was offered
  // 'GGX_E_avg', three case changes being more edits than allowed).
  for (const std::string& n : names)
    if (n.size() == word.size() && begins_with_word(n)) return n;
  std::string nearest;
  std::size_t best = max_edits + 1;
  for (const std::string& n : names) {
    const std::size_t d = edit_distance(word, n);
    if (d < best) best = d, nearest = n;
  }
  if (!nearest.empty() || word.size() < 3) return nearest;
  for (const std::string& n : names)
    if (n.size() > word.size() && begins_with_word(n)) return n;
  return nearest;
}

std::string did_you_mean(const std::string& word, const std::vector<std::string>& names) {
  const std::string near = nearest_name(word, names);
  return near.empty() ? "" : "; did you mean '" + near + "'?";
}

}  // namespace dspbr
