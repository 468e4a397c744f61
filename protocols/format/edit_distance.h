// "Did you mean": the nearest names to a misspelt one, by Levenshtein distance
// (Levenshtein 1966; the classic two-row dynamic programme, O(|a| |b|)).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace protocols {

// Number of single-character insertions, deletions and substitutions turning a into b.
std::size_t editDistance(std::string_view a, std::string_view b);

// The candidates closest to `word` (all ties), if close enough to be a plausible typo: within
// a third of the word's length (at least 2 edits), or one a prefix of the other (4+ letters).
// Empty when nothing is close.
std::vector<std::string> nearestNames(std::string_view word,
                                      std::span<const std::string_view> candidates);

// "did you mean 'a' or 'b'?" for nearestNames(), or "" when there is no close candidate.
std::string didYouMean(std::string_view word, std::span<const std::string_view> candidates);

// "a, b, c" (each quoted when `quote`).
std::string joinNames(std::span<const std::string_view> names, bool quote = false);

}  // namespace protocols
