#pragma once
// Turns true poses into plausible wheel odometry: the bundled Radish logs are
// SLAM-corrected (their "odometry" is the corrected path), so localization on
// them is only a test once their odometry is degraded as a real robot's is.
//
//   localization::OdometryPerturber perturber(localization::OdometryErrorModel{}, seed);
//   for (auto& truth : poses) odometry.push_back(perturber.next(truth));
//
//   std::ofstream out("intel-noisy.log");
//   auto summary = localization::perturb_log("intel-corrected.log.gz", out, {}, 42);
//
// The error model (README.md gives the reasons for the defaults): each
// increment between successive true poses is taken in the robot frame at the
// earlier pose, (dx, dy) with length d and a turn dtheta, and measured as
//   length   d * (1 + translation_scale_error) + N(0, translation_noise^2 * d)
//   turn     dtheta * (1 + rotation_scale_error) + heading_drift * d
//            + N(0, rotation_noise_per_sqrt_rad^2 * |dtheta| + rotation_noise_per_sqrt_m^2 * d)
// (the direction of (dx, dy) is kept); the measured increments are composed
// from the first true pose on. So the odometry starts at the truth, its error
// grows with the distance and the turning, and a straight drive of L metres
// reads L * (1 + scale) with a heading off by drift * L. Noise variances grow
// linearly with the motion, so the error of a path does not depend on how
// finely it is sampled.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <ostream>
#include <random>

#include "algorithms/geometry/pose2.hpp"
#include "log/log_format_detection.hpp"

namespace playerkit::localization {

struct OdometryErrorModel {
  double translation_scale_error = 0.02;            // fraction: +0.02 reads 1.02 m per metre
  double rotation_scale_error = 0.03;               // fraction of every turn
  double heading_drift_rad_per_m = 0.005;           // systematic turn per metre driven (~3 deg / 10 m)
  double translation_noise_m_per_sqrt_m = 0.01;     // sd of the length error after 1 m
  double rotation_noise_rad_per_sqrt_rad = 0.02;    // sd of the turn error after turning 1 rad
  double rotation_noise_rad_per_sqrt_m = 0.005;     // sd of the heading error after 1 m (slip)

  // Every error zero: the odometry equals the truth.
  static OdometryErrorModel none() { return {0, 0, 0, 0, 0, 0}; }
  friend bool operator==(const OdometryErrorModel&, const OdometryErrorModel&) = default;
};

// Degrades one stream of true poses (one robot). Deterministic for a seed.
class OdometryPerturber {
 public:
  OdometryPerturber(OdometryErrorModel model, std::uint64_t seed);

  // The odometry pose for the next true pose of the stream.
  geometry::Pose2 next(const geometry::Pose2& true_pose);

  std::size_t poses() const { return poses_; }
  double true_path_length_m() const { return true_path_m_; }
  // The latest poses in and out (nullopt before the first).
  std::optional<geometry::Pose2> last_true_pose() const { return last_true_; }
  std::optional<geometry::Pose2> last_odometry_pose() const { return last_odometry_; }

 private:
  OdometryErrorModel model_;
  std::mt19937_64 random_;
  std::normal_distribution<double> unit_normal_{0.0, 1.0};
  std::optional<geometry::Pose2> last_true_;
  std::optional<geometry::Pose2> last_odometry_;
  std::size_t poses_ = 0;
  double true_path_m_ = 0;
};

struct PerturbationSummary {
  log::LogFormat format = log::LogFormat::kPlayer;
  std::size_t odometry_poses_changed = 0;  // position lines (Player) / ODOM, TRUEPOS, laser odom fields (CARMEN)
  std::size_t truth_lines_added = 0;       // Player logs without truth get truth:0 lines
  std::size_t malformed_lines = 0;         // passed through unchanged
  double odometry_input_path_m = 0;        // the path of the original odometry, as the model saw it
  double truth_path_m = 0;                 // the path of the truth poses (laser:0 truth)
  double final_position_drift_m = 0;       // last degraded odometry pose vs the last original one
  double final_heading_drift_rad = 0;      // signed, odometry minus original
};

// Copies a log (Player or CARMEN, plain or gzip, told by content) to `out` in
// the same format with its odometry degraded, and the truth kept:
//   CARMEN  ODOM x y theta, the odom fields of FLASER/RLASER/ROBOTLASERn and
//           TRUEPOS's odometry are degraded (CARMEN's "%f"); a laser record's
//           x y theta (the corrected pose, i.e. the truth) is kept.
//   Player  every position:N pose (x y yaw) is degraded ("%+07.3f %+07.3f
//           %+04.3f", one stream per index); truth lines are kept; a log with
//           no truth line gets a truth:0 line with the original pose after
//           each position:0 line.
// What drives the model (seeded from `seed`), in file order: in a CARMEN log
// whose laser records carry odometry, those poses alone (the scan path, which
// is the truth in corrected logs), and each ODOM/TRUEPOS odometry keeps its
// offset from the latest one (lines before the first are left as they are);
// otherwise every odometry pose. Every other line, and every malformed one, is
// copied byte for byte. Throws std::runtime_error for an unreadable file.
PerturbationSummary perturb_log(const std::filesystem::path& in, std::ostream& out,
                                const OdometryErrorModel& model, std::uint64_t seed);

}  // namespace playerkit::localization
