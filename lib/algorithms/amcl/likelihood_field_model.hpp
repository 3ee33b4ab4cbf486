#pragma once
// The likelihood field laser model (Probabilistic Robotics table 6.3): a
// beam's endpoint is scored by its distance d to the nearest obstacle,
//   p = z_hit N(d; 0, sigma_hit) + z_rand / max_range,
// and no-return (max-range) readings are skipped, since they say nothing
// about where an obstacle is. The distance transform is computed once per
// map and kept as one byte per cell (the distance in 255ths of the cap, off
// by at most 4 mm at the default 2 m): a quarter of a float table, so the
// random lookups of a big map's endpoints stay in cache. A 256-entry table
// turns the byte into log p; it is rebuilt when the settings or the scan's
// max_range change.

#include "algorithms/amcl/laser_model_settings.hpp"
#include "algorithms/amcl/laser_scan.hpp"
#include "algorithms/amcl/particle_set.hpp"
#include "algorithms/grid/occupancy_grid.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace playerkit::amcl {

class LikelihoodFieldModel {
 public:
  // Distances are capped at `max_distance` (m): farther endpoints all score
  // as this far.
  LikelihoodFieldModel(const grid::OccupancyGrid& map, double max_distance);

  double max_distance() const { return max_distance_; }

  // log p(scan | particle pose) for each particle, into `out` (same size).
  void log_likelihoods(std::span<const Particle> particles, const PreparedBeams& beams,
                       const LaserModelSettings& settings, std::span<double> out);

  // Endpoints are scored four at a time on a processor with AVX2, one at a
  // time otherwise; the values are the same bit for bit. false: one at a
  // time here too (tests compare the two).
  void use_vector_scoring(bool use) { vector_scoring_ = use; }

  // log p of one endpoint at `distance` from the nearest obstacle.
  static double log_endpoint_likelihood(double distance, double max_range,
                                        const LaserModelSettings& settings);

 private:
  void refresh_table(const LaserModelSettings& settings, double max_range);

  static constexpr int kDistanceCodes = 256;

  int width_;
  int height_;
  double resolution_;
  Eigen::Vector2d origin_;
  double max_distance_;
  std::vector<std::uint8_t> distance_codes_;  // per cell, and 3 bytes; kDistanceCodes - 1 is the cap
  std::array<float, kDistanceCodes> log_by_code_{};
  bool vector_scoring_ = true;
  bool table_valid_ = false;
  LaserModelSettings table_settings_;
  double table_max_range_ = 0.0;
  std::vector<double> hit_x_, hit_y_;  // endpoints of beams that returned
  std::vector<float> particle_values_;  // a batch of particles', per beam
  std::vector<std::size_t> every_beam_;  // 0, 1, ... : no beam skipped
  std::vector<float> beam_values_;     // beam skipping: per particle, per beam
  std::vector<double> explained_weight_;  // beam skipping: per beam
  std::vector<std::size_t> kept_beams_;   // beam skipping: the beams summed
};

}  // namespace playerkit::amcl
