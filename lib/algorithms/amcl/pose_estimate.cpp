#include "algorithms/amcl/pose_estimate.hpp"

#include "algorithms/geometry/sin_cos.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace playerkit::amcl {

Hypothesis weighted_estimate(std::span<const Particle> particles) {
  Hypothesis estimate;
  double total = 0.0, x = 0.0, y = 0.0, c = 0.0, s = 0.0;
  for (const Particle& particle : particles) {
    total += particle.weight;
    x += particle.weight * particle.pose.x;
    y += particle.weight * particle.pose.y;
    const geometry::SinCos heading = geometry::sin_cos(particle.pose.yaw);
    c += particle.weight * heading.cos;
    s += particle.weight * heading.sin;
  }
  if (!(total > 0.0)) return estimate;
  estimate.weight = total;
  estimate.mean = {x / total, y / total, std::atan2(s, c)};
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
  bins_.reset(particles.size());
  bin_coordinates_.clear();
  particle_bin_.resize(particles.size());
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const PoseBin bin = binning.bin_of(particles[i].pose);
    const auto [index, is_new] = bins_.insert(PoseBinning::key(bin));
    if (is_new) bin_coordinates_.push_back(bin);
    particle_bin_[i] = index;
  }

  const std::size_t bin_count = bin_coordinates_.size();
  parent_.resize(bin_count);
  for (std::uint32_t b = 0; b < bin_count; ++b) parent_[b] = b;
  // Touching bins join: each pair is found from one side, as the other's
  // forward neighbour (half the lookups of all 26).
  std::array<PoseBin, 13> around;
  for (std::uint32_t b = 0; b < bin_count; ++b) {
    const std::size_t count = binning.forward_neighbours(bin_coordinates_[b], around);
    for (std::size_t k = 0; k < count; ++k) {
      const std::uint32_t other = bins_.find(PoseBinning::key(around[k]));
      if (other == BinTable::not_found) continue;
      const std::uint32_t a = find_root(b), c = find_root(other);
      if (a != c) parent_[std::max(a, c)] = std::min(a, c);
    }
  }

  // Number clusters in order of their first bin, so results do not depend
  // on hash order.
  cluster_of_root_.assign(bin_count, BinTable::not_found);
  accumulators_.clear();
  for (std::uint32_t b = 0; b < bin_count; ++b) {
    const std::uint32_t root = find_root(b);
    if (cluster_of_root_[root] == BinTable::not_found) {
      cluster_of_root_[root] = static_cast<std::uint32_t>(accumulators_.size());
      accumulators_.emplace_back();
    }
  }
  // Sums per cluster in particle order. Runs of particles share a cluster
  // (most belong to one): a run's sums stay in a local until the cluster
  // changes, where sums kept in the vector made each particle wait for the
  // last one's store. The additions are the same, in the same order.
  std::uint32_t current = BinTable::not_found;
  Accumulator run;
  const auto run_of = [&](std::uint32_t k) -> Accumulator& {
    if (k != current) {
      if (current != BinTable::not_found) accumulators_[current] = run;
      current = k;
      run = accumulators_[k];
    }
    return run;
  };
  const auto end_run = [&] {
    if (current != BinTable::not_found) accumulators_[current] = run;
    current = BinTable::not_found;
  };
  double total = 0.0;
  for (std::size_t i = 0; i < particles.size(); ++i) {
    Accumulator& a = run_of(cluster_of_root_[find_root(particle_bin_[i])]);
    const Particle& p = particles[i];
    a.weight += p.weight;
    a.x += p.weight * p.pose.x;
    a.y += p.weight * p.pose.y;
    const geometry::SinCos heading = geometry::sin_cos(p.pose.yaw);
    a.cos_yaw += p.weight * heading.cos;
    a.sin_yaw += p.weight * heading.sin;
    total += p.weight;
  }
  end_run();
  out.resize(accumulators_.size());
  for (std::size_t k = 0; k < accumulators_.size(); ++k) {
    const Accumulator& a = accumulators_[k];
    Hypothesis& h = out[k];
    h.weight = a.weight;
    h.covariance.setZero();
    if (a.weight > 0.0) {
      h.mean = {a.x / a.weight, a.y / a.weight, std::atan2(a.sin_yaw, a.cos_yaw)};
    } else {
      h.mean = {};
    }
  }
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const std::uint32_t k = cluster_of_root_[find_root(particle_bin_[i])];
    const Particle& p = particles[i];
    const Hypothesis& h = out[k];
    const std::array<double, 3> d{p.pose.x - h.mean.x, p.pose.y - h.mean.y,
                                  geometry::angle_difference(p.pose.yaw, h.mean.yaw)};
    // weight * d * d^T, element by element: as an Eigen expression the
    // compiler built it in memory with stores the next loads could not
    // forward from, a stall per particle.
    Eigen::Matrix3d& scatter = run_of(k).scatter;
    for (int row = 0; row < 3; ++row) {
      const double weighted = p.weight * d[static_cast<std::size_t>(row)];
      for (int col = 0; col < 3; ++col) scatter(row, col) += weighted * d[static_cast<std::size_t>(col)];
    }
  }
  end_run();
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (accumulators_[k].weight > 0.0) {
      out[k].covariance = accumulators_[k].scatter / accumulators_[k].weight;
    }
    out[k].weight = total > 0.0 ? out[k].weight / total
                                : 1.0 / static_cast<double>(out.size());
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Hypothesis& a, const Hypothesis& b) { return a.weight > b.weight; });
}

}  // namespace playerkit::amcl
