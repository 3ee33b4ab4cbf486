#pragma once
// Random numbers that depend only on (seed, model, step): a sensor's noise
// at step k is the same whether or not it was read at steps before k, so a
// run is reproducible at any speed and with any set of clients. A counter-
// based generator (SplitMix64 over a hash of the three), not a stream.

#include <cstdint>

#include "sim/world/model_spec.hpp"

namespace playerkit::sim {

class NoiseDraws {
 public:
  NoiseDraws(std::uint64_t seed, ModelId model, std::uint64_t step);

  // Uniform in [0, 1).
  double uniform();
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  // Normal with mean 0 and this standard deviation (0 gives 0 and draws nothing).
  double gaussian(double standard_deviation);

 private:
  std::uint64_t next();
  std::uint64_t state_;
};

}  // namespace playerkit::sim
