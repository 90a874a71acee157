// "Did you mean": the known names closest to a misspelt one, by edit distance (Levenshtein:
// insertions, deletions and substitutions of one character each count 1). Used wherever a name
// from a user is refused: case-file keys, parameters, mutants.
#pragma once

#include <string>
#include <vector>

namespace gt {

std::size_t edit_distance(const std::string& a, const std::string& b);

// The known names at the smallest edit distance from `name`, in their given order, when that
// distance is at most a third of the longer name's length (plus one); otherwise none.
std::vector<std::string> closest_names(const std::string& name, const std::vector<std::string>& known);

// " (did you mean 'a' or 'b'?)", or "" when nothing is close.
std::string did_you_mean(const std::string& name, const std::vector<std::string>& known);

}  // namespace gt
