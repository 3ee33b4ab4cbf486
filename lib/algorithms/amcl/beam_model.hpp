#pragma once
// The beam laser model (Probabilistic Robotics table 6.1, as in Player
// 1.5's amcl): for each beam the range a perfect sensor would read is ray
// cast through the map from the particle's pose, and the reading z against
// that expected range z* is scored by a mixture of
//   hit   z_hit   N(z - z*; sigma_hit)          measurement noise
//   short z_short lambda exp(-lambda z), z < z*  unexpected obstacles
//   max   z_max   when z is a no-return reading   missed returns
//   rand  z_rand  / max_range, z < max_range     everything else
// A no-return reading thus scores high where the map has nothing within
// range and only z_max (not a miss) where it has.
//
// Expected ranges come from a grid::RangeCaster (cast_ray's answers by ray
// marching), whose distance transform makes construction cost about as much
// as a likelihood field's: build one per map.

#include "algorithms/amcl/laser_model_settings.hpp"
#include "algorithms/amcl/laser_scan.hpp"
#include "algorithms/amcl/particle_set.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "algorithms/grid/range_caster.hpp"

#include <memory>
#include <span>

namespace playerkit::amcl {

class BeamModel {
 public:
  // Throws std::invalid_argument for a null map. The map is not kept.
  explicit BeamModel(std::shared_ptr<const grid::OccupancyGrid> map);

  void log_likelihoods(std::span<const Particle> particles, const PreparedBeams& beams,
                       const LaserModelSettings& settings, std::span<double> out) const;

  // log p of reading `range` (no_return: a max-range reading) when the map
  // predicts `expected`.
  static double log_beam_likelihood(double range, bool no_return, double expected,
                                    double max_range, const LaserModelSettings& settings);

 private:
  // Stops at occupied cells only. Player 1.5's map_calc_range stopped at
  // anything not free, which a map made from a log (free only where beams
  // went, unknown between them far from the path) turns into expected
  // ranges cut short: Radish Edmonton was lost from the true start.
  grid::RangeCaster caster_;
};

}  // namespace playerkit::amcl
