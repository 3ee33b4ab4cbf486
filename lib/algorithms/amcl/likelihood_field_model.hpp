#pragma once
// The likelihood field laser model (Probabilistic Robotics table 6.3): a
// beam's endpoint is scored by its distance d to the nearest obstacle,
//   p = z_hit N(d; 0, sigma_hit) + z_rand / max_range,
// and no-return (max-range) readings are skipped, since they say nothing
// about where an obstacle is. The distance transform is computed once per
// map; from it a table of log p per cell is built (and rebuilt only when the
// settings or the scan's max_range change), so a beam costs one lookup.

#include "algorithms/amcl/laser_model_settings.hpp"
#include "algorithms/amcl/laser_scan.hpp"
#include "algorithms/amcl/particle_set.hpp"
#include "algorithms/grid/distance_map.hpp"
#include "algorithms/grid/occupancy_grid.hpp"

#include <span>
#include <vector>

namespace playerkit::amcl {

class LikelihoodFieldModel {
 public:
  // Distances are capped at `max_distance` (m): farther endpoints all score
  // as this far.
  LikelihoodFieldModel(const grid::OccupancyGrid& map, double max_distance);

  double max_distance() const { return distances_.max_distance(); }

  // log p(scan | particle pose) for each particle, into `out` (same size).
  void log_likelihoods(std::span<const Particle> particles, const PreparedBeams& beams,
                       const LaserModelSettings& settings, std::span<double> out);

  // log p of one endpoint at `distance` from the nearest obstacle.
  static double log_endpoint_likelihood(double distance, double max_range,
                                        const LaserModelSettings& settings);

 private:
  void refresh_table(const LaserModelSettings& settings, double max_range);

  int width_;
  int height_;
  double resolution_;
  Eigen::Vector2d origin_;
  grid::DistanceMap distances_;
  std::vector<float> log_table_;
  float log_outside_ = 0.0f;
  bool table_valid_ = false;
  LaserModelSettings table_settings_;
  double table_max_range_ = 0.0;
  std::vector<double> hit_x_, hit_y_;  // endpoints of beams that returned
  std::vector<float> beam_values_;     // beam skipping: per particle, per beam
  std::vector<double> explained_weight_;  // beam skipping: per beam
};

}  // namespace playerkit::amcl
