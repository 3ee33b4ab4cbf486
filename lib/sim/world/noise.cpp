#include "sim/world/noise.hpp"

#include <cmath>
#include <numbers>

namespace playerkit::sim {

namespace {

std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

NoiseDraws::NoiseDraws(std::uint64_t seed, ModelId model, std::uint64_t step)
    : state_(mix(mix(seed ^ 0x9e3779b97f4a7c15ULL) ^ (static_cast<std::uint64_t>(static_cast<std::uint32_t>(model)) << 32) ^
                 mix(step + 0x632be59bd9b4e019ULL))) {}

std::uint64_t NoiseDraws::next() {
  state_ += 0x9e3779b97f4a7c15ULL;
  return mix(state_);
}

double NoiseDraws::uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

double NoiseDraws::gaussian(double standard_deviation) {
  if (standard_deviation == 0.0) return 0.0;
  // Box-Muller; 1 - u keeps the logarithm's argument in (0, 1].
  const double u = 1.0 - uniform();
  const double v = uniform();
  return standard_deviation * std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
}

}  // namespace playerkit::sim
