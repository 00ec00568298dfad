// The nearest valid name to a mistyped one, for "did you mean ...?" in error messages (the CLI's
// subcommands and options, material parameter ids).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace dspbr {

// Levenshtein distance: insertions, deletions and substitutions of one character.
std::size_t edit_distance(const std::string& a, const std::string& b);

// The name of `names` nearest to `word` when at most `max_edits` edits away (the first of equals),
// else "".
std::string nearest_name(const std::string& word, const std::vector<std::string>& names, std::size_t max_edits = 2);

}  // namespace dspbr
