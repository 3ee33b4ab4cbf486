#include "algorithms/amcl/likelihood_field_model.hpp"

#include "algorithms/amcl/laser_model_test_support.hpp"
#include "algorithms/amcl/likelihood_field_lanes.hpp"
#include "algorithms/amcl/synthetic_room_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace playerkit::amcl {
namespace likelihood_field_model_test {

using test::scores;

TEST(LikelihoodFieldModel, EndpointLikelihoodIsTheHitGaussianPlusRandom) {
  const LaserModelSettings s;
  const double peak = 0.95 / (std::sqrt(2 * std::numbers::pi) * 0.2);
  EXPECT_NEAR(LikelihoodFieldModel::log_endpoint_likelihood(0.0, 8.0, s),
              std::log(peak + 0.05 / 8.0), 1e-12);
  EXPECT_NEAR(LikelihoodFieldModel::log_endpoint_likelihood(0.2, 8.0, s),
              std::log(peak * std::exp(-0.5) + 0.05 / 8.0), 1e-12);
  EXPECT_NEAR(LikelihoodFieldModel::log_endpoint_likelihood(5.0, 8.0, s), std::log(0.05 / 8.0),
              1e-9);
}

TEST(LikelihoodFieldModel, TruePoseBeatsPosesOffByThirtyCentimetresOrTenDegrees) {
  const auto map = test::make_room();
  LikelihoodFieldModel model(*map, 2.0);
  for (const geometry::Pose2& truth :
       {test::true_pose, geometry::Pose2{8.0, 4.5, -2.5}, geometry::Pose2{4.0, 1.0, 3.1}}) {
    const auto particles = test::true_and_offset_poses(truth);
    const auto s = scores(model, particles, test::simulate_scan(*map, truth));
    for (std::size_t i = 1; i < s.size(); ++i) {
      // By a clear margin: at least 3 nats (a factor of 20).
      EXPECT_GT(s[0] - s[i], 3.0) << "offset pose " << i;
    }
  }
}

TEST(LikelihoodFieldModel, ScoreAtTheTruePoseIsNearThePeak) {
  // A noise-free scan's endpoints lie on walls, within half a cell (plus the
  // ray caster's own cell rounding) of an occupied cell's centre.
  const auto map = test::make_room();
  LikelihoodFieldModel model(*map, 2.0);
  const std::vector<Particle> truth{{test::true_pose, 1.0}};
  const auto s = scores(model, truth, test::simulate_scan(*map, test::true_pose));
  const double peak = LikelihoodFieldModel::log_endpoint_likelihood(0.0, 8.0, LaserModelSettings{});
  EXPECT_GT(s[0], 30 * (peak - 0.1));
  EXPECT_LE(s[0], 30 * peak + 1e-9);
}

TEST(LikelihoodFieldModel, NoReturnReadingsNeitherRewardNorPenalise) {
  const auto map = test::make_room();
  LikelihoodFieldModel model(*map, 2.0);
  const auto particles = test::true_and_offset_poses();
  LaserScan scan = test::simulate_scan(*map, test::true_pose);
  const auto before = scores(model, particles, scan, 1000);

  // Every reading "no return": the scan carries no evidence at all.
  LaserScan blind = scan;
  for (double& r : blind.ranges) r = blind.max_range;
  for (double s : scores(model, particles, blind, 1000)) EXPECT_EQ(s, 0.0);

  // Appending no-return readings in any direction changes nothing.
  LaserScan padded = scan;
  for (int i = 0; i < 20; ++i) {
    padded.ranges.push_back(padded.max_range + 1.0);
    padded.bearings.push_back(0.3 * i);
  }
  const auto after = scores(model, particles, padded, 1000);
  for (std::size_t i = 0; i < particles.size(); ++i) EXPECT_DOUBLE_EQ(before[i], after[i]);
}

// One reading straight ahead, the laser at the robot's centre.
LaserScan one_reading(double range) {
  LaserScan scan;
  scan.ranges = {range};
  scan.bearings = {0.0};
  return scan;
}

TEST(LikelihoodFieldModel, EndpointsOffTheMapScoreAsFarFromAnything) {
  const auto map = test::make_room();
  LikelihoodFieldModel model(*map, 2.0);
  const std::vector<Particle> outside{{{-20.0, -20.0, 0.0}, 1.0}};
  const auto s = scores(model, outside, one_reading(5.0));
  EXPECT_NEAR(s[0], LikelihoodFieldModel::log_endpoint_likelihood(2.0, 8.0, LaserModelSettings{}),
              1e-6);
}

// Distances are kept to 255ths of the cap: an endpoint 0.35 m (seven cells)
// from the east wall's first occupied cell scores as 0.35 m within 4 mm.
TEST(LikelihoodFieldModel, AnEndpointScoresByItsDistanceWithinFourMillimetres) {
  const auto map = test::make_room();
  LikelihoodFieldModel model(*map, 2.0);
  // The endpoint at (9.575, 3.025), a cell centre; the wall's cells start at
  // 9.9, their first centre at 9.925.
  const std::vector<Particle> particle{{{8.575, 3.025, 0.0}, 1.0}};
  const auto s = scores(model, particle, one_reading(1.0));
  const auto at = [](double distance) {
    return LikelihoodFieldModel::log_endpoint_likelihood(distance, 8.0, LaserModelSettings{});
  };
  EXPECT_NEAR(s[0], at(0.35), std::abs(at(0.354) - at(0.35)));
  EXPECT_GT(std::abs(at(0.354) - at(0.35)), 1e-3);  // the tolerance is not vacuous
}

TEST(LikelihoodFieldModel, SensorOffsetIsApplied) {
  // The same world endpoints seen by a laser mounted 0.5 m forward: the
  // robot pose 0.5 m behind the true sensor scores like the true pose.
  const auto map = test::make_room();
  LikelihoodFieldModel model(*map, 2.0);
  test::LaserSpec spec;
  spec.sensor_pose = {0.5, 0.0, 0.0};
  const geometry::Pose2 robot{3.0, 3.0, 0.0};
  const LaserScan scan = test::simulate_scan(*map, robot, spec);
  const std::vector<Particle> particles{{robot, 1.0}, {{3.5, 3.0, 0.0}, 1.0}};
  const auto s = scores(model, particles, scan);
  EXPECT_GT(s[0] - s[1], 3.0);
}

// Scored four endpoints at a time (AVX2, where the processor has it) or
// one at a time, every particle's score is the same bit for bit: with and
// without beam skipping, for beam counts that do not fill the last four,
// and for particles whose endpoints fall off the map.
TEST(LikelihoodFieldModel, VectorAndScalarScoringAgreeBitForBit) {
  const auto map = test::make_room();
  std::mt19937 random(17);
  std::uniform_real_distribution<double> x(-2.0, 12.0), y(-2.0, 8.0), yaw(-std::numbers::pi, std::numbers::pi);
  std::vector<Particle> particles;
  for (int i = 0; i < 500; ++i) particles.push_back({{x(random), y(random), yaw(random)}, 1.0 / 500});
  int off_map = 0;
  for (const int beams : {1, 7, 30, 61}) {
    test::LaserSpec spec;
    spec.beams = static_cast<std::size_t>(beams);
    LaserScan scan = test::simulate_scan(*map, test::true_pose, spec);
    if (beams > 1) scan.ranges[1] = scan.max_range;  // a no-return reading
    PreparedBeams prepared;
    prepare_beams(scan, static_cast<std::size_t>(beams), prepared);
    for (const bool beam_skip : {false, true}) {
      LaserModelSettings settings;
      settings.beam_skip = beam_skip;
      LikelihoodFieldModel vector(*map, 2.0), scalar(*map, 2.0);
      scalar.use_vector_scoring(false);
      std::vector<double> by_vector(particles.size()), by_scalar(particles.size());
      vector.log_likelihoods(particles, prepared, settings, by_vector);
      scalar.log_likelihoods(particles, prepared, settings, by_scalar);
      for (std::size_t i = 0; i < particles.size(); ++i) {
        ASSERT_EQ(by_vector[i], by_scalar[i]) << beams << " beams, skip " << beam_skip << ", particle " << i;
      }
      const auto hits = std::count(prepared.no_return.begin(), prepared.no_return.end(), false);
      const double far =
          static_cast<double>(hits) * LikelihoodFieldModel::log_endpoint_likelihood(2.0, scan.max_range, settings);
      off_map += static_cast<int>(std::count_if(by_scalar.begin(), by_scalar.end(),
                                                [far](double score) { return score <= far + 1e-3; }));
    }
  }
  EXPECT_GT(off_map, 10);  // some particles saw only the far value: off the map
#if defined(__x86_64__)
  EXPECT_EQ(field_lanes::available(), __builtin_cpu_supports("avx2") != 0);
#endif
}

}  // namespace likelihood_field_model_test
}  // namespace playerkit::amcl
