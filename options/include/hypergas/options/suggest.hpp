// hypergas/options/suggest.hpp -- "did you mean ...?" for a misspelt name: the command's
// options and subcommands, a sweep plan's keys and the Python keywords use the same rule.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace hypergas::options {

/// The edit distance between a and b: insertions, deletions, substitutions and swaps of two
/// neighbouring characters each count 1 (optimal string alignment).
int edit_distance(std::string_view a, std::string_view b);

/// The candidate closest to `name` if it is near: at most 1 edit for names of up to 4
/// characters, 2 up to 8, 3 beyond (one slip of the fingers per word); the first of equals.
/// Empty when none is near.
std::string nearest(std::string_view name, const std::vector<std::string>& candidates);

/// "; did you mean 'X'?" for nearest(name, candidates) = X (X written as `quote` + X +
/// `quote`), or "" when no candidate is near.
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates,
                         std::string_view quote = "'");

}  // namespace hypergas::options
