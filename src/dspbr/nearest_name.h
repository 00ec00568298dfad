// The nearest valid name to a mistyped one, for "did you mean ...?" in error messages (the CLI's
// subcommands and options, material parameter ids).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace dspbr {

// Levenshtein distance: insertions, deletions and substitutions of one character.
std::size_t edit_distance(const std::string& a, const std::string& b);

// The name of `names` that is `word` in another case ('ggx_e' -> 'GGX_E'); else the one nearest
// to `word` when at most `max_edits` edits away (the first of equals); else the first name that
// `word` (3 characters or more) begins, ignoring case ('sheen' -> 'sheenColor'); else "".
std::string nearest_name(const std::string& word, const std::vector<std::string>& names, std::size_t max_edits = 2);

// "; did you mean 'NAME'?" for the nearest_name of word, else "" (appended to an error message).
std::string did_you_mean(const std::string& word, const std::vector<std::string>& names);

}  // namespace dspbr
