#include "algorithms/amcl/motion_model.hpp"

#include "algorithms/amcl/standard_normal.hpp"
#include "algorithms/geometry/sin_cos.hpp"

#include <cmath>
#include <numbers>

namespace playerkit::amcl {
namespace {

// The standard deviation of a variance, 0 for none (or a negative one).
double deviation_of(double variance) { return variance > 0.0 ? std::sqrt(variance) : 0.0; }

// A draw with that deviation; none drawn for 0, so that noise-free motion
// leaves the random numbers alone.
double sample_with_deviation(double deviation, const StandardNormal& standard_normal, std::mt19937_64& rng) {
  if (!(deviation > 0.0)) return 0.0;
  return deviation * standard_normal(rng);
}

}  // namespace

MotionNoise MotionNoise::from(const AmclParameters& p) {
  return {p.rotation_noise_from_rotation, p.rotation_noise_from_translation,
          p.translation_noise_from_translation, p.translation_noise_from_rotation,
          p.strafe_noise_from_translation, p.update_min_distance, p.update_min_angle};
}

double noise_square(double x, double step) {
  const double magnitude = std::abs(x);
  const double longest = kStepsAsOneMove * step;
  return step > 0.0 && magnitude > longest ? magnitude * longest : magnitude * magnitude;
}

DifferentialMotion decompose_differential(const geometry::Pose2& odometry_from,
                                          const geometry::Pose2& odometry_to) {
  const double dx = odometry_to.x - odometry_from.x;
  const double dy = odometry_to.y - odometry_from.y;
  const double turn = geometry::angle_difference(odometry_to.yaw, odometry_from.yaw);
  DifferentialMotion motion;
  motion.translation = std::hypot(dx, dy);
  if (motion.translation > 0.0) {
    motion.rotation1 = geometry::angle_difference(std::atan2(dy, dx), odometry_from.yaw);
    if (std::abs(motion.rotation1) > std::numbers::pi / 2) {
      // Travel points behind the robot: it reversed.
      motion.rotation1 = geometry::normalize_angle(motion.rotation1 + std::numbers::pi);
      motion.translation = -motion.translation;
    }
  }
  motion.rotation2 = geometry::normalize_angle(turn - motion.rotation1);
  return motion;
}

void apply_differential_motion(std::span<Particle> particles, const geometry::Pose2& odometry_from,
                               const geometry::Pose2& odometry_to, const MotionNoise& noise,
                               std::mt19937_64& rng) {
  const DifferentialMotion motion = decompose_differential(odometry_from, odometry_to);
  // For noise, a translation too short to have a direction turns only in rot2.
  const bool has_direction = std::abs(motion.translation) >= direction_noise_min_translation;
  const double rot1 = has_direction ? motion.rotation1 : 0.0;
  const double rot2 = has_direction ? motion.rotation2
                                    : geometry::normalize_angle(motion.rotation1 + motion.rotation2);
  const double trans2 = noise_square(motion.translation, noise.translation_step);
  const double rot1_square = noise_square(rot1, noise.rotation_step);
  const double rot2_square = noise_square(rot2, noise.rotation_step);
  const double rot1_variance = noise.rotation_from_rotation * rot1_square + noise.rotation_from_translation * trans2;
  const double trans_variance = noise.translation_from_translation * trans2 +
                                noise.translation_from_rotation * (rot1_square + rot2_square);
  const double rot2_variance = noise.rotation_from_rotation * rot2_square + noise.rotation_from_translation * trans2;

  const double rot1_deviation = deviation_of(rot1_variance);
  const double trans_deviation = deviation_of(trans_variance);
  const double rot2_deviation = deviation_of(rot2_variance);
  const StandardNormal standard_normal;
  for (Particle& particle : particles) {
    const double noisy_rot1 = motion.rotation1 + sample_with_deviation(rot1_deviation, standard_normal, rng);
    const double noisy_trans =
        motion.translation + sample_with_deviation(trans_deviation, standard_normal, rng);
    const double noisy_rot2 = motion.rotation2 + sample_with_deviation(rot2_deviation, standard_normal, rng);
    geometry::Pose2& pose = particle.pose;
    const double heading = pose.yaw + noisy_rot1;
    const geometry::SinCos direction = geometry::sin_cos(heading);
    pose.x += noisy_trans * direction.cos;
    pose.y += noisy_trans * direction.sin;
    pose.yaw = geometry::normalize_angle(heading + noisy_rot2);
  }
}

void apply_omni_motion(std::span<Particle> particles, const geometry::Pose2& odometry_from,
                       const geometry::Pose2& odometry_to, const MotionNoise& noise,
                       std::mt19937_64& rng) {
  const geometry::Pose2 delta = odometry_from.between(odometry_to);  // robot frame
  const double trans = std::hypot(delta.x, delta.y);
  const double rot = delta.yaw;
  // Noise along and across the direction of travel; with no travel, along
  // the robot's own axes.
  const Eigen::Vector2d along =
      trans > 0.0 ? Eigen::Vector2d(delta.x / trans, delta.y / trans) : Eigen::Vector2d(1.0, 0.0);
  const Eigen::Vector2d across(-along.y(), along.x());
  const double trans2 = noise_square(trans, noise.translation_step);
  const double rot2 = noise_square(rot, noise.rotation_step);
  const double along_sd = std::sqrt(noise.translation_from_translation * trans2 + noise.translation_from_rotation * rot2);
  const double across_sd = std::sqrt(noise.strafe_from_translation * trans2 + noise.translation_from_rotation * rot2);
  const double rot_sd = std::sqrt(noise.rotation_from_rotation * rot2 + noise.rotation_from_translation * trans2);

  const StandardNormal standard_normal;
  for (Particle& particle : particles) {
    const double along_error = along_sd > 0.0 ? along_sd * standard_normal(rng) : 0.0;
    const double across_error = across_sd > 0.0 ? across_sd * standard_normal(rng) : 0.0;
    const double rot_error = rot_sd > 0.0 ? rot_sd * standard_normal(rng) : 0.0;
    const Eigen::Vector2d step =
        Eigen::Vector2d(delta.x, delta.y) + along_error * along + across_error * across;
    particle.pose = particle.pose.compose({step.x(), step.y(), rot + rot_error});
  }
}

void apply_motion(MotionModelType type, std::span<Particle> particles,
                  const geometry::Pose2& odometry_from, const geometry::Pose2& odometry_to,
                  const MotionNoise& noise, std::mt19937_64& rng) {
  if (type == MotionModelType::omni) {
    apply_omni_motion(particles, odometry_from, odometry_to, noise, rng);
  } else {
    apply_differential_motion(particles, odometry_from, odometry_to, noise, rng);
  }
}

}  // namespace playerkit::amcl
