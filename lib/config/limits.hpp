#pragma once
// How much of a configuration is read, at most. A configuration is a few KB
// written by hand (the largest of the manual's examples is 2 KB); without
// limits, `include "/dev/zero"` grew to 1.5 GB in 6 s. docs/limits.md lists
// these with every other reader's.

#include <cstddef>

namespace playerkit::config {

// The text of one configuration, its main file and every included file
// together: 500 times the largest real one. Tokens take up to ~100 bytes of
// memory per byte of text (a token keeps its file name), so this also bounds
// the parser's memory (~150 MB at worst, measured).
inline constexpr std::size_t kMaxConfigBytes = std::size_t{1} << 20;
// A line of a configuration: a tuple of some 8000 numbers.
inline constexpr std::size_t kMaxConfigLineBytes = std::size_t{64} << 10;
// Sections within sections, macros expanded (1.5's configurations nest two:
// a robot section around devices).
inline constexpr int kMaxSectionDepth = 32;
// Sections and property values once macros are expanded. A macro made of two
// copies of another doubles in size at each level (30 lines would make a
// billion sections); this bounds the memory to that of kMaxConfigBytes of
// plain text. Real configurations have a few hundred.
inline constexpr std::size_t kMaxConfigItems = 1'000'000;
// Includes within includes (the manual's examples nest one deep).
inline constexpr int kMaxIncludeDepth = 16;
// Include statements read in one configuration, a file included twice
// counting twice.
inline constexpr int kMaxIncludedFiles = 256;

}  // namespace playerkit::config
