#pragma once
// Inside LikelihoodFieldModel: the scoring of one particle's beam endpoints,
// four beams at a time on AVX2 (likelihood_field_avx2.cpp) or one at a time
// (likelihood_field_model.cpp). Both give the same values bit for bit. Not
// for other callers.

#include <cstddef>
#include <cstdint>

namespace playerkit::amcl::field_lanes {

// Bytes readable after the last cell's code: the vector scoring reads four
// at a cell.
inline constexpr std::size_t kReadPadding = 3;

// The field as the lanes read it.
struct FieldTable {
  const std::uint8_t* codes;  // row-major distance codes, kReadPadding readable bytes after the last
  const float* log_by_code;   // log p per code
  float log_outside;          // log p of an endpoint off the map
  int width, height;
};

// One particle's pose, in cells: an endpoint (hx, hy) in the robot's frame
// (metres) falls in cell floor(col + cos_r hx - sin_r hy),
// floor(row + sin_r hx + cos_r hy).
struct CellPose {
  double col, row;
  double cos_r, sin_r;  // cos and sin of the heading, over the resolution
};

// Whether this processor runs the vector walk (AVX2).
[[nodiscard]] bool available();

// values[b] = log p of endpoint b, for b < count; count is a multiple of 4
// (the caller pads hx and hy). Only where available().
void endpoint_values(const FieldTable& field, const CellPose& pose, const double* hx, const double* hy,
                     std::size_t count, float* values);

}  // namespace playerkit::amcl::field_lanes
