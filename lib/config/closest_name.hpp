#pragma once
// "Did you mean ...?" suggestions for misspelt interface and driver names.

#include <cstddef>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace playerkit::config {

// Names longer than this get no suggestion: no driver or interface name is
// longer than 24 characters, and the search costs time in the length of the
// word (a 1 MB driver name took 13 s before this limit).
inline constexpr std::size_t kMaxSuggestedNameBytes = 64;

// Edits (insert, delete, replace, swap two neighbours) needed to turn a into
// b, or limit + 1 as soon as it is known to be more than `limit` (the search
// then stops early: the distance of a long word to a short name is found
// without going through the whole word).
std::size_t edit_distance(std::string_view a, std::string_view b,
                          std::size_t limit = std::numeric_limits<std::size_t>::max() - 1);

// The candidate nearest to `word`, if it is close enough to be a plausible typo
// (at most one edit per three characters, and at least one allowed). Ties go
// to the earlier candidate. None for words over kMaxSuggestedNameBytes.
std::optional<std::string> closest_name(std::string_view word,
                                        std::span<const std::string_view> candidates);

}  // namespace playerkit::config
