#pragma once
// "Did you mean ...?" suggestions for misspelt interface and driver names.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace playerkit::config {

// Edits (insert, delete, replace, swap two neighbours) needed to turn a into b.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate nearest to `word`, if it is close enough to be a plausible typo
// (at most one edit per three characters, and at least one allowed). Ties go
// to the earlier candidate.
std::optional<std::string> closest_name(std::string_view word,
                                        std::span<const std::string_view> candidates);

}  // namespace playerkit::config
