#include "protocols/format/edit_distance.h"

#include <algorithm>
#include <cctype>

namespace protocols {

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

std::vector<std::string> nearestNames(std::string_view word,
                                      std::span<const std::string_view> candidates) {
  // Case differences ("od" for "OD", "Supine") count as one edit in total, not one per letter.
  auto lower = [](std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
  };
  const std::string lowerWord = lower(word);
  // Scores in half edits: a difference of case only scores 1, any other edit 2, so "od"
  // suggests "OD" and not also "OS".
  const std::size_t threshold = 2 * std::max<std::size_t>(2, word.size() / 3);
  std::size_t best = threshold + 1;
  std::vector<std::string> names;
  for (std::string_view candidate : candidates) {
    std::size_t score = 2 * editDistance(lowerWord, lower(candidate));
    if (score == 0 && candidate != word) score = 1;
    // A truncated or extended name ("elastic" for "elasticity") is a likely slip however many
    // letters are missing.
    const std::string lowerCandidate = lower(candidate);
    const bool isPrefix = lowerWord.size() >= 4 && (lowerCandidate.starts_with(lowerWord) ||
                                                    lowerWord.starts_with(lowerCandidate));
    if (isPrefix) score = std::min(score, threshold);
    if (score > threshold || score > best) continue;
    if (score < best) names.clear();
    best = score;
    names.emplace_back(candidate);
  }
  return names;
}

std::string didYouMean(std::string_view word, std::span<const std::string_view> candidates) {
  const std::vector<std::string> names = nearestNames(word, candidates);
  if (names.empty()) return {};
  std::string text = "did you mean ";
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (k > 0) text += k + 1 == names.size() ? " or " : ", ";
    text += "'" + names[k] + "'";
  }
  return text + "?";
}

std::string joinNames(std::span<const std::string_view> names, bool quote) {
  std::string text;
  for (std::string_view name : names) {
    if (!text.empty()) text += ", ";
    if (quote) text += '\'';
    text += name;
    if (quote) text += '\'';
  }
  return text;
}

}  // namespace protocols
