#include "localization/odometry_perturbation.hpp"

#include <cmath>

namespace playerkit::localization {

OdometryPerturber::OdometryPerturber(OdometryErrorModel model, std::uint64_t seed)
    : model_(model), random_(seed) {}

geometry::Pose2 OdometryPerturber::next(const geometry::Pose2& true_pose) {
  ++poses_;
  if (!last_true_) {
    last_true_ = true_pose;
    last_odometry_ = true_pose;
    return true_pose;
  }
  const geometry::Pose2 increment = last_true_->between(true_pose);
  const double length = std::hypot(increment.x, increment.y);
  const double turn = increment.yaw;
  true_path_m_ += length;

  // Always two draws per step, so one error term being zero does not shift the
  // random stream of the others.
  const double length_noise = unit_normal_(random_) * model_.translation_noise_m_per_sqrt_m * std::sqrt(length);
  const double turn_noise_sd =
      std::sqrt(model_.rotation_noise_rad_per_sqrt_rad * model_.rotation_noise_rad_per_sqrt_rad * std::abs(turn) +
                model_.rotation_noise_rad_per_sqrt_m * model_.rotation_noise_rad_per_sqrt_m * length);
  const double turn_noise = unit_normal_(random_) * turn_noise_sd;

  geometry::Pose2 measured{0, 0, 0};
  if (length > 0) {
    const double measured_length = length * (1.0 + model_.translation_scale_error) + length_noise;
    measured.x = increment.x / length * measured_length;
    measured.y = increment.y / length * measured_length;
  }
  measured.yaw = turn * (1.0 + model_.rotation_scale_error) + model_.heading_drift_rad_per_m * length + turn_noise;

  last_true_ = true_pose;
  last_odometry_ = last_odometry_->compose(measured);
  return *last_odometry_;
}

}  // namespace playerkit::localization
