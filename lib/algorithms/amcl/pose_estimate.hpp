#pragma once
// The pose estimate: particles are grouped into clusters — connected groups
// of occupied histogram bins (bins touching in x, y or yaw, yaw wrapping
// around the circle) — and each cluster gives one hypothesis: its weight,
// its weighted mean and covariance. Yaw is averaged on the circle (the
// direction of the summed unit vectors) and its spread is measured by
// wrapped differences from that mean, so a cluster straddling +-pi has a
// mean near pi, not 0.

#include "algorithms/amcl/particle_set.hpp"
#include "algorithms/amcl/pose_bins.hpp"
#include "algorithms/geometry/pose2.hpp"

#include <Eigen/Core>

#include <array>
#include <span>
#include <vector>

namespace playerkit::amcl {

struct Hypothesis {
  geometry::Pose2 mean;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  // over (x, y, yaw)
  double weight = 0.0;
};

// The weighted sums a mean pose is made of, yaw as summed unit vectors.
struct WeightedMoments {
  double weight = 0.0, x = 0.0, y = 0.0, cos_yaw = 0.0, sin_yaw = 0.0;

  void add(const Particle& particle);
  // Meaningful only when weight > 0.
  [[nodiscard]] geometry::Pose2 mean() const;
};

// The weighted mean and covariance of a set of particles (one cluster).
Hypothesis weighted_estimate(std::span<const Particle> particles);

class PoseClusterer {
 public:
  // Hypotheses, heaviest first; weights are fractions of the set's total
  // weight (they sum to 1 over all clusters). Reuses its buffers.
  void cluster(std::span<const Particle> particles, double cell_size, double angle_size,
               std::vector<Hypothesis>& out);

  // Off, bins always go through the hash table; the answer is the same
  // (a test compares the two ways).
  void use_dense_grid(bool on) { dense_grid_allowed_ = on; }

 private:
  // Gives every particle its bin's number (particle_bin_), bins numbered
  // in the order their first particle comes; true when through the dense grid.
  bool number_bins(std::span<const Particle> particles, const PoseBinning& binning);
  // Joins touching bins into sets (parent_, a set's root its lowest bin).
  void join_touching_bins(const PoseBinning& binning, bool dense);
  // A hypothesis per set: weight, mean and covariance of its particles.
  void summarise_clusters(std::span<const Particle> particles, std::vector<Hypothesis>& out);
  std::uint32_t find_root(std::uint32_t bin);

  struct Accumulator {
    WeightedMoments moments;
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  };

  // A dense grid when the bins' box holds at most kDenseGridPerParticle
  // bins per particle (or kDenseGridLeast bins): a global search's
  // particles, spread over the free space, and a tracked cloud both fit.
  static constexpr std::size_t kDenseGridPerParticle = 8;
  static constexpr std::size_t kDenseGridLeast = 1 << 14;

  bool dense_grid_allowed_ = true;
  DenseBinGrid grid_;
  BinTable bins_;
  std::vector<PoseBin> bin_coordinates_;
  std::vector<std::uint32_t> parent_;
  std::vector<PoseBin> particle_pose_bin_;
  std::vector<std::uint64_t> particle_key_;
  std::vector<std::uint32_t> particle_bin_;
  std::vector<std::uint32_t> cluster_of_root_;
  std::vector<Accumulator> accumulators_;
};

}  // namespace playerkit::amcl
