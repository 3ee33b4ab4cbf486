#pragma once
// Low-variance (systematic) resampling, Probabilistic Robotics table 4.4:
// one random offset, then `count` equally spaced pointers walk the
// cumulative weights once. O(weights + count), and particle i is drawn
// either floor(count * w_i) or ceil(count * w_i) times — far less variance
// than drawing each sample independently.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace playerkit::amcl {

// `weights` need not be normalised but must be non-negative with a positive
// sum; `offset` is a uniform draw from [0, 1). Fills `indices` with `count`
// parent indices in increasing order (resized, reusing its capacity).
void low_variance_resample(std::span<const double> weights, std::size_t count, double offset,
                           std::vector<std::uint32_t>& indices);

}  // namespace playerkit::amcl
