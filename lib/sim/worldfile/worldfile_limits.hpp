#pragma once
// How much of a world file is read, at most (docs/limits.md). World files
// are a few KB written by hand (data/worlds' are 1.2 to 1.8 KB).

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

// Rays of one laser scan or blobfinder image row. Each costs memory and a
// ray cast per update; the densest real worlds have 1081 (a Hokuyo in
// stage_ros's willow-erratic.world).
inline constexpr int kMaxSensorSamples = 100'000;
// The extent of a world, in metres along x and along y: Stage's benchmark
// hospital is 140 m across. Beyond this a typo (a size of 1e30) would only
// make a map of absurd cells.
inline constexpr double kMaxWorldExtent = 1.0e6;

}  // namespace playerkit::sim::worldfile
