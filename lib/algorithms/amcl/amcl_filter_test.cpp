#include "algorithms/amcl/amcl_filter.hpp"

#include "algorithms/amcl/synthetic_room_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numbers>
#include <random>

namespace playerkit::amcl {
namespace amcl_filter_test {
constexpr double pi = std::numbers::pi;

// A robot driving waypoint to waypoint through the test room (turning in
// place, then driving straight), with wheel odometry that drifts: every step's
// distance and turn are misread by a few percent and a little heading slips.
class SimulatedRobot {
 public:
  SimulatedRobot(const geometry::Pose2& start, std::uint64_t seed) : truth_(start), rng_(seed) {}

  const geometry::Pose2& truth() const { return truth_; }
  const geometry::Pose2& odometry() const { return odometry_; }
  void teleport(const geometry::Pose2& pose) { truth_ = pose; }

  // One step of at most 5 cm or 0.1 rad towards `goal`; false once there.
  bool step_towards(const Eigen::Vector2d& goal) {
    const Eigen::Vector2d to_goal = goal - truth_.translation();
    if (to_goal.norm() < 1e-9) return false;
    const double turn = geometry::angle_difference(std::atan2(to_goal.y(), to_goal.x()), truth_.yaw);
    geometry::Pose2 delta;
    if (std::abs(turn) > 1e-9) {
      delta.yaw = std::clamp(turn, -0.1, 0.1);
    } else {
      delta.x = std::min(0.05, to_goal.norm());
    }
    move(delta);
    return true;
  }

  void move(const geometry::Pose2& delta) {
    truth_ = truth_.compose(delta);
    std::normal_distribution<double> gain(1.0, 0.03), slip(0.0, 0.002);
    const geometry::Pose2 measured{delta.x * gain(rng_), delta.y * gain(rng_),
                                   delta.yaw * gain(rng_) + slip(rng_)};
    odometry_ = odometry_.compose(measured);
  }

  LaserScan scan(const grid::OccupancyGrid& map) {
    test::LaserSpec spec;
    spec.max_range = 12.0;
    return test::simulate_scan(map, truth_, spec, 0.02, &rng_);
  }

 private:
  geometry::Pose2 truth_;
  geometry::Pose2 odometry_{10.0, -3.0, 1.0};  // an odometry frame unrelated to the map's
  std::mt19937_64 rng_;
};

// A loop around the room, clear of the box and the pillar.
const std::vector<Eigen::Vector2d> loop{{8.5, 1.0}, {8.5, 5.0}, {3.5, 5.0}, {3.5, 3.0},
                                        {1.0, 3.0}, {1.0, 1.0}};

double distance(const geometry::Pose2& a, const geometry::Pose2& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

struct RunStatistics {
  std::size_t laser_updates = 0;
  double worst_error = 0.0;
};

// Drives the loop, feeding every step's odometry and scan to the filter;
// `after_update` sees each laser update.
template <typename AfterUpdate>
void drive(AmclFilter& filter, SimulatedRobot& robot, const grid::OccupancyGrid& map,
           const std::vector<Eigen::Vector2d>& waypoints, AfterUpdate after_update) {
  for (const Eigen::Vector2d& goal : waypoints) {
    while (robot.step_towards(goal)) {
      const LaserScan scan = robot.scan(map);
      if (filter.update(robot.odometry(), &scan)) after_update();
    }
  }
}

// Augmented MCL is off by default; these tests are about what it adds.
AmclParameters with_recovery() {
  AmclParameters parameters;
  parameters.alpha_slow = 0.001;
  parameters.alpha_fast = 0.1;
  return parameters;
}

TEST(AmclFilter, TracksALoopWithinTenCentimetres) {
  const auto map = test::make_room();
  SimulatedRobot robot({1.0, 1.0, 0.0}, 11);
  AmclFilter filter(AmclParameters{}, map, 42);
  filter.set_pose({1.05, 0.95, 0.05}, Eigen::Vector3d(0.01, 0.01, 0.005).asDiagonal());
  RunStatistics stats;
  drive(filter, robot, *map, loop, [&] {
    ++stats.laser_updates;
    if (stats.laser_updates < 3) return;  // let the first scans pull it in
    const Hypothesis best = filter.best();
    stats.worst_error = std::max(stats.worst_error, distance(best.mean, robot.truth()));
    EXPECT_LT(std::abs(geometry::angle_difference(best.mean.yaw, robot.truth().yaw)), 0.05);
  });
  EXPECT_GT(stats.laser_updates, 60u);  // ~25 m and 6 turns at 0.2 m / 30 deg
  EXPECT_LT(stats.worst_error, 0.1);
  EXPECT_EQ(filter.update_count(), stats.laser_updates);
}

TEST(AmclFilter, TracksWithTheBeamModelToo) {
  const auto map = test::make_room();
  SimulatedRobot robot({1.0, 1.0, 0.0}, 12);
  AmclParameters parameters;
  parameters.laser_model = LaserModelType::beam;
  parameters.max_particles = 1000;
  AmclFilter filter(parameters, map, 43);
  filter.set_pose({1.0, 1.0, 0.0}, Eigen::Vector3d(0.01, 0.01, 0.005).asDiagonal());
  double worst = 0.0;
  std::size_t updates = 0;
  drive(filter, robot, *map, {{8.5, 1.0}, {8.5, 5.0}}, [&] {
    if (++updates < 3) return;
    worst = std::max(worst, distance(filter.best().mean, robot.truth()));
  });
  EXPECT_GT(updates, 30u);
  EXPECT_LT(worst, 0.1);
}

// The room is nearly symmetric under a half turn: from some starts the
// search settles on the mirror pose. It must find the robot from most.
TEST(AmclFilter, GlobalLocalizationConvergesInTheAsymmetricRoom) {
  const auto map = test::make_room();
  const auto converges = [&](std::uint64_t seed) {
    SimulatedRobot robot({4.5, 3.5, -0.5}, 13);
    AmclFilter filter(with_recovery(), map, seed);  // starts global
    std::size_t updates = 0;
    std::size_t first_good_update = 0;
    drive(filter, robot, *map, {{8.5, 1.0}, {8.5, 5.0}, {3.5, 5.0}}, [&] {
      ++updates;
      const bool good = distance(filter.best().mean, robot.truth()) < 0.1;
      if (good && first_good_update == 0) first_good_update = updates;
      if (!good) first_good_update = 0;
    });
    const Hypothesis best = filter.predict(robot.odometry());
    return first_good_update > 0 && first_good_update < 20 && distance(best.mean, robot.truth()) < 0.1 &&
           std::abs(geometry::angle_difference(best.mean.yaw, robot.truth().yaw)) < 0.05 && best.weight > 0.9;
  };
  int found = 0;
  for (std::uint64_t seed = 1; seed <= 16; ++seed) found += converges(seed) ? 1 : 0;
  // 14 measured (12 before short readings were left out once the search
  // ends). Over seeds 1-40 before: 31 (a 1.5-like start of max_particles
  // without the search's ceiling: 28).
  EXPECT_GE(found, 11) << "of 16 starts";
}

// A global start covers the free space at global_particles_per_square_metre
// (the room: 55 m^2 free), within [max_particles, global_particles_most].
TEST(AmclFilter, AGlobalStartDrawsParticlesByTheFreeArea) {
  const auto map = test::make_room();
  std::size_t free_cells = 0;
  for (int row = 0; row < map->height(); ++row) {
    for (int col = 0; col < map->width(); ++col) free_cells += map->at(col, row) == grid::CellState::free ? 1 : 0;
  }
  const double free_area = static_cast<double>(free_cells) * map->resolution() * map->resolution();
  AmclParameters parameters;
  AmclFilter filter(parameters, map, 3);
  EXPECT_TRUE(filter.searching());
  EXPECT_EQ(filter.particles().size(),
            static_cast<std::size_t>(parameters.global_particles_per_square_metre * free_area));
  EXPECT_EQ(filter.particles().size(), filter.global_particles());

  parameters.global_particles_most = 5100;
  EXPECT_EQ(AmclFilter(parameters, map, 3).particles().size(), 5100u);
  parameters.global_particles_per_square_metre = 1.0;  // never fewer than max_particles
  EXPECT_EQ(AmclFilter(parameters, map, 3).particles().size(), parameters.max_particles);
  parameters.max_particles = 8000;  // nor when the most is below them
  EXPECT_EQ(AmclFilter(parameters, map, 3).particles().size(), 8000u);

  filter.set_pose({1.0, 1.0, 0.0}, Eigen::Vector3d(0.01, 0.01, 0.005).asDiagonal());
  EXPECT_FALSE(filter.searching());
  EXPECT_EQ(filter.particles().size(), AmclParameters{}.max_particles);
}

// The search ends once one place has held the belief for
// search_end_updates updates; then max_particles caps KLD again and
// recovery is as configured (off by default).
TEST(AmclFilter, TheSearchEndsWhenOnePlaceHoldsTheBelief) {
  const auto map = test::make_room();
  SimulatedRobot robot({4.5, 3.5, -0.5}, 13);
  AmclParameters parameters;
  parameters.search_end_updates = 5;
  AmclFilter filter(parameters, map, 2);
  std::size_t updates = 0;
  std::size_t ended_at = 0;
  std::size_t most_after_the_end = 0;
  double injection_after_the_end = 0.0;
  double weight_at_the_end = 0.0;
  drive(filter, robot, *map, {{8.5, 1.0}, {8.5, 5.0}, {3.5, 5.0}}, [&] {
    ++updates;
    if (filter.searching()) return;
    if (ended_at == 0) {
      ended_at = updates;
      weight_at_the_end = filter.hypotheses().front().weight;
    }
    most_after_the_end = std::max(most_after_the_end, filter.particles().size());
    injection_after_the_end = std::max(injection_after_the_end, filter.injection_probability());
  });
  ASSERT_GE(ended_at, 5u);  // five updates in a row at the least
  EXPECT_GE(weight_at_the_end, parameters.search_end_weight);
  EXPECT_LE(most_after_the_end, parameters.max_particles);
  EXPECT_EQ(injection_after_the_end, 0.0);
}

TEST(AmclFilter, KldAdaptsTheParticleCount) {
  const auto map = test::make_room();
  AmclFilter filter(AmclParameters{}, map, 46);  // starts global
  // Scans without a single return carry no information: the belief stays
  // spread over the room and KLD keeps every particle.
  LaserScan blind = test::simulate_scan(*map, {5, 3, 0});
  for (double& range : blind.ranges) range = blind.max_range;
  ASSERT_TRUE(filter.update({0, 0, 0}, &blind));
  ASSERT_TRUE(filter.update({0.3, 0, 0}, &blind));  // second update resamples
  EXPECT_EQ(filter.particles().size(), filter.global_particles());

  // Tracking a known pose, it keeps a small fraction of that.
  SimulatedRobot robot({1.0, 1.0, 0.0}, 16);
  filter.set_pose({1.0, 1.0, 0.0}, Eigen::Vector3d(0.01, 0.01, 0.005).asDiagonal());
  std::size_t most = 0;
  std::size_t updates = 0;
  drive(filter, robot, *map, {{8.5, 1.0}}, [&] {
    if (++updates > 4) most = std::max(most, filter.particles().size());
  });
  EXPECT_GT(updates, 20u);
  EXPECT_LT(most, 1500u);
}

// Kidnapped in the nearly symmetric room, the filter must find the robot
// again from most random streams (one seed proved nothing either way).
TEST(AmclFilter, AugmentedMclRecoversFromAKidnap) {
  const auto map = test::make_room();
  const auto recovers = [&](std::uint64_t seed) {
    SimulatedRobot robot({1.0, 1.0, 0.0}, 14);
    AmclFilter filter(with_recovery(), map, seed);
    filter.set_pose({1.0, 1.0, 0.0}, Eigen::Vector3d(0.01, 0.01, 0.005).asDiagonal());
    drive(filter, robot, *map, {{8.5, 1.0}, {8.5, 3.5}}, [] {});
    if (distance(filter.predict(robot.odometry()).mean, robot.truth()) >= 0.1) return false;

    // Picked up and put down elsewhere; odometry knows nothing of it.
    robot.teleport({4.0, 4.0, pi});
    std::size_t updates_until_recovered = 0;
    std::size_t updates = 0;
    const std::vector<Eigen::Vector2d> route{{1.0, 3.0}, {1.0, 1.0}, {8.5, 1.0}, {8.5, 5.0}};
    drive(filter, robot, *map, route, [&] {
      ++updates;
      const bool on_truth = distance(filter.best().mean, robot.truth()) < 0.2;
      if (on_truth && updates_until_recovered == 0) updates_until_recovered = updates;
      if (!on_truth) updates_until_recovered = 0;  // must stay recovered
    });
    return updates_until_recovered > 0 && updates_until_recovered <= 60;
  };
  int recovered = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) recovered += recovers(seed) ? 1 : 0;
  // 9 measured; 24 of seeds 1-30, with the ziggurat's deviates as with
  // std::normal_distribution's.
  EXPECT_GE(recovered, 8) << "of 12 kidnaps";
}

TEST(AmclFilter, WithoutRecoveryAKidnapIsNotNoticed) {
  // The control for the test above: alpha 0, 0 (Player 1.5's behaviour).
  const auto map = test::make_room();
  SimulatedRobot robot({1.0, 1.0, 0.0}, 14);
  AmclParameters parameters;
  parameters.alpha_slow = parameters.alpha_fast = 0.0;
  AmclFilter filter(parameters, map, 45);
  filter.set_pose({1.0, 1.0, 0.0}, Eigen::Vector3d(0.01, 0.01, 0.005).asDiagonal());
  drive(filter, robot, *map, {{8.5, 1.0}, {8.5, 3.5}}, [] {});
  robot.teleport({4.0, 4.0, pi});
  drive(filter, robot, *map, {{1.0, 3.0}, {1.0, 1.0}}, [] {});
  EXPECT_GT(distance(filter.predict(robot.odometry()).mean, robot.truth()), 1.0);
  EXPECT_EQ(filter.injection_probability(), 0.0);
}

// People crowd round a robot turning in place near a wall: bodies (discs of
// 0.2 m radius) in a ring `near`-`far` m away, shifting between scans, hide
// most of every scan for two full turns. Then they leave and the robot
// drives on.
struct Crowd {
  int people = 8;
  double near = 0.5, far = 1.2;  // m, body centres from the robot
  double body_radius = 0.25;     // m
};

struct CrowdRun {
  double worst_error = 0.0;      // m, over every laser update
  double worst_yaw_error = 0.0;  // rad
  double final_error = 0.0;      // m, after the drive
  double mean_matching_share = 0.0;  // of the beams, those that saw the room
};

void place_body(grid::OccupancyGrid& map, const Eigen::Vector2d& centre, double radius) {
  const Eigen::Vector2i low = map.world_to_cell(centre - Eigen::Vector2d::Constant(radius));
  const Eigen::Vector2i high = map.world_to_cell(centre + Eigen::Vector2d::Constant(radius));
  for (int row = std::max(low.y(), 0); row <= std::min(high.y(), map.height() - 1); ++row) {
    for (int col = std::max(low.x(), 0); col <= std::min(high.x(), map.width() - 1); ++col) {
      if ((map.cell_centre({col, row}) - centre).norm() <= radius) map.set(col, row, grid::CellState::occupied);
    }
  }
}

CrowdRun turn_in_a_crowd(std::uint64_t seed, const Crowd& crowd, const AmclParameters& parameters) {
  const auto map = test::make_room();
  SimulatedRobot robot({1.0, 3.0, 0.0}, 100 + seed);  // 0.9 m from the west wall
  AmclFilter filter(parameters, map, seed);
  filter.set_pose(robot.truth(), Eigen::Vector3d(0.01, 0.01, 0.005).asDiagonal());
  CrowdRun run;
  const auto check = [&] {
    const Hypothesis best = filter.best();
    run.worst_error = std::max(run.worst_error, distance(best.mean, robot.truth()));
    run.worst_yaw_error = std::max(
        run.worst_yaw_error, std::abs(geometry::angle_difference(best.mean.yaw, robot.truth().yaw)));
  };
  std::mt19937_64 crowd_rng(seed);
  std::uniform_real_distribution<double> reach(crowd.near, crowd.far), shuffle(-0.15, 0.15);
  constexpr int steps = 126;  // two turns at 0.1 rad
  std::size_t matching = 0, beams = 0;
  for (int step = 0; step < steps; ++step) {
    robot.move({0.0, 0.0, 0.1});
    grid::OccupancyGrid crowded = *map;
    for (int k = 0; k < crowd.people; ++k) {
      const double bearing = 2 * pi * k / crowd.people + shuffle(crowd_rng);
      place_body(crowded, robot.truth().translation() + reach(crowd_rng) * Eigen::Vector2d(std::cos(bearing), std::sin(bearing)), crowd.body_radius);
    }
    const LaserScan scan = robot.scan(crowded);
    const LaserScan clear = test::simulate_scan(*map, robot.truth(), {.max_range = 12.0});
    for (std::size_t b = 0; b < scan.ranges.size(); ++b) {
      matching += std::abs(scan.ranges[b] - clear.ranges[b]) < 0.1 ? 1 : 0;
    }
    beams += scan.ranges.size();
    if (filter.update(robot.odometry(), &scan)) check();
  }
  run.mean_matching_share = static_cast<double>(matching) / static_cast<double>(beams);
  drive(filter, robot, *map, {{8.5, 5.0}, {8.5, 1.0}}, check);
  run.final_error = distance(filter.predict(robot.odometry()).mean, robot.truth());
  return run;
}

// A fifth of each scan sees the room; the rest are people who, seen from a
// pose a little off, line up with the wall behind them. The heading may
// wander by the motion model's spread while so little is seen (0.24 rad at
// worst over seeds 1-12); the position holds (0.107 m at worst).
TEST(AmclFilter, KeepsTheTrackTurningInACrowd) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const CrowdRun run = turn_in_a_crowd(seed, Crowd{}, AmclParameters{});
    EXPECT_LT(run.mean_matching_share, 0.25) << "seed " << seed;  // as dense as claimed
    EXPECT_LT(run.worst_error, 0.15) << "seed " << seed;
    EXPECT_LT(run.worst_yaw_error, 0.3) << "seed " << seed;
    EXPECT_LT(run.final_error, 0.1) << "seed " << seed;
  }
}

// The control: scored beam by beam, the people pull the estimate off and
// the drive after carries it metres away (11 of seeds 1-12).
TEST(AmclFilter, WithoutTheShortReadingFilterACrowdPullsTheTrackAway) {
  AmclParameters parameters;
  parameters.short_reading_filter = false;
  int lost = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    lost += turn_in_a_crowd(seed, Crowd{}, parameters).final_error > 1.0 ? 1 : 0;
  }
  EXPECT_GE(lost, 4) << "of 6 runs";
}

// A ring so close that almost nothing of the room shows: no scan says which
// way the robot faces, so the heading spreads, but the position must not run
// off to where the bodies fit, and the room's first clear scans settle it.
TEST(AmclFilter, FindsTheTrackAgainAfterACrowdHidesTheRoom) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const CrowdRun run =
        turn_in_a_crowd(seed, Crowd{.people = 10, .near = 0.45, .far = 0.8}, AmclParameters{});
    EXPECT_LT(run.mean_matching_share, 0.05) << "seed " << seed;
    EXPECT_LT(run.worst_error, 0.2) << "seed " << seed;
    EXPECT_LT(run.final_error, 0.1) << "seed " << seed;
  }
}

std::vector<Particle> run_short(std::uint64_t filter_seed) {
  const auto map = test::make_room();
  SimulatedRobot robot({4.5, 3.5, -0.5}, 15);
  AmclFilter filter(AmclParameters{}, map, filter_seed);
  drive(filter, robot, *map, {{8.5, 1.0}}, [] {});
  return {filter.particles().begin(), filter.particles().end()};
}

bool bit_identical(const std::vector<Particle>& a, const std::vector<Particle>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double x[4] = {a[i].pose.x, a[i].pose.y, a[i].pose.yaw, a[i].weight};
    const double y[4] = {b[i].pose.x, b[i].pose.y, b[i].pose.yaw, b[i].weight};
    if (std::memcmp(x, y, sizeof x) != 0) return false;
  }
  return true;
}

TEST(AmclFilter, SameSeedAndInputsGiveBitIdenticalParticles) {
  const auto first = run_short(7);
  EXPECT_TRUE(bit_identical(first, run_short(7)));
  EXPECT_FALSE(bit_identical(first, run_short(8)));
}

LaserScan room_scan(const grid::OccupancyGrid& map, const geometry::Pose2& pose) {
  return test::simulate_scan(map, pose);
}

TEST(AmclFilter, UpdatesOnlyAfterMovingPastTheThresholds) {
  const auto map = test::make_room();
  AmclFilter filter(AmclParameters{}, map, 1);
  filter.set_pose({3, 3, 0}, Eigen::Vector3d(0.01, 0.01, 0.01).asDiagonal());
  const LaserScan scan = room_scan(*map, {3, 3, 0});
  EXPECT_FALSE(filter.update({0, 0, 0}, nullptr));  // records the origin
  EXPECT_TRUE(filter.update({0, 0, 0}, &scan));     // first scan after set_pose
  EXPECT_FALSE(filter.update({0.1, 0, 0}, &scan));
  EXPECT_FALSE(filter.update({0.19, 0, 0.5}, &scan));
  EXPECT_TRUE(filter.update({0.21, 0, 0}, &scan));   // 0.21 m
  EXPECT_FALSE(filter.update({0.21, 0, 0.5}, &scan));
  EXPECT_TRUE(filter.update({0.21, 0, 0.53}, &scan));  // 30.4 degrees
  EXPECT_EQ(filter.update_count(), 3u);
}

TEST(AmclFilter, FirstCallWithAScanUpdatesWithoutMotion) {
  const auto map = test::make_room();
  AmclFilter filter(AmclParameters{}, map, 2);
  filter.set_pose({3, 3, 0}, Eigen::Vector3d(0.04, 0.04, 0.01).asDiagonal());
  const LaserScan scan = room_scan(*map, {3, 3, 0});
  EXPECT_TRUE(filter.update({5, 5, 1}, &scan));
  const Hypothesis best = filter.best();
  EXPECT_LT(distance(best.mean, {3, 3, 0}), 0.1);
}

TEST(AmclFilter, PredictCarriesTheEstimateForwardByOdometry) {
  const auto map = test::make_room();
  AmclParameters parameters;
  AmclFilter filter(parameters, map, 3);
  filter.set_pose({3, 3, pi / 2}, Eigen::Matrix3d::Identity() * 1e-6);
  filter.update({10, 10, 0}, nullptr);
  const Hypothesis now = filter.predict({10.1, 10, 0.05});  // under the thresholds
  const Hypothesis best = filter.best();
  const geometry::Pose2 expected = best.mean.compose({0.1, 0.0, 0.05});
  EXPECT_NEAR(now.mean.x, expected.x, 1e-12);
  EXPECT_NEAR(now.mean.y, expected.y, 1e-12);
  EXPECT_NEAR(now.mean.yaw, expected.yaw, 1e-12);
}

TEST(AmclFilter, HypothesesAreSortedCappedAndNormalised) {
  // Globally localizing from one spot: after two scans several places of
  // the room still fit.
  const auto map = test::make_room();
  AmclParameters parameters = with_recovery();
  parameters.max_hypotheses = 2;
  AmclFilter filter(parameters, map, 4);
  const LaserScan scan = room_scan(*map, {5.0, 3.0, 0.0});
  filter.update({0, 0, 0}, &scan);
  filter.update({0, 0, 0.6}, &scan);
  const auto hypotheses = filter.hypotheses();
  ASSERT_EQ(hypotheses.size(), 2u);
  double total = 0.0;
  for (std::size_t i = 0; i < hypotheses.size(); ++i) {
    total += hypotheses[i].weight;
    if (i > 0) {
      EXPECT_GE(hypotheses[i - 1].weight, hypotheses[i].weight);
    }
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
  EXPECT_EQ(filter.best().mean, hypotheses.front().mean);
}

TEST(AmclFilter, SelectiveResamplingKeepsWeightsUntilTheyDegenerate) {
  const auto map = test::make_room();
  AmclParameters parameters;
  parameters.selective_resampling = true;
  AmclFilter filter(parameters, map, 5);
  filter.set_pose({3, 3, 0}, Eigen::Vector3d(0.01, 0.01, 0.01).asDiagonal());
  const LaserScan scan = room_scan(*map, {3, 3, 0});
  filter.update({0, 0, 0}, &scan);
  // The first scan sharpens the spread-out weights: resampled to fewer
  // particles of equal weight.
  EXPECT_LT(filter.particles().size(), 5000u);
  const double first = filter.particles().front().weight;
  for (const Particle& p : filter.particles()) EXPECT_EQ(p.weight, first);
}

TEST(AmclFilter, LiveParameterChangesApply) {
  const auto map = test::make_room();
  AmclFilter filter(AmclParameters{}, map, 6);
  AmclParameters changed = filter.parameters();
  changed.max_particles = 500;
  changed.global_particles_per_square_metre = 0.0;  // a global start of max_particles, as 1.5
  changed.likelihood_max_distance = 1.0;
  filter.set_parameters(changed);
  EXPECT_EQ(filter.parameters().max_particles, 500u);
  filter.set_global();
  EXPECT_EQ(filter.particles().size(), 500u);
  changed.min_particles = 1000;
  EXPECT_THROW(filter.set_parameters(changed), std::invalid_argument);
  EXPECT_EQ(filter.parameters().min_particles, 100u);
}

TEST(AmclFilter, RejectsAMapWithoutFreeSpace) {
  auto solid = std::make_shared<grid::OccupancyGrid>(10, 10, 0.1, Eigen::Vector2d::Zero(),
                                                     grid::CellState::occupied);
  EXPECT_THROW(AmclFilter(AmclParameters{}, solid, 1), std::invalid_argument);
  EXPECT_THROW(AmclFilter(AmclParameters{}, nullptr, 1), std::invalid_argument);
}

}  // namespace amcl_filter_test
}  // namespace playerkit::amcl
