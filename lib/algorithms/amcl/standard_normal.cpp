#include "algorithms/amcl/standard_normal.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace playerkit::amcl {
namespace standard_normal_detail {

constexpr int kLayers = 128;
// The base layer's right edge and every layer's area (the rectangles' and
// the base's, tail included), for 128 layers of equal area under
// exp(-x^2 / 2).
constexpr double kTailStart = 3.442619855899;
constexpr double kLayerArea = 9.91256303526217e-3;

struct Layers {
  std::array<double, kLayers + 1> edge{};    // x of each layer's right edge; edge[128] = 0
  std::array<double, kLayers> inside_ratio{};  // edge[i + 1] / edge[i]: wholly under the curve below this

  Layers() {
    double f = std::exp(-0.5 * kTailStart * kTailStart);
    edge[0] = kLayerArea / f;  // the base layer as a rectangle of the same area
    edge[1] = kTailStart;
    edge[kLayers] = 0.0;
    for (int i = 2; i < kLayers; ++i) {
      edge[i] = std::sqrt(-2.0 * std::log(kLayerArea / edge[i - 1] + f));
      f = std::exp(-0.5 * edge[i] * edge[i]);
    }
    for (int i = 0; i < kLayers; ++i) inside_ratio[i] = edge[i + 1] / edge[i];
  }
};

const Layers& layers() {
  static const Layers table;
  return table;
}

// Uniform in [0, 1) from the top 53 bits.
double uniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Beyond kTailStart (Marsaglia 1964): exponential proposals, accepted in
// proportion to the normal's tail.
double tail(std::mt19937_64& rng, bool negative) {
  double x = 0.0;
  double y = 0.0;
  do {
    x = std::log(1.0 - uniform(rng)) / kTailStart;  // 1 - u: never log(0)
    y = std::log(1.0 - uniform(rng));
  } while (-2.0 * y < x * x);
  return negative ? x - kTailStart : kTailStart - x;
}

}  // namespace standard_normal_detail

double StandardNormal::operator()(std::mt19937_64& rng) const {
  using namespace standard_normal_detail;
  const Layers& table = layers();
  for (;;) {
    const std::uint64_t bits = rng();
    // The top 53 bits give u in [-1, 1), the lowest 7 the layer.
    const double u = static_cast<double>(bits >> 11) * 0x1.0p-52 - 1.0;
    const auto layer = static_cast<std::size_t>(bits & (kLayers - 1));
    const double outer = table.edge[layer];
    if (std::abs(u) < table.inside_ratio[layer]) return u * outer;
    if (layer == 0) return tail(rng, u < 0.0);
    // Between the layer's inner and outer edge: under the curve or not.
    const double x = u * outer;
    const double inner = table.edge[layer + 1];
    const double f_outer = std::exp(-0.5 * (outer * outer - x * x));
    const double f_inner = std::exp(-0.5 * (inner * inner - x * x));
    if (f_inner + uniform(rng) * (f_outer - f_inner) < 1.0) return x;
  }
}

}  // namespace playerkit::amcl
