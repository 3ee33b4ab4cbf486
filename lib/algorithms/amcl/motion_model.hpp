#pragma once
// Odometry motion models (Probabilistic Robotics ch. 5.4): move every
// particle by the odometry delta between two odometry poses, with noise
// whose variance grows with the distance driven and the angle turned.
//
// Differential drive: the delta is split into rotate (rot1), translate
// (trans), rotate (rot2); each is perturbed by zero-mean Gaussian noise with
//   var(rot1)  = a1 rot1^2 + a2 trans^2
//   var(trans) = a3 trans^2 + a4 (rot1^2 + rot2^2)
//   var(rot2)  = a1 rot2^2 + a2 trans^2
// where for moves longer than two of MotionNoise's steps x^2 becomes
// |x| * 2 step (noise_square).
// Unlike the textbook (and Player 1.5), driving backwards is read as a
// reversed translation, not as "turn around by pi, drive, turn back", which
// would otherwise add a full rotation's noise to every reversing step.
//
// Omnidirectional: the delta in the robot frame is a translation (along its
// direction of travel and across it) and a rotation:
//   var(along)  = a3 trans^2 + a4 rot^2
//   var(across) = a5 trans^2 + a4 rot^2
//   var(rot)    = a1 rot^2   + a2 trans^2

#include "algorithms/amcl/amcl_parameters.hpp"
#include "algorithms/amcl/particle_set.hpp"
#include "algorithms/geometry/pose2.hpp"

#include <random>
#include <span>

namespace playerkit::amcl {

struct MotionNoise {
  double rotation_from_rotation = 0.0;        // a1
  double rotation_from_translation = 0.0;     // a2
  double translation_from_translation = 0.0;  // a3
  double translation_from_rotation = 0.0;     // a4
  double strafe_from_translation = 0.0;       // a5 (omni)
  // The filter's update distance and angle; 0: none. A move longer than
  // two of them counts as so many moves of two, whose errors add up: its
  // variance grows with its length, not with its square (noise_square). The
  // textbook's square assumes an update every step or so; a log with a scan
  // every 2 m spread the particles sqrt(5) times wider than the same path
  // in 0.4 m moves.
  double translation_step = 0.0;  // m
  double rotation_step = 0.0;     // rad

  static MotionNoise from(const AmclParameters& parameters);
};

// A filter updates once the robot has moved a step, and scans come at
// their own pace: a move between updates is normally up to about two steps,
// the range the coefficients were set for. Beyond it, a move counts as so
// many moves of two steps.
inline constexpr double kStepsAsOneMove = 2.0;

// x^2, or |x| * kStepsAsOneMove * step beyond that many steps (step > 0).
double noise_square(double x, double step);

// The differential-drive decomposition of an odometry delta.
struct DifferentialMotion {
  double rotation1 = 0.0;    // turn before translating (rad)
  double translation = 0.0;  // signed: negative when reversing (m)
  double rotation2 = 0.0;    // turn after translating (rad)
};
DifferentialMotion decompose_differential(const geometry::Pose2& odometry_from,
                                          const geometry::Pose2& odometry_to);

// Below this translation (m) the direction of travel is odometry jitter, so
// rot1 carries no noise of its own (its turn is attributed to rot2).
inline constexpr double direction_noise_min_translation = 0.01;

void apply_differential_motion(std::span<Particle> particles, const geometry::Pose2& odometry_from,
                               const geometry::Pose2& odometry_to, const MotionNoise& noise,
                               std::mt19937_64& rng);

void apply_omni_motion(std::span<Particle> particles, const geometry::Pose2& odometry_from,
                       const geometry::Pose2& odometry_to, const MotionNoise& noise,
                       std::mt19937_64& rng);

void apply_motion(MotionModelType type, std::span<Particle> particles,
                  const geometry::Pose2& odometry_from, const geometry::Pose2& odometry_to,
                  const MotionNoise& noise, std::mt19937_64& rng);

}  // namespace playerkit::amcl
