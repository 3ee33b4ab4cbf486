#include "algorithms/amcl/particle_set.hpp"

#include "algorithms/amcl/kld_sampling.hpp"
#include "algorithms/amcl/low_variance_resampler.hpp"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace playerkit::amcl {

FreeSpaceSampler::FreeSpaceSampler(const grid::OccupancyGrid& map) : resolution_(map.resolution()) {
  for (int row = 0; row < map.height(); ++row) {
    for (int col = 0; col < map.width(); ++col) {
      if (map.at(col, row) != grid::CellState::free) continue;
      free_cells_.push_back(map.origin() +
                            Eigen::Vector2d(col * resolution_, row * resolution_));
    }
  }
}

geometry::Pose2 FreeSpaceSampler::sample(std::mt19937_64& rng) const {
  std::uniform_int_distribution<std::size_t> pick_cell(0, free_cells_.size() - 1);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const Eigen::Vector2d& corner = free_cells_[pick_cell(rng)];
  const double x = corner.x() + unit(rng) * resolution_;
  const double y = corner.y() + unit(rng) * resolution_;
  const double yaw = geometry::normalize_angle((2.0 * unit(rng) - 1.0) * std::numbers::pi);
  return {x, y, yaw};
}

void sample_gaussian(const geometry::Pose2& mean, const Eigen::Matrix3d& covariance,
                     std::size_t count, std::mt19937_64& rng, std::vector<Particle>& out) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(
      0.5 * (covariance + covariance.transpose()));
  const Eigen::Vector3d deviations = solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  const Eigen::Matrix3d square_root = solver.eigenvectors() * deviations.asDiagonal();
  std::normal_distribution<double> standard_normal(0.0, 1.0);
  out.resize(count);
  const double weight = 1.0 / static_cast<double>(count);
  for (Particle& particle : out) {
    // One draw per statement: the order of a call's arguments is unspecified
    // (GCC takes them last first, clang first first), and a seed must give
    // the same particles whichever compiler built the filter.
    Eigen::Vector3d z;
    for (int axis = 0; axis < 3; ++axis) z[axis] = standard_normal(rng);
    const Eigen::Vector3d offset = square_root * z;
    particle.pose = {mean.x + offset.x(), mean.y + offset.y(),
                     geometry::normalize_angle(mean.yaw + offset.z())};
    particle.weight = weight;
  }
}

void sample_uniform(const FreeSpaceSampler& free_space, std::size_t count, std::mt19937_64& rng,
                    std::vector<Particle>& out) {
  if (free_space.empty()) throw std::invalid_argument("sample_uniform: the map has no free cell");
  out.resize(count);
  const double weight = 1.0 / static_cast<double>(count);
  for (Particle& particle : out) particle = {free_space.sample(rng), weight};
}

double normalize_weights(std::span<Particle> particles) {
  double total = 0.0;
  for (const Particle& particle : particles) total += particle.weight;
  if (particles.empty()) return total;
  if (!(total > 0.0) || !std::isfinite(total)) {
    const double uniform = 1.0 / static_cast<double>(particles.size());
    for (Particle& particle : particles) particle.weight = uniform;
    return total;
  }
  const double scale = 1.0 / total;
  for (Particle& particle : particles) particle.weight *= scale;
  return total;
}

double effective_sample_size(std::span<const Particle> particles) {
  double total = 0.0, squares = 0.0;
  for (const Particle& particle : particles) {
    total += particle.weight;
    squares += particle.weight * particle.weight;
  }
  if (!(squares > 0.0)) return 0.0;
  return total * total / squares;
}

void AdaptiveResampler::resample(std::vector<Particle>& particles,
                                 const ResampleSettings& settings,
                                 const FreeSpaceSampler* free_space, std::mt19937_64& rng) {
  if (particles.empty()) return;
  const std::size_t max_count = settings.max_particles;
  weights_.resize(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) weights_[i] = particles[i].weight;

  std::uniform_real_distribution<double> unit(0.0, 1.0);
  low_variance_resample(weights_, max_count, unit(rng), parents_);

  const bool may_inject =
      settings.injection_probability > 0.0 && free_space != nullptr && !free_space->empty();
  const PoseBinning binning(settings.bin_cell_size, settings.bin_angle_size);
  bins_.reset(max_count);
  next_.resize(max_count);

  // Only copies count towards the KLD bound: it measures how complex the
  // posterior is, and random particles would otherwise each open a new bin
  // and drive any injection rate above ~1% straight to max_particles. The
  // random ones come on top, at their rate.
  std::size_t count = 0;
  std::size_t copies = 0;
  std::size_t needed = settings.min_particles;
  while (count < max_count) {
    // Partial Fisher-Yates shuffle: the first `count` parents are a uniform
    // random subset of the systematic draw.
    std::uniform_int_distribution<std::size_t> pick(count, max_count - 1);
    std::swap(parents_[count], parents_[pick(rng)]);
    if (may_inject && unit(rng) < settings.injection_probability) {
      next_[count++].pose = free_space->sample(rng);
      continue;
    }
    const geometry::Pose2& pose = particles[parents_[count]].pose;
    next_[count++].pose = pose;
    ++copies;
    if (bins_.insert(PoseBinning::key(binning.bin_of(pose))).second) {
      needed = kld_particle_count(bins_.size(), settings.kld_error, settings.kld_z,
                                  settings.min_particles, max_count);
    }
    if (copies >= needed) break;
  }
  next_.resize(count);
  const double weight = 1.0 / static_cast<double>(count);
  for (Particle& particle : next_) particle.weight = weight;
  particles.swap(next_);
}

}  // namespace playerkit::amcl
