#include "did_you_mean.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

namespace catena::model::detail {
namespace {

std::string lower_case(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool is_prefix(std::string_view prefix, std::string_view word) {
  return prefix.size() >= 3 && word.size() > prefix.size() && word.starts_with(prefix);
}

}  // namespace

std::size_t levenshtein_distance(std::string_view a, std::string_view b) {
  // Two-row dynamic programme: row[j] = distance between a[0, i) and b[0, j).
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

std::string closest_match(std::string_view word, std::span<const std::string> candidates) {
  constexpr std::size_t max_distance = 2;
  const std::string needle = lower_case(word);
  const std::string* best = nullptr;
  std::size_t best_distance = max_distance + 1;
  for (const std::string& candidate : candidates) {
    const std::size_t d = levenshtein_distance(needle, lower_case(candidate));
    // A one-letter word is within distance 2 of every short key; only suggest on a real
    // resemblance (fewer edits than the word has letters).
    if (d < best_distance && d < needle.size()) {
      best = &candidate;
      best_distance = d;
    }
  }
  if (best) return *best;
  for (const std::string& candidate : candidates) {
    const std::string lowered = lower_case(candidate);
    if (is_prefix(needle, lowered) || is_prefix(lowered, needle)) return candidate;
  }
  return {};
}

std::string did_you_mean(std::string_view word, std::span<const std::string> candidates) {
  const std::string match = closest_match(word, candidates);
  return match.empty() ? std::string() : " did you mean '" + match + "'?";
}

}  // namespace catena::model::detail
