#pragma once
// Where a run's filter had lost the robot, by its own account: the
// stretches of scans whose claimed 2-sigma (the position ellipse's long
// half-axis, or the heading interval's half-width) passes 1 m or 60
// degrees. `amcl-offline localize` warns of each, so that a filter that
// lost the robot says so even without the truth to compare. Tracking on
// the six bundled Radish logs never passes them; its claimed 2-sigma
// reaches 0.65 m and 49 degrees for a scan or two after a turn, which is
// the motion model's spread, not a lost robot.
//
//   UncertaintyWatch watch;
//   for (each row) if (auto ended = watch.observe(row.time, row.estimate.covariance)) report(*ended);
//   if (auto last = watch.finish()) report(*last);

#include <cstddef>
#include <numbers>
#include <optional>

#include <Eigen/Core>

namespace playerkit::localization {

struct UncertaintyBounds {
  double position_2sigma_m = 1.0;
  double heading_2sigma_rad = 60.0 * std::numbers::pi / 180.0;
};

struct UncertainStretch {
  double start_time = 0;  // s, the first unsure row
  double end_time = 0;    // s, the last one
  std::size_t rows = 0;
  double worst_position_2sigma_m = 0;
  double worst_heading_2sigma_rad = 0;
};

// The claimed 2-sigma of a pose covariance (x, y, yaw): the position
// ellipse's long half-axis and the heading's half-width.
double position_2sigma(const Eigen::Matrix3d& covariance);
double heading_2sigma(const Eigen::Matrix3d& covariance);

class UncertaintyWatch {
 public:
  explicit UncertaintyWatch(UncertaintyBounds bounds = {}) : bounds_(bounds) {}
  // One row; the stretch this row ends (the first sure row after it), if any.
  std::optional<UncertainStretch> observe(double time, const Eigen::Matrix3d& covariance);
  // At the end of the run: the stretch still open, if any.
  std::optional<UncertainStretch> finish();

 private:
  UncertaintyBounds bounds_;
  std::optional<UncertainStretch> open_;
};

}  // namespace playerkit::localization
