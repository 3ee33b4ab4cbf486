#pragma once
// Standard normal deviates by the ziggurat method (Marsaglia and Tsang
// 2000, with Doornik's 2005 change: 128 layers, the uniform and the layer
// from independent bits). Most draws take one 64-bit random number, a
// multiplication and a comparison; std::normal_distribution's polar method
// takes two or more numbers, a logarithm, a square root and a division.
// The motion model draws three deviates per particle per update, which
// made the library's normal sampling a seventh of an offline localization.

#include <random>

namespace playerkit::amcl {

class StandardNormal {
 public:
  double operator()(std::mt19937_64& rng) const;
};

}  // namespace playerkit::amcl
