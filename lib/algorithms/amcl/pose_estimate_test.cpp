#include "algorithms/amcl/pose_estimate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace playerkit::amcl {
namespace pose_estimate_test {

constexpr double pi = std::numbers::pi;
constexpr double ten_degrees = pi / 18;

TEST(PoseEstimate, ClusterStraddlingThePiSeamHasItsMeanNearPi) {
  std::vector<Particle> particles;
  for (int i = 0; i < 50; ++i) {
    const double offset = 0.002 * i;
    particles.push_back({{1.0, 1.0, pi - offset}, 1.0});
    particles.push_back({{1.0, 1.0, -pi + offset}, 1.0});
  }
  std::vector<Hypothesis> clusters;
  PoseClusterer clusterer;
  clusterer.cluster(particles, 0.5, ten_degrees, clusters);
  ASSERT_EQ(clusters.size(), 1u);  // the yaw bins wrap: one cluster, not two
  EXPECT_NEAR(std::abs(clusters[0].mean.yaw), pi, 1e-9);
  // Spread: offsets 0 .. 0.098 on both sides, var = mean(offset^2).
  double expected_variance = 0.0;
  for (int i = 0; i < 50; ++i) expected_variance += (0.002 * i) * (0.002 * i) / 50.0;
  EXPECT_NEAR(clusters[0].covariance(2, 2), expected_variance, 1e-12);
  EXPECT_NEAR(clusters[0].weight, 1.0, 1e-12);

  const Hypothesis whole = weighted_estimate(particles);
  EXPECT_NEAR(std::abs(whole.mean.yaw), pi, 1e-9);
}

TEST(PoseEstimate, SeparateGroupsBecomeHypothesesSortedByWeight) {
  std::mt19937_64 rng(1);
  std::normal_distribution<double> noise(0.0, 0.05);
  std::vector<Particle> particles;
  for (int i = 0; i < 300; ++i) particles.push_back({{2 + noise(rng), 3 + noise(rng), 0.5 + noise(rng)}, 1.0});
  for (int i = 0; i < 700; ++i) particles.push_back({{-4 + noise(rng), 1 + noise(rng), -1.0 + noise(rng)}, 1.0});
  std::vector<Hypothesis> clusters;
  PoseClusterer clusterer;
  clusterer.cluster(particles, 0.5, ten_degrees, clusters);
  ASSERT_EQ(clusters.size(), 2u);
  EXPECT_NEAR(clusters[0].weight, 0.7, 1e-12);
  EXPECT_NEAR(clusters[1].weight, 0.3, 1e-12);
  EXPECT_NEAR(clusters[0].mean.x, -4.0, 0.01);
  EXPECT_NEAR(clusters[0].mean.yaw, -1.0, 0.01);
  EXPECT_NEAR(clusters[1].mean.y, 3.0, 0.01);
  for (const Hypothesis& h : clusters) {
    EXPECT_NEAR(h.covariance(0, 0), 0.0025, 0.0006);
    EXPECT_NEAR(h.covariance(1, 1), 0.0025, 0.0006);
    EXPECT_NEAR(h.covariance(2, 2), 0.0025, 0.0006);
    EXPECT_NEAR(h.covariance(0, 1), 0.0, 0.0006);
  }
}

TEST(PoseEstimate, WeightsNotCountsDecide) {
  std::vector<Particle> particles;
  for (int i = 0; i < 90; ++i) particles.push_back({{0.1, 0.1, 0.0}, 0.1 / 90});
  for (int i = 0; i < 10; ++i) particles.push_back({{9.1, 0.1, 0.0}, 0.9 / 10});
  std::vector<Hypothesis> clusters;
  PoseClusterer clusterer;
  clusterer.cluster(particles, 0.5, ten_degrees, clusters);
  ASSERT_EQ(clusters.size(), 2u);
  EXPECT_NEAR(clusters[0].mean.x, 9.1, 1e-12);
  EXPECT_NEAR(clusters[0].weight, 0.9, 1e-12);
}

// The dense grid and the hash table number bins alike, so the clusters
// are the same to the bit: spread like a global search, in blobs, in one.
TEST(PoseEstimate, DenseGridAndHashTableGiveTheSameClusters) {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> across(-15.0, 15.0), along(-5.0, 5.0), heading(-pi, pi);
  std::normal_distribution<double> noise(0.0, 0.3);
  std::uniform_real_distribution<double> weight(0.1, 1.0);
  for (int scene = 0; scene < 3; ++scene) {
    std::vector<Particle> particles;
    for (int i = 0; i < 20000; ++i) {
      geometry::Pose2 pose{across(rng), along(rng), heading(rng)};
      if (scene == 1) pose = {(i % 4) * 6.0 + noise(rng), (i % 3) * 2.0 + noise(rng), (i % 5) * 1.2 + noise(rng)};
      if (scene == 2) pose = {3.0 + noise(rng), -1.0 + noise(rng), geometry::normalize_angle(3.0 + noise(rng))};
      particles.push_back({pose, weight(rng)});
    }
    PoseClusterer dense, hashed;
    hashed.use_dense_grid(false);
    std::vector<Hypothesis> a, b;
    dense.cluster(particles, 0.5, ten_degrees, a);
    hashed.cluster(particles, 0.5, ten_degrees, b);
    ASSERT_EQ(a.size(), b.size()) << "scene " << scene;
    EXPECT_GT(a.size(), scene == 2 ? 0u : 1u) << "scene " << scene;
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_EQ(a[k].weight, b[k].weight) << "scene " << scene << " cluster " << k;
      EXPECT_EQ(a[k].mean.x, b[k].mean.x);
      EXPECT_EQ(a[k].mean.y, b[k].mean.y);
      EXPECT_EQ(a[k].mean.yaw, b[k].mean.yaw);
      EXPECT_EQ(a[k].covariance, b[k].covariance);
    }
  }
}

TEST(PoseEstimate, ChainOfTouchingBinsIsOneCluster) {
  // Particles every 0.4 m along x: each bin touches the next.
  std::vector<Particle> particles;
  for (int i = 0; i < 20; ++i) particles.push_back({{0.4 * i, 0.0, 0.0}, 1.0});
  std::vector<Hypothesis> clusters;
  PoseClusterer clusterer;
  clusterer.cluster(particles, 0.5, ten_degrees, clusters);
  ASSERT_EQ(clusters.size(), 1u);
  EXPECT_NEAR(clusters[0].mean.x, 0.4 * 9.5, 1e-9);
}

}  // namespace pose_estimate_test
}  // namespace playerkit::amcl
