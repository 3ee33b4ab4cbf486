#pragma once
// How much of a world file is read, at most (docs/limits.md). Stage's own
// worlds are a few KB; the largest, benchmark/hospital.world with its
// includes, about 20 KB.

#include <cstddef>

namespace playerkit::sim::worldfile {

// The text of one world, its main file and every included file together.
inline constexpr std::size_t kMaxWorldFileBytes = std::size_t{1} << 20;
// Includes within includes (Stage's worlds nest one deep).
inline constexpr int kMaxWorldIncludeDepth = 16;
// Include statements read in one world, a file included twice counting twice.
inline constexpr int kMaxWorldIncludedFiles = 256;
// Entities within entities, macros expanded: the expander recurses (Stage's
// worlds nest three deep: robot, ranger, sensor).
inline constexpr int kMaxEntityDepth = 32;
// Entities and property assignments once macros are expanded. A macro made
// of two copies of another doubles at each level; this bounds the memory to
// that of the largest plain file. Real worlds have a few thousand.
inline constexpr std::size_t kMaxWorldItems = 1'000'000;

}  // namespace playerkit::sim::worldfile
