#include "algorithms/amcl/pose_estimate.hpp"

#include "algorithms/geometry/sin_cos.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace playerkit::amcl {

void WeightedMoments::add(const Particle& particle) {
  weight += particle.weight;
  x += particle.weight * particle.pose.x;
  y += particle.weight * particle.pose.y;
  const geometry::SinCos heading = geometry::sin_cos(particle.pose.yaw);
  cos_yaw += particle.weight * heading.cos;
  sin_yaw += particle.weight * heading.sin;
}

geometry::Pose2 WeightedMoments::mean() const { return {x / weight, y / weight, std::atan2(sin_yaw, cos_yaw)}; }

Hypothesis weighted_estimate(std::span<const Particle> particles) {
  Hypothesis estimate;
  WeightedMoments moments;
  for (const Particle& particle : particles) moments.add(particle);
  const double total = moments.weight;
  if (!(total > 0.0)) return estimate;
  estimate.weight = total;
  estimate.mean = moments.mean();
  for (const Particle& particle : particles) {
    const Eigen::Vector3d d(particle.pose.x - estimate.mean.x, particle.pose.y - estimate.mean.y,
                            geometry::angle_difference(particle.pose.yaw, estimate.mean.yaw));
    estimate.covariance += particle.weight * d * d.transpose();
  }
  estimate.covariance /= total;
  return estimate;
}

std::uint32_t PoseClusterer::find_root(std::uint32_t bin) {
  while (parent_[bin] != bin) {
    parent_[bin] = parent_[parent_[bin]];  // path halving
    bin = parent_[bin];
  }
  return bin;
}

void PoseClusterer::cluster(std::span<const Particle> particles, double cell_size,
                            double angle_size, std::vector<Hypothesis>& out) {
  out.clear();
  if (particles.empty()) return;
  const PoseBinning binning(cell_size, angle_size);
  const bool dense = number_bins(particles, binning);
  join_touching_bins(binning, dense);
  summarise_clusters(particles, out);
}

bool PoseClusterer::number_bins(std::span<const Particle> particles, const PoseBinning& binning) {
  bin_coordinates_.clear();
  particle_bin_.resize(particles.size());
  particle_pose_bin_.resize(particles.size());
  PoseBin low = binning.bin_of(particles[0].pose), high = low;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const PoseBin bin = binning.bin_of(particles[i].pose);
    particle_pose_bin_[i] = bin;
    low = {std::min(low.x, bin.x), std::min(low.y, bin.y), 0};
    high = {std::max(high.x, bin.x), std::max(high.y, bin.y), 0};
  }
  // Bins numbered 0, 1, ... in the order their first particle comes, with
  // an array over their box when they fill a fair share of it (a global
  // search), else a hash table. Either way the same numbers.
  const std::size_t dense_limit = std::max(kDenseGridLeast, kDenseGridPerParticle * particles.size());
  const bool dense = dense_grid_allowed_ && grid_.reset(low, high, binning.yaw_bin_count(), dense_limit);
  if (dense) {
    for (std::size_t i = 0; i < particles.size(); ++i) {
      std::uint32_t& index = grid_.at(particle_pose_bin_[i]);
      if (index == BinTable::not_found) {
        index = static_cast<std::uint32_t>(bin_coordinates_.size());
        bin_coordinates_.push_back(particle_pose_bin_[i]);
      }
      particle_bin_[i] = index;
    }
  } else {
    // Keys first, so the table can be fetched a few particles ahead.
    constexpr std::size_t kAhead = 8;
    bins_.reset(particles.size());
    particle_key_.resize(particles.size());
    for (std::size_t i = 0; i < particles.size(); ++i) particle_key_[i] = PoseBinning::key(particle_pose_bin_[i]);
    for (std::size_t i = 0; i < particles.size(); ++i) {
      if (i + kAhead < particles.size()) bins_.prefetch(particle_key_[i + kAhead]);
      const auto [index, is_new] = bins_.insert(particle_key_[i]);
      if (is_new) bin_coordinates_.push_back(particle_pose_bin_[i]);
      particle_bin_[i] = index;
    }
  }
  return dense;
}

void PoseClusterer::join_touching_bins(const PoseBinning& binning, bool dense) {
  const std::size_t bin_count = bin_coordinates_.size();
  parent_.resize(bin_count);
  for (std::uint32_t b = 0; b < bin_count; ++b) parent_[b] = b;
  // Touching bins join: each pair is found from one side, as the other's
  // forward neighbour (half the lookups of all 26).
  // The sets are the same whatever order the bins are visited in.
  std::array<PoseBin, 13> around;
  const auto join_touching = [&](const PoseBin& bin, std::uint32_t b, const auto& index_of) {
    const std::size_t count = binning.forward_neighbours(bin, around);
    // A set's root is its lowest bin (the higher root is linked under the
    // lower), so b's root after a join is the lower of the two.
    std::uint32_t root = find_root(b);
    for (std::size_t k = 0; k < count; ++k) {
      const std::uint32_t other = index_of(around[k]);
      if (other == BinTable::not_found) continue;
      const std::uint32_t other_root = find_root(other);
      if (root == other_root) continue;
      parent_[std::max(root, other_root)] = std::min(root, other_root);
      root = std::min(root, other_root);
    }
  };
  if (dense) {
    // In memory order, so that neighbours are looked up close to each other.
    const auto in_grid = [&](const PoseBin& bin) { return grid_.find(bin); };
    grid_.for_each([&](const PoseBin& bin, std::uint32_t b) { join_touching(bin, b, in_grid); });
  } else {
    const auto in_table = [&](const PoseBin& bin) { return bins_.find(PoseBinning::key(bin)); };
    for (std::uint32_t b = 0; b < bin_count; ++b) join_touching(bin_coordinates_[b], b, in_table);
  }
}

void PoseClusterer::summarise_clusters(std::span<const Particle> particles, std::vector<Hypothesis>& out) {
  const std::size_t bin_count = bin_coordinates_.size();
  // Number clusters in order of their first bin, so results do not depend
  // on hash order.
  cluster_of_root_.assign(bin_count, BinTable::not_found);
  accumulators_.clear();
  // A parent is a lower bin, so in rising order every parent already points
  // at its root: one pass leaves each bin pointing at its root, and a
  // particle's cluster is two lookups away.
  for (std::uint32_t b = 0; b < bin_count; ++b) {
    const std::uint32_t root = parent_[b] = parent_[parent_[b]];
    if (cluster_of_root_[root] == BinTable::not_found) {
      cluster_of_root_[root] = static_cast<std::uint32_t>(accumulators_.size());
      accumulators_.emplace_back();
    }
  }
  const auto cluster_of = [&](std::size_t particle) { return cluster_of_root_[parent_[particle_bin_[particle]]]; };
  // Sums per cluster in particle order. Runs of particles share a cluster
  // (most belong to one): a run's sums stay in locals, in registers, until
  // the cluster changes. Summed in memory, each particle waited for the
  // last one's stores. The additions are the same, in the same order.
  std::uint32_t current = BinTable::not_found;
  WeightedMoments run;
  const auto store_moments = [&] {
    if (current != BinTable::not_found) accumulators_[current].moments = run;
  };
  double total = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (const std::uint32_t k = cluster_of(i); k != current) {
      store_moments();
      current = k;
      run = accumulators_[k].moments;
    }
    run.add(particles[i]);
    total += particles[i].weight;
  }
  store_moments();
  out.resize(accumulators_.size());
  for (std::size_t k = 0; k < accumulators_.size(); ++k) {
    const WeightedMoments& moments = accumulators_[k].moments;
    Hypothesis& h = out[k];
    h.weight = moments.weight;
    h.covariance.setZero();
    if (moments.weight > 0.0) {
      h.mean = moments.mean();
    } else {
      h.mean = {};
    }
  }
  // weight * d * d^T, element by element, row by row, in nine locals: as
  // an Eigen matrix the compiler kept the sums on the stack.
  current = BinTable::not_found;
  double s00 = 0.0, s01 = 0.0, s02 = 0.0, s10 = 0.0, s11 = 0.0, s12 = 0.0, s20 = 0.0, s21 = 0.0, s22 = 0.0;
  const auto store_scatter = [&] {
    if (current == BinTable::not_found) return;
    accumulators_[current].scatter << s00, s01, s02, s10, s11, s12, s20, s21, s22;
  };
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (const std::uint32_t k = cluster_of(i); k != current) {
      store_scatter();
      current = k;
      const Eigen::Matrix3d& m = accumulators_[k].scatter;
      s00 = m(0, 0), s01 = m(0, 1), s02 = m(0, 2);
      s10 = m(1, 0), s11 = m(1, 1), s12 = m(1, 2);
      s20 = m(2, 0), s21 = m(2, 1), s22 = m(2, 2);
    }
    const Particle& p = particles[i];
    const Hypothesis& h = out[current];
    const double d0 = p.pose.x - h.mean.x, d1 = p.pose.y - h.mean.y;
    const double d2 = geometry::angle_difference(p.pose.yaw, h.mean.yaw);
    const double w0 = p.weight * d0, w1 = p.weight * d1, w2 = p.weight * d2;
    s00 += w0 * d0, s01 += w0 * d1, s02 += w0 * d2;
    s10 += w1 * d0, s11 += w1 * d1, s12 += w1 * d2;
    s20 += w2 * d0, s21 += w2 * d1, s22 += w2 * d2;
  }
  store_scatter();
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (accumulators_[k].moments.weight > 0.0) {
      out[k].covariance = accumulators_[k].scatter / accumulators_[k].moments.weight;
    }
    out[k].weight = total > 0.0 ? out[k].weight / total
                                : 1.0 / static_cast<double>(out.size());
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Hypothesis& a, const Hypothesis& b) { return a.weight > b.weight; });
}

}  // namespace playerkit::amcl
