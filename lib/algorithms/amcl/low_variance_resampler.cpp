#include "algorithms/amcl/low_variance_resampler.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace playerkit::amcl {

void low_variance_resample(std::span<const double> weights, std::size_t count, double offset,
                           std::vector<std::uint32_t>& indices) {
  indices.resize(count);
  if (count == 0) return;
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  if (weights.empty() || !(total > 0.0)) {
    throw std::invalid_argument("low_variance_resample: weights must have a positive sum");
  }
  const double step = total / static_cast<double>(count);
  // The cumulative sum below adds in the same order as `total`, so it ends at
  // exactly `total`; keeping pointers strictly below it (rounding could push
  // the last one over) and advancing on >= means a zero-weight particle is
  // never drawn.
  const double last_pointer = std::nextafter(total, 0.0);
  double pointer = offset * step;
  std::size_t parent = 0;
  double cumulative = weights[0];
  for (std::size_t i = 0; i < count; ++i) {
    const double target = std::min(pointer, last_pointer);
    while (target >= cumulative && parent + 1 < weights.size()) cumulative += weights[++parent];
    indices[i] = static_cast<std::uint32_t>(parent);
    pointer += step;
  }
}

}  // namespace playerkit::amcl
