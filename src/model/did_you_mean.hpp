#pragma once
// Suggestions for misspelt names (keys, section types, section names, support kinds), so
// that "unknown key 'mass_per_lenght'" comes with "did you mean 'mass_per_length'?".
#include <cstddef>
#include <span>
#include <string>
#include <string_view>

namespace catena::model::detail {

// Not collective. Edit distance with unit-cost insertion, deletion and substitution.
std::size_t levenshtein_distance(std::string_view a, std::string_view b);

// Not collective. The candidate closest to `word` (case-insensitive) if it is within edit
// distance 2, or else the first candidate that `word` is a prefix of, or that is a prefix of
// `word` (both at least 3 characters: shorter prefixes suggest nonsense); "" if none.
std::string closest_match(std::string_view word, std::span<const std::string> candidates);

// Not collective. " did you mean 'X'?" for the closest match, or "" if there is none.
std::string did_you_mean(std::string_view word, std::span<const std::string> candidates);

}  // namespace catena::model::detail
