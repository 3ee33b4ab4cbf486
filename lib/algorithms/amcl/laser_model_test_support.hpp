#pragma once
// Scores of one scan at a true pose and at nearby wrong ones, for the laser
// model tests.

#include "algorithms/amcl/laser_model_settings.hpp"
#include "algorithms/amcl/laser_scan.hpp"
#include "algorithms/amcl/particle_set.hpp"
#include "algorithms/geometry/pose2.hpp"

#include <numbers>
#include <vector>

namespace playerkit::amcl::test {

inline const geometry::Pose2 true_pose{3.0, 2.5, 0.4};

// The true pose first, then 0.3 m off in +-x and +-y, then +-10 degrees.
inline std::vector<Particle> true_and_offset_poses(const geometry::Pose2& truth = true_pose) {
  const double ten_degrees = std::numbers::pi / 18;
  std::vector<Particle> particles{{truth, 1.0}};
  for (const geometry::Pose2& offset :
       {geometry::Pose2{0.3, 0, 0}, geometry::Pose2{-0.3, 0, 0}, geometry::Pose2{0, 0.3, 0},
        geometry::Pose2{0, -0.3, 0}, geometry::Pose2{0, 0, ten_degrees},
        geometry::Pose2{0, 0, -ten_degrees}}) {
    particles.push_back({{truth.x + offset.x, truth.y + offset.y, truth.yaw + offset.yaw}, 1.0});
  }
  return particles;
}

// Each particle's log-likelihood of `scan` under `model` (either laser model),
// default settings.
template <typename Model>
std::vector<double> scores(Model& model, const std::vector<Particle>& particles, const LaserScan& scan,
                           std::size_t max_beams = 30) {
  PreparedBeams beams;
  prepare_beams(scan, max_beams, beams);
  std::vector<double> out(particles.size());
  model.log_likelihoods(particles, beams, LaserModelSettings{}, out);
  return out;
}

}  // namespace playerkit::amcl::test
