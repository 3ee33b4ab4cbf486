#include "families/rflex/driver/rflex_readings.hpp"

#include <algorithm>
#include <cmath>

#include "interfaces/position_data.hpp"
#include "interfaces/wire_units.hpp"

namespace playerkit::drivers::rflex {

namespace hw = hardware::rflex;

namespace {

// The signed step between two readings of a 32-bit counter, across its wrap.
std::int32_t counter_step(std::int32_t now, std::int32_t before) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(now) - static_cast<std::uint32_t>(before));
}

// Division by a conversion the configuration left at 0 gives 0, not infinity.
double converted(double value, double per_unit) { return per_unit > 0.0 ? value / per_unit : 0.0; }

}  // namespace

RflexReadings::RflexReadings(const RflexSettings& settings)
    : settings_(&settings),
      sonar_history_(static_cast<std::size_t>(settings.max_num_sonars)),
      bumpers_(static_cast<std::size_t>(settings.bumper_count), 0) {}

bool RflexReadings::take_motion(const hw::MotionReport& report) {
  if (report.axis == hw::kTranslationAxis) {
    pending_distance_ = report.position;
    distance_velocity_ = report.velocity;
    return false;
  }
  if (report.axis != hw::kRotationAxis) return false;
  bearing_velocity_ = report.velocity;
  const std::int32_t distance = pending_distance_.value_or(distance_.value_or(0));
  if (distance_ && bearing_) {
    const double step_mm = converted(counter_step(distance, *distance_), settings_->odo_distance_conversion);
    const double turn = converted(counter_step(report.position, *bearing_), settings_->odo_angle_conversion);
    odometry_.drive(step_mm, turn);
  }
  distance_ = distance;
  bearing_ = report.position;
  pending_distance_.reset();
  odometry_started_ = true;
  return true;
}

void RflexReadings::restart_counters() {
  odometry_started_ = false;
  distance_.reset();
  bearing_.reset();
  pending_distance_.reset();
  distance_velocity_ = bearing_velocity_ = 0;
}

void RflexReadings::take_sonar(const std::vector<hw::SonarEcho>& echoes) {
  const auto limit = static_cast<std::size_t>(std::min(settings_->num_sonars, 256));
  for (std::size_t k = 0; k < echoes.size() && k < limit; ++k) {
    const hw::SonarEcho& echo = echoes[k];
    if (echo.id >= sonar_history_.size()) {
      ++unknown_sonar_ids_;  // 1.5 wrote past its table
      continue;
    }
    auto& history = sonar_history_[echo.id];
    history.push_back(echo.range);
    while (history.size() > static_cast<std::size_t>(settings_->sonar_age)) history.pop_front();
  }
}

bool RflexReadings::take_dio(const hw::DioReport& report) {
  const int panel = report.address - settings_->bumper_address;
  if (panel < 0 || panel >= static_cast<int>(bumpers_.size())) return false;
  bumpers_[static_cast<std::size_t>(panel)] = static_cast<std::uint8_t>(report.value & 0x0F);
  return true;
}

protocol::PositionData RflexReadings::position() const {
  const geometry::Pose2 pose = odometry_.reported();
  const geometry::Pose2 metres{pose.x / interfaces::kMillimetresPerMetre, pose.y / interfaces::kMillimetresPerMetre,
                               pose.yaw};
  const double speed = converted(distance_velocity_, settings_->odo_distance_conversion) /
                       interfaces::kMillimetresPerMetre;
  const double turn_rate = converted(bearing_velocity_, settings_->odo_angle_conversion);
  return interfaces::position_data(metres, {speed, 0.0, turn_rate}, false,
                                   interfaces::HeadingRange::from_0_to_360);
}

protocol::SonarData RflexReadings::sonar() const {
  protocol::SonarData data;
  std::size_t index = 0;
  const auto wanted = static_cast<std::size_t>(std::min(settings_->num_sonars, 64));
  for (int bank = 0; bank < settings_->num_sonar_banks && index < wanted; ++bank) {
    const int in_bank =
        bank < static_cast<int>(settings_->num_sonars_in_bank.size()) ? settings_->num_sonars_in_bank[bank] : 0;
    for (int channel = 0; channel < in_bank && index < wanted; ++channel, ++index) {
      const auto id = static_cast<std::size_t>(bank * settings_->num_sonars_possible_per_bank + channel);
      if (id >= sonar_history_.size() || sonar_history_[id].empty()) continue;  // no echo yet: 0
      const auto& history = sonar_history_[id];
      const std::uint16_t nearest = *std::min_element(history.begin(), history.end());
      data.ranges[index] = interfaces::wire_value<std::uint16_t>(nearest / settings_->range_distance_conversion);
    }
  }
  data.range_count = static_cast<std::uint16_t>(wanted);
  return data;
}

protocol::IrData RflexReadings::ir() const {
  protocol::IrData data;
  const auto wanted = static_cast<std::size_t>(std::clamp(settings_->ir_pose_count, 0, 32));
  std::size_t index = 0;
  for (int i = 0; i < settings_->ir_bank_count && index < wanted; ++i) {
    const auto bank = static_cast<std::size_t>(settings_->ir_base_bank + i);
    const int used = i < static_cast<int>(settings_->ir_banks.size()) ? settings_->ir_banks[i] : 0;
    for (int j = 0; j < used && j < 8 && index < wanted; ++j, ++index) {
      if (bank >= ir_banks_.size()) continue;
      const std::uint8_t raw = ir_banks_[bank][static_cast<std::size_t>(j)];
      const auto calibration =
          index < settings_->ir_calibration.size() ? settings_->ir_calibration[index] : std::array<double, 2>{1, 1};
      double range = std::pow(calibration[0] * raw, calibration[1]);
      if (!std::isfinite(range) || range < settings_->ir_min_range) range = 0;
      range = std::min(range, static_cast<double>(settings_->ir_max_range));
      data.voltages[index] = raw;
      data.ranges[index] = static_cast<std::uint16_t>(range);
    }
  }
  data.range_count = static_cast<std::uint16_t>(wanted);
  return data;
}

protocol::BumperData RflexReadings::bumper() const {
  protocol::BumperData data;
  data.bumper_count = static_cast<std::uint8_t>(std::min<std::size_t>(bumpers_.size(), 32));
  std::copy_n(bumpers_.begin(), data.bumper_count, data.bumpers.begin());
  return data;
}

protocol::PowerData RflexReadings::power() const {
  protocol::PowerData data;
  if (status_) {
    data.charge = interfaces::wire_value<std::uint16_t>(static_cast<double>(status_->voltage / 10) +
                                                        settings_->power_offset);
  }
  return data;
}

std::vector<geometry::Pose2> RflexReadings::sonar_poses() const {
  std::vector<geometry::Pose2> poses;
  const auto count = static_cast<std::size_t>(std::min(settings_->num_sonars, 64));
  for (std::size_t i = 0; i < count; ++i) {
    const MountPose pose = i < settings_->sonar_poses.size() ? settings_->sonar_poses[i] : MountPose{};
    poses.push_back({pose.x / interfaces::kMillimetresPerMetre, pose.y / interfaces::kMillimetresPerMetre, pose.theta});
  }
  return poses;
}

std::vector<geometry::Pose2> RflexReadings::ir_poses() const {
  std::vector<geometry::Pose2> poses;
  const auto count = static_cast<std::size_t>(std::clamp(settings_->ir_pose_count, 0, 32));
  for (std::size_t i = 0; i < count; ++i) {
    const MountPose pose = i < settings_->ir_poses.size() ? settings_->ir_poses[i] : MountPose{};
    poses.push_back({pose.x / interfaces::kMillimetresPerMetre, pose.y / interfaces::kMillimetresPerMetre, pose.theta});
  }
  return poses;
}

protocol::BumperGeom RflexReadings::bumper_geometry() const {
  protocol::BumperGeom geom;
  geom.subtype = protocol::kBumperGetGeomReq;
  const std::size_t count = std::min<std::size_t>(static_cast<std::size_t>(settings_->bumper_count), 32);
  geom.bumper_count = static_cast<std::uint16_t>(count);
  for (std::size_t i = 0; i < count && i < settings_->bumper_def.size(); ++i) {
    const BumperPanel& p = settings_->bumper_def[i];
    // Truncated to whole units, as 1.5 sent them.
    geom.bumper_def[i] = {static_cast<std::int16_t>(p.x), static_cast<std::int16_t>(p.y),
                          static_cast<std::int16_t>(p.theta_degrees), static_cast<std::uint16_t>(p.length),
                          static_cast<std::uint16_t>(p.radius)};
  }
  return geom;
}

}  // namespace playerkit::drivers::rflex
