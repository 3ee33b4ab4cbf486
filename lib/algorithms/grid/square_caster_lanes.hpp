#pragma once
// Inside SquareCaster: what square_caster.cpp (which starts every ray of a
// batch) hands to square_caster_avx2.cpp (which walks them sixteen at a
// time). Not for other callers.

#include <cstddef>
#include <cstdint>
#include <span>

namespace playerkit::grid::lanes {

// What both walks must agree on, for the same answers bit for bit.
// A direction component this small counts as 0: its crossings are then
// "never" (kNeverInverse times the distance, finite so that no inf * 0
// appears), and a ray with both components this small has no direction.
inline constexpr double kNoComponent = 1e-300;
inline constexpr double kNeverInverse = 1e300;
// floor() by truncation of a shifted value: the coordinates floored lie
// within the square being left, so never below -256, and truncation needs
// no call or branch where SSE4.1 is not assumed. Shifting may round a value
// within 1e-13 of a cell border across it: a tie the ray decides either way.
inline constexpr double kFloorShift = 512.0;
// Bytes readable after the last cell: the vector walk reads four at a cell.
inline constexpr std::size_t kReadPadding = 3;

// One ray's walk as a lane holds it: start()'s Walk and first cell, in
// doubles (cell numbers are whole numbers, exact in a double).
struct LaneStart {
  double x, y, dx, dy, inverse_x, inverse_y, length;
  double step_x, behind_x, step_y, behind_y;  // behind: 1 when the step is -1, else 0
  double col, row, clearance;
  double max_range;  // m, the answer when the walk leaves the grid or passes it
};

// The map as the lanes read it.
struct LaneMap {
  const std::uint8_t* cells;  // row-major clearances, kReadPadding readable bytes after the last
  int width, height;          // width * height < 2^31
  double resolution;
};

// Whether this processor runs walk() (AVX2).
[[nodiscard]] bool available();

// Walks every start to its end and writes ranges[start_ray[i]] for start i,
// as SquareCaster's scalar walk would. Only where available().
void walk(const LaneMap& map, std::span<const LaneStart> starts, std::span<const std::size_t> start_ray,
          std::span<double> ranges);

}  // namespace playerkit::grid::lanes
