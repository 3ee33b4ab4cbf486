#include "algorithms/amcl/motion_model.hpp"

#include "algorithms/amcl/pose_estimate.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace playerkit::amcl {
namespace motion_model_test {

constexpr double pi = std::numbers::pi;

void expect_pose_near(const geometry::Pose2& actual, const geometry::Pose2& expected,
                      double tolerance = 1e-12) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(geometry::angle_difference(actual.yaw, expected.yaw), 0.0, tolerance);
}

std::vector<Particle> copies(const geometry::Pose2& pose, std::size_t count) {
  return std::vector<Particle>(count, Particle{pose, 1.0 / static_cast<double>(count)});
}

TEST(DifferentialMotion, WithoutNoiseComposesTheOdometryDelta) {
  std::mt19937_64 rng(1);
  const geometry::Pose2 start{1.0, 2.0, 0.3};
  const struct {
    geometry::Pose2 from, to;
  } cases[] = {
      {{0, 0, 0}, {1, 0, 0}},                    // forward
      {{0, 0, 0}, {0, 0, 1.0}},                  // rotate in place
      {{5, 5, 0.2}, {5.8, 5.9, 1.4}},            // arc
      {{0, 0, 0}, {-0.7, 0.1, -0.2}},            // reversing
      {{-3, 1, 3.0}, {-3.4, 1.3, -2.9}},         // across the +-pi seam
      {{0, 0, 0}, {0.005, 0.004, 0.0}},          // jitter shorter than a centimetre
  };
  for (const auto& c : cases) {
    std::vector<Particle> particles = copies(start, 1);
    apply_differential_motion(particles, c.from, c.to, MotionNoise{}, rng);
    expect_pose_near(particles[0].pose, start.compose(c.from.between(c.to)));
  }
}

TEST(DifferentialMotion, ReversingIsANegativeTranslationNotAHalfTurn) {
  const DifferentialMotion motion = decompose_differential({0, 0, 0.5}, {-std::cos(0.5), -std::sin(0.5), 0.5});
  EXPECT_NEAR(motion.translation, -1.0, 1e-12);
  EXPECT_NEAR(motion.rotation1, 0.0, 1e-12);
  EXPECT_NEAR(motion.rotation2, 0.0, 1e-12);

  // With rotation-from-rotation noise only, straight reversing adds no yaw
  // noise (the textbook decomposition would turn by pi twice and add
  // var = a1 pi^2 to each turn).
  MotionNoise noise;
  noise.rotation_from_rotation = 0.05;
  noise.translation_from_translation = 0.01;
  std::mt19937_64 rng(2);
  std::vector<Particle> particles = copies({0, 0, 0}, 5000);
  apply_differential_motion(particles, {0, 0, 0}, {-1, 0, 0}, noise, rng);
  const Hypothesis estimate = weighted_estimate(particles);
  EXPECT_NEAR(estimate.mean.x, -1.0, 0.01);
  EXPECT_NEAR(estimate.covariance(2, 2), 0.0, 1e-20);
  EXPECT_NEAR(estimate.covariance(0, 0), 0.01, 0.001);
}

TEST(DifferentialMotion, ForwardNoiseMatchesTheModelsVariances) {
  // d = 1 forward, a2 = 0.01, a3 = 0.04: rot1 and rot2 each have variance
  // 0.01, the translation 0.04. So yaw variance = 0.02; x = (1 + e_t) cos
  // e_r1 has variance ~0.04 and mean exp(-0.01 / 2); y = (1 + e_t) sin e_r1
  // has variance ~0.01 (1 + 0.04).
  MotionNoise noise;
  noise.rotation_from_translation = 0.01;
  noise.translation_from_translation = 0.04;
  std::mt19937_64 rng(3);
  std::vector<Particle> particles = copies({0, 0, 0}, 40000);
  apply_differential_motion(particles, {2, 3, pi / 2}, {2, 4, pi / 2}, noise, rng);
  const Hypothesis e = weighted_estimate(particles);
  EXPECT_NEAR(e.mean.x, std::exp(-0.005), 0.003);
  EXPECT_NEAR(e.mean.y, 0.0, 0.003);
  EXPECT_NEAR(e.mean.yaw, 0.0, 0.003);
  EXPECT_NEAR(e.covariance(0, 0), 0.04, 0.04 * 0.05);
  EXPECT_NEAR(e.covariance(1, 1), 0.0104, 0.0104 * 0.05);
  EXPECT_NEAR(e.covariance(2, 2), 0.02, 0.02 * 0.05);
  // y and yaw both follow rot1: correlated, cov(y, yaw) ~ var(rot1) = 0.01.
  EXPECT_NEAR(e.covariance(1, 2), 0.01, 0.001);
}

TEST(DifferentialMotion, RotationNoiseMatchesTheModelsVariances) {
  // Turning 1 rad in place: var(rot) = a1 = 0.05, var(trans) = a4 * 1 = 0.01.
  MotionNoise noise;
  noise.rotation_from_rotation = 0.05;
  noise.translation_from_rotation = 0.01;
  std::mt19937_64 rng(4);
  std::vector<Particle> particles = copies({0, 0, 0}, 40000);
  apply_differential_motion(particles, {0, 0, 0}, {0, 0, 1.0}, noise, rng);
  const Hypothesis e = weighted_estimate(particles);
  EXPECT_NEAR(e.mean.yaw, 1.0, 0.005);
  EXPECT_NEAR(e.covariance(2, 2), 0.05, 0.05 * 0.05);
  EXPECT_NEAR(e.covariance(0, 0), 0.01, 0.01 * 0.05);
  EXPECT_NEAR(e.covariance(1, 1), 0.0, 1e-20);
}

TEST(OmniMotion, WithoutNoiseComposesTheOdometryDelta) {
  std::mt19937_64 rng(5);
  const geometry::Pose2 start{1.0, 2.0, 0.3};
  for (const geometry::Pose2& to : {geometry::Pose2{0, 1, 0}, geometry::Pose2{-0.5, 0.2, 0.4},
                                    geometry::Pose2{0, 0, -1.0}}) {
    std::vector<Particle> particles = copies(start, 1);
    apply_omni_motion(particles, {0, 0, 0}, to, MotionNoise{}, rng);
    expect_pose_near(particles[0].pose, start.compose(to));
  }
  // Sideways: 1 m to the robot's left.
  std::vector<Particle> particles = copies({0, 0, pi / 2}, 1);
  apply_omni_motion(particles, {3, 3, 0}, {3, 4, 0}, MotionNoise{}, rng);
  expect_pose_near(particles[0].pose, {-1, 0, pi / 2});
}

TEST(OmniMotion, SidewaysNoiseMatchesTheModelsVariances) {
  // 1 m sideways: along the travel (y) var a3 = 0.01, across it (x) var
  // a5 = 0.04, yaw var a2 = 0.01.
  MotionNoise noise;
  noise.rotation_from_translation = 0.01;
  noise.translation_from_translation = 0.01;
  noise.strafe_from_translation = 0.04;
  std::mt19937_64 rng(6);
  std::vector<Particle> particles = copies({0, 0, 0}, 40000);
  apply_omni_motion(particles, {0, 0, 0}, {0, 1, 0}, noise, rng);
  const Hypothesis e = weighted_estimate(particles);
  EXPECT_NEAR(e.mean.y, 1.0, 0.003);
  EXPECT_NEAR(e.covariance(0, 0), 0.04, 0.04 * 0.05);
  EXPECT_NEAR(e.covariance(1, 1), 0.01, 0.01 * 0.05);
  EXPECT_NEAR(e.covariance(2, 2), 0.01, 0.01 * 0.05);
}

TEST(MotionModel, NoiseCoefficientsComeFromTheNamedParameters) {
  AmclParameters p;
  p.rotation_noise_from_rotation = 1;
  p.rotation_noise_from_translation = 2;
  p.translation_noise_from_translation = 3;
  p.translation_noise_from_rotation = 4;
  p.strafe_noise_from_translation = 5;
  const MotionNoise n = MotionNoise::from(p);
  EXPECT_EQ(n.rotation_from_rotation, 1);
  EXPECT_EQ(n.rotation_from_translation, 2);
  EXPECT_EQ(n.translation_from_translation, 3);
  EXPECT_EQ(n.translation_from_rotation, 4);
  EXPECT_EQ(n.strafe_from_translation, 5);
  EXPECT_EQ(n.translation_step, p.update_min_distance);
  EXPECT_EQ(n.rotation_step, p.update_min_angle);
}

TEST(MotionModel, AMoveOfManyStepsAddsTheirVariancesNotTheSquareOfItsLength) {
  // Up to two steps the textbook's square; beyond, |x| * two steps: the
  // variance grows with the length, and meets the square at two steps.
  EXPECT_DOUBLE_EQ(noise_square(0.3, 0.2), 0.09);
  EXPECT_DOUBLE_EQ(noise_square(-0.4, 0.2), 0.16);
  EXPECT_DOUBLE_EQ(noise_square(2.0, 0.2), 0.8);
  EXPECT_DOUBLE_EQ(noise_square(-2.0, 0.2), 0.8);
  EXPECT_DOUBLE_EQ(noise_square(2.0, 0.0), 4.0);  // no step: the textbook
  EXPECT_NEAR(noise_square(0.4 + 1e-9, 0.2), 0.16, 1e-9);  // continuous

  // 40 000 particles from the origin through one differential move.
  const auto moved = [](const MotionNoise& noise, const geometry::Pose2& to) {
    std::mt19937_64 rng(5);
    std::vector<Particle> particles = copies({0, 0, 0}, 40000);
    apply_differential_motion(particles, {0, 0, 0}, to, noise, rng);
    return weighted_estimate(particles);
  };
  // A 4 m drive with a3 = 0.1 and a 0.2 m step: var(trans) = 0.1 * 4 * 0.4,
  // sd 0.4 m (the textbook: 0.1 * 16, sd 1.26 m).
  const Hypothesis drive = moved({.translation_from_translation = 0.1, .translation_step = 0.2, .rotation_step = 0.5},
                                 {4, 0, 0});
  EXPECT_NEAR(drive.mean.x, 4.0, 0.01);
  EXPECT_NEAR(drive.covariance(0, 0), 0.16, 0.16 * 0.05);
  // A 2 rad turn with a1 = 0.05: rot1 is 0 here, rot2 = 2 rad, beyond two
  // 0.5 rad steps: var = 0.05 * 2 * 1.
  const Hypothesis turn = moved({.rotation_from_rotation = 0.05, .rotation_step = 0.5}, {0, 0, 2.0});
  EXPECT_NEAR(turn.covariance(2, 2), 0.1, 0.1 * 0.05);
}

}  // namespace motion_model_test
}  // namespace playerkit::amcl
