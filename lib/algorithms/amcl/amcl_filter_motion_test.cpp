// The filter through the motions that broke 1.5's and our earlier amcl: a
// fast turn in a tight corridor (issue 34: a 64 degree turn between two
// scans stayed 80 degrees off for 9 s while reporting 2 degrees), turning
// on the spot with perfect odometry (a singular motion covariance; 1.5
// aborted inside GSL) and standing still for minutes.
#include "algorithms/amcl/amcl_filter.hpp"

#include "algorithms/amcl/synthetic_room_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <tuple>
#include <vector>

namespace playerkit::amcl {
namespace amcl_filter_motion_test {
constexpr double degree = std::numbers::pi / 180.0;

double heading_error_degrees(const geometry::Pose2& estimate, const geometry::Pose2& truth) {
  return std::abs(geometry::angle_difference(estimate.yaw, truth.yaw)) / degree;
}

// What each scan of a run showed: the heading error of the estimate the
// filter reports for it (predict(), as amcl-offline and the driver do) and
// the heading standard deviation it claims.
struct ScanResult {
  double heading_error = 0.0;  // degrees
  double heading_deviation = 0.0;  // degrees
  double position_error = 0.0;  // m
};

// Along the corridor in 0.4 m steps, one scan each (0.8 s apart at
// 0.5 m/s); at the side corridor a 64 degree turn while moving 0.18 m
// between two scans, then creeping (2 cm and 6.5 degrees a scan) for four
// scans, then up the side corridor. Wheel odometry misreads every step by
// a few percent, and the fast turn by `turn_misread` (1: right).
std::vector<ScanResult> drive_the_fast_turn(const AmclParameters& parameters, std::uint64_t seed,
                                            double turn_misread) {
  const auto map = test::make_corridors();
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gain(1.0, 0.05), slip(0.0, 0.01);
  geometry::Pose2 truth{1.5, 3.0, 0.0};
  geometry::Pose2 odometry{5.0, -2.0, 2.5};  // a frame of its own; the turn crosses its +-pi
  AmclFilter filter(parameters, map, seed);
  filter.set_pose(truth, Eigen::Vector3d(0.01, 0.01, 0.003).asDiagonal());

  struct Step {
    geometry::Pose2 motion;
    bool fast_turn = false;
  };
  std::vector<Step> steps(16, Step{{0.4, 0.0, 0.0}});
  steps.push_back({{0.18, 0.0, 64.0 * degree}, true});
  for (int i = 0; i < 4; ++i) steps.push_back({{0.02, 0.0, 6.5 * degree}});
  for (int i = 0; i < 10; ++i) steps.push_back({{0.4, 0.0, 0.0}});

  test::LaserSpec laser;
  laser.max_range = 8.0;
  std::vector<ScanResult> results;
  for (const Step& step : steps) {
    truth = truth.compose(step.motion);
    const double turn_gain = step.fast_turn ? turn_misread : gain(rng);
    odometry = odometry.compose({step.motion.x * gain(rng), 0.0, step.motion.yaw * turn_gain + slip(rng)});
    const LaserScan scan = test::simulate_scan(*map, truth, laser, 0.02, &rng);
    filter.update(odometry, &scan);
    const Hypothesis estimate = filter.predict(odometry);
    results.push_back({heading_error_degrees(estimate.mean, truth),
                       std::sqrt(std::max(0.0, estimate.covariance(2, 2))) / degree,
                       std::hypot(estimate.mean.x - truth.x, estimate.mean.y - truth.y)});
  }
  return results;
}

constexpr std::size_t fast_turn_scan = 16;

TEST(AmclFilterMotion, FollowsAFastTurnInATightCorridor) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const auto results = drive_the_fast_turn(AmclParameters{}, seed, 1.0);
    for (std::size_t i = 0; i < results.size(); ++i) {
      EXPECT_LE(results[i].heading_error, 5.0) << "seed " << seed << ", scan " << i;
      // Along a corridor the position is the weaker part; 1.5 m of it is
      // all the laser sees behind the first scans.
      EXPECT_LE(results[i].position_error, 0.5) << "seed " << seed << ", scan " << i;
    }
  }
}

// Odometry says 102 degrees where the robot turned 64: one damped scan
// cannot pull a cloud spread over tens of degrees in, so the scan of the
// turn is off, but says so; the scans while the robot creeps update
// although it has not moved 0.2 m or 30 degrees, and the next one is right.
TEST(AmclFilterMotion, AMisreadTurnIsOwnedUpToAndPutRightByTheNextScan) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const auto results = drive_the_fast_turn(AmclParameters{}, seed, 1.6);
    for (std::size_t i = 0; i < results.size(); ++i) {
      EXPECT_LE(results[i].heading_error, 2.0 * results[i].heading_deviation + 1.0)
          << "seed " << seed << ", scan " << i << ": confidently wrong";
      if (i > fast_turn_scan) {
        EXPECT_LE(results[i].heading_error, 5.0) << "seed " << seed << ", scan " << i;
      }
    }
  }
}

// The cause, shown by switching the remedy off: waiting for motion, the
// creeping scans keep the turn's error.
TEST(AmclFilterMotion, WaitingForMotionAfterAMisreadTurnStaysOff) {
  AmclParameters motion_only;
  motion_only.uncertain_heading_deviation = 0.0;
  motion_only.uncertain_position_deviation = 0.0;
  const auto results = drive_the_fast_turn(motion_only, 1, 1.6);
  for (std::size_t i = fast_turn_scan + 1; i <= fast_turn_scan + 4; ++i) {
    EXPECT_GT(results[i].heading_error, 10.0) << "scan " << i;
  }
}

std::size_t distinct_poses(std::span<const Particle> particles) {
  std::set<std::tuple<double, double, double>> poses;
  for (const Particle& particle : particles) poses.insert({particle.pose.x, particle.pose.y, particle.pose.yaw});
  return poses.size();
}

// Perfect odometry turning on the spot: the motion has no translation, so
// its covariance is singular; 1.5 aborted inside GSL on it. Three turns in
// 10 degree steps with every noise coefficient 0 as well as at the defaults.
TEST(AmclFilterMotion, TurnsOnTheSpotWithPerfectOdometry) {
  const auto map = test::make_room();
  AmclParameters noiseless;
  noiseless.rotation_noise_from_rotation = 0.0;
  noiseless.rotation_noise_from_translation = 0.0;
  noiseless.translation_noise_from_translation = 0.0;
  noiseless.translation_noise_from_rotation = 0.0;
  for (const AmclParameters& parameters : {AmclParameters{}, noiseless}) {
    AmclFilter filter(parameters, map, 5);
    geometry::Pose2 truth{3.0, 2.0, 0.0};
    filter.set_pose(truth, Eigen::Vector3d(0.01, 0.01, 0.003).asDiagonal());
    for (int step = 0; step <= 108; ++step) {
      truth.yaw = geometry::normalize_angle(step * 10.0 * degree);
      const LaserScan scan = test::simulate_scan(*map, truth);
      filter.update({0.0, 0.0, truth.yaw}, &scan);
      const Hypothesis estimate = filter.predict({0.0, 0.0, truth.yaw});
      ASSERT_TRUE(estimate.covariance.allFinite());
      EXPECT_LE(heading_error_degrees(estimate.mean, truth), 3.0) << "step " << step;
      EXPECT_LE(std::hypot(estimate.mean.x - truth.x, estimate.mean.y - truth.y), 0.1) << "step " << step;
    }
  }
}

// Five minutes of 10 Hz scans without moving, in a corridor whose walls
// are all a 1.5 m laser sees: where along it the robot stands stays
// uncertain, so the scans update without motion, but only
// uncertain_updates_most of them; the estimate stays, says it is unsure
// along the corridor, and the cloud does not thin out to a few copies.
TEST(AmclFilterMotion, StandsStillForMinutes) {
  const auto map = test::make_corridors();
  AmclFilter filter(AmclParameters{}, map, 9);
  const geometry::Pose2 truth{5.5, 3.0, 0.0};
  filter.set_pose(truth, Eigen::Vector3d(0.25, 0.01, 0.003).asDiagonal());
  test::LaserSpec short_laser;
  short_laser.max_range = 1.5;
  std::mt19937_64 rng(3);
  std::size_t updates = 0;
  for (int i = 0; i < 3000; ++i) {
    const LaserScan scan = test::simulate_scan(*map, truth, short_laser, 0.02, &rng);
    if (filter.update({1.0, 1.0, 1.0}, &scan)) ++updates;
  }
  EXPECT_EQ(updates, 1 + AmclParameters{}.uncertain_updates_most);  // the first scan, then the uncertain ones
  const Hypothesis estimate = filter.best();
  EXPECT_LE(std::abs(estimate.mean.y - truth.y), 0.1);
  EXPECT_LE(heading_error_degrees(estimate.mean, truth), 3.0);
  EXPECT_GE(std::sqrt(estimate.covariance(0, 0)), 0.2);
  EXPECT_GE(distinct_poses(filter.particles()), filter.particles().size() / 4);
}

}  // namespace amcl_filter_motion_test
}  // namespace playerkit::amcl
