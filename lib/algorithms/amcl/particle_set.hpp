#pragma once
// Particles and the operations on a whole set: initialisation (Gaussian
// around a pose, or uniform over the map's free space), weight
// normalisation, effective sample size, and adaptive resampling — low-
// variance resampling whose sample count KLD-sampling chooses, with augmented
// MCL's random particles mixed in.

#include "algorithms/amcl/pose_bins.hpp"
#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <random>
#include <span>
#include <vector>

namespace playerkit::amcl {

struct Particle {
  geometry::Pose2 pose;
  double weight = 0.0;
};

// Uniform poses over the free cells of a map: uniform cell, uniform point in
// it, uniform yaw.
class FreeSpaceSampler {
 public:
  explicit FreeSpaceSampler(const grid::OccupancyGrid& map);
  bool empty() const { return free_cells_.empty(); }
  std::size_t free_cell_count() const { return free_cells_.size(); }
  // Precondition: !empty().
  geometry::Pose2 sample(std::mt19937_64& rng) const;

 private:
  std::vector<Eigen::Vector2d> free_cells_;  // lowest corners
  double resolution_;
};

// `count` particles drawn from N(mean, covariance) over (x, y, yaw), equal
// weights. A covariance that is not positive semi-definite is projected onto
// the nearest one (negative eigenvalues treated as zero).
void sample_gaussian(const geometry::Pose2& mean, const Eigen::Matrix3d& covariance,
                     std::size_t count, std::mt19937_64& rng, std::vector<Particle>& out);

void sample_uniform(const FreeSpaceSampler& free_space, std::size_t count, std::mt19937_64& rng,
                    std::vector<Particle>& out);

// Scales weights to sum to 1 and returns the old sum; an all-zero (or
// non-finite) set becomes uniform.
double normalize_weights(std::span<Particle> particles);

// 1 / sum(w^2) of normalised weights: N for equal weights, 1 when one
// particle carries everything.
double effective_sample_size(std::span<const Particle> particles);

struct ResampleSettings {
  std::size_t min_particles = 100;
  std::size_t max_particles = 5000;
  double kld_error = 0.01;
  double kld_z = 3.0;
  double bin_cell_size = 0.5;
  double bin_angle_size = 0.1745;
  // Chance that each new particle is a random pose instead of a copy.
  double injection_probability = 0.0;
};

// Resamples in place. Low-variance resampling picks max_particles parents
// (O(n)); KLD-sampling then takes them in random order, one at a time, until
// the number of copies reaches the bound for the bins they occupy — so the
// subset kept is an unbiased draw whatever its size. Each new particle is
// instead a random free pose with the injection probability; those do not
// count towards the bound. Buffers persist between calls; nothing is
// allocated once they have grown to max_particles.
class AdaptiveResampler {
 public:
  void resample(std::vector<Particle>& particles, const ResampleSettings& settings,
                const FreeSpaceSampler* free_space, std::mt19937_64& rng);

 private:
  std::vector<double> weights_;
  std::vector<std::uint32_t> parents_;
  std::vector<Particle> next_;
  BinTable bins_;
};

}  // namespace playerkit::amcl
