#include "localization/uncertain_stretches.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/Eigenvalues>

namespace playerkit::localization {

double position_2sigma(const Eigen::Matrix3d& covariance) {
  const Eigen::Matrix2d position = covariance.topLeftCorner<2, 2>();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(position, Eigen::EigenvaluesOnly);
  return 2.0 * std::sqrt(std::max(0.0, solver.eigenvalues().maxCoeff()));
}

double heading_2sigma(const Eigen::Matrix3d& covariance) { return 2.0 * std::sqrt(std::max(0.0, covariance(2, 2))); }

std::optional<UncertainStretch> UncertaintyWatch::observe(double time, const Eigen::Matrix3d& covariance) {
  const double position = position_2sigma(covariance);
  const double heading = heading_2sigma(covariance);
  // A covariance that is not a number is no claim of certainty.
  const bool unsure = !(position <= bounds_.position_2sigma_m) || !(heading <= bounds_.heading_2sigma_rad);
  if (!unsure) return finish();
  if (!open_) open_ = UncertainStretch{time, time, 0, 0.0, 0.0};
  open_->end_time = time;
  ++open_->rows;
  if (std::isfinite(position)) open_->worst_position_2sigma_m = std::max(open_->worst_position_2sigma_m, position);
  if (std::isfinite(heading)) open_->worst_heading_2sigma_rad = std::max(open_->worst_heading_2sigma_rad, heading);
  return std::nullopt;
}

std::optional<UncertainStretch> UncertaintyWatch::finish() { return std::exchange(open_, std::nullopt); }

}  // namespace playerkit::localization
