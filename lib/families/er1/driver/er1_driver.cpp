// The er1_position driver: an ER1 as a position device. The kit's
// SerialDeviceDriver opens the port, wakes this driver when a command or
// request arrives or when the next odometry reading is due, and looks for
// the controller again when it goes quiet; what is here is the RCM's
// exchange (Rcm) and the mapping to Player's position structs (er1.md §3).
#include "families/er1/driver/er1_driver.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "families/er1/driver/er1_options.hpp"
#include "families/er1/driver/er1_rcm.hpp"
#include "families/er1/driver/er1_wheels.hpp"
#include "hardware_driver/serial_device_driver.hpp"
#include "interfaces/odometry_integrator.hpp"
#include "interfaces/position_data.hpp"
#include "interfaces/position_requests.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::drivers {

namespace {

using namespace std::chrono_literals;
using er1::WheelSpeeds;

// 1.5 read the counts as fast as the line allowed; 50 readings a second
// give the same odometry without keeping a core busy.
constexpr auto kCyclePeriod = 20ms;
constexpr auto kDebugPeriod = 1s;
constexpr auto kSpeedWindow = 60ms;
constexpr int kBaud = 230400;
constexpr double kFastestPlausibleWheel = 2.0;  // m/s: four times what 1.5 would command
constexpr int kImplausibleReadings = 3;

class Er1PositionDriver final : public hardware_driver::SerialDeviceDriver, private interfaces::PositionBase {
 public:
  explicit Er1PositionDriver(const er1::Er1Settings& settings)
      : SerialDeviceDriver(settings.port, {.baud = kBaud}, {}),
        settings_(settings),
        wiring_(er1::Wiring::from_motor_dir(settings.motor_dir)) {}

  core::RequestResult handle_request(const core::Request& request) override {
    return interfaces::answer_position_request(*this, request);
  }

 private:
  // --- the kit's hooks
  void start_device(links::ByteLink& link, bool recovering) override {
    rcm_ = std::make_unique<er1::Rcm>(link, wiring_, [this] { return stopping(); });
    try {
      rcm_->start();
      last_counts_ = rcm_->counts();
    } catch (const links::ExchangeError& e) {
      if (e.kind() == links::ExchangeError::Kind::stopped) throw hardware_driver::Stopping();
      throw std::runtime_error(std::string(e.what()) + " (is the robot's controller powered and plugged in?)");
    }
    // The reset zeroed the counts: the reported pose carries on from where it was.
    if (recovering) odometry_.restart_counters({});
    sent_ = WheelSpeeds{};
    last_reading_ = speed_since_ = Clock::now();
    travel_since_ = turn_since_ = 0.0;
    velocity_ = {};
    next_reading_ = last_reading_ + kCyclePeriod;
  }

  void serve(links::ByteLink& /*link*/, const core::Wakeup::Woken& /*woke*/) override {
    if (auto command = device().take_command()) {
      const auto cmd = protocol::decode<protocol::PositionCommand>(command->payload);
      wanted_ = er1::wheel_speeds(cmd.xspeed, cmd.yawspeed, settings_.axle);
    }
    device().service_requests();
    drive(powered_ ? wanted_ : WheelSpeeds{});
    if (Clock::now() >= next_reading_) publish_reading();
  }

  [[nodiscard]] Clock::time_point next_deadline() const override { return next_reading_; }

  void stop_device(links::ByteLink& /*link*/) noexcept override {
    if (!rcm_) return;
    try {
      rcm_->stop();
    } catch (const std::exception& e) {
      device().logger().warning(device().name() + ": could not stop the ER1's motors: " + e.what());
    }
  }

  void link_closing() noexcept override { rcm_.reset(); }
  [[nodiscard]] std::string subject() const override { return "the ER1 on " + port(); }
  [[nodiscard]] std::vector<core::DriverCounter> protocol_counters() const override {
    return {{"implausible_counts", implausible_readings_.load()}};
  }

  // --- Player -> robot
  void drive(const WheelSpeeds& wheels) {
    if (wheels == sent_) return;
    // 1.5 stops both wheels before one changes direction: the RCM's profile
    // is not asked to pass through zero.
    if (er1::reverses(sent_, wheels)) rcm_->drive({});
    rcm_->drive(wheels);
    sent_ = wheels;
  }

  // --- robot -> Player
  void publish_reading() {
    const auto asked = Clock::now();
    const er1::WheelCounts counts = rcm_->counts();
    const auto now = Clock::now();
    // When the counts were taken, as near as can be told.
    const auto taken = asked + (now - asked) / 2;
    next_reading_ = std::max(next_reading_ + kCyclePeriod, now);
    const double left = er1::wheel_travel(counts.left, last_counts_.left);
    const double right = er1::wheel_travel(counts.right, last_counts_.right);
    const double seconds = std::chrono::duration<double>(taken - last_reading_).count();
    // A count cut from line noise would throw the pose far away: a wheel
    // that seems to have outrun the robot is read again next cycle (a few
    // times; after that the counts are taken as they are).
    const double farthest = kFastestPlausibleWheel * std::max(seconds, 0.1);
    if ((std::abs(left) > farthest || std::abs(right) > farthest) && implausible_in_a_row_ < kImplausibleReadings) {
      ++implausible_in_a_row_;
      ++implausible_readings_;
      return;
    }
    implausible_in_a_row_ = 0;
    last_counts_ = counts;
    last_reading_ = taken;
    const double turn = (right - left) / settings_.axle;
    const double distance = (left + right) / 2.0;
    odometry_.drive(distance, turn);
    // Speeds over at least kSpeedWindow: two readings a scheduling hiccup
    // apart would divide a few ticks by almost nothing.
    travel_since_ += distance;
    turn_since_ += turn;
    const double window = std::chrono::duration<double>(taken - speed_since_).count();
    if (window >= std::chrono::duration<double>(kSpeedWindow).count()) {
      velocity_ = {travel_since_ / window, 0.0, turn_since_ / window};
      travel_since_ = turn_since_ = 0.0;
      speed_since_ = taken;
    }
    const geometry::Pose2 pose = odometry_.reported();
    device().publish(
        protocol::encode(interfaces::position_data(pose, velocity_, false, interfaces::HeadingRange::from_0_to_360)));
    if (settings_.debug && now >= next_debug_line_) {
      char line[160];
      std::snprintf(line, sizeof line, ": odometry x %.3f m, y %.3f m, yaw %.1f deg; wheels %.0f, %.0f mm/s", pose.x,
                    pose.y, pose.yaw * 180.0 / 3.14159265358979, sent_.left, sent_.right);
      device().logger().info(device().name() + line);
      next_debug_line_ = now + kDebugPeriod;
    }
  }

  // --- requests (interfaces::PositionBase), on the driver's thread
  std::optional<interfaces::BaseGeometry> geometry() override {
    return interfaces::BaseGeometry{.pose = {}, .length = 0.45, .width = 0.45};
  }
  // Off stops the wheels and holds them until on (1.5 ignored it).
  bool set_motor_power(bool on) override {
    powered_ = on;
    return true;
  }
  bool reset_odometry() override {
    odometry_.reset_reported();
    return true;
  }
  bool set_odometry(const geometry::Pose2& pose) override {
    odometry_.set_reported(pose);
    return true;
  }

  const er1::Er1Settings settings_;
  const er1::Wiring wiring_;
  std::unique_ptr<er1::Rcm> rcm_;
  interfaces::OdometryIntegrator odometry_;
  er1::WheelCounts last_counts_{};
  WheelSpeeds wanted_{};
  WheelSpeeds sent_{};
  bool powered_ = true;
  int implausible_in_a_row_ = 0;
  std::atomic<std::uint64_t> implausible_readings_{0};
  Clock::time_point last_reading_{};
  Clock::time_point speed_since_{};
  double travel_since_ = 0.0;  // m since speed_since_
  double turn_since_ = 0.0;    // rad since speed_since_
  geometry::Pose2 velocity_;
  Clock::time_point next_reading_{};
  Clock::time_point next_debug_line_{};
};

}  // namespace

core::DriverSpec er1_position_driver_spec() {
  return {
      .name = "er1_position",
      .interfaces = {protocol::kPositionCode},
      .access = protocol::Access::kAll,
      .factory = [](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
        return std::make_unique<Er1PositionDriver>(er1::read_er1_settings(context.section));
      },
      .limits = {},
      .summary = "Evolution Robotics ER1 motor controller (position)",
      .family = "er1",
      .doc = {.manual_section = "7.7",
              .needs_hardware = true,
              .options = {},
              .requests = {"GET_GEOM: the robot's 450 x 450 mm body, centred",
                           "MOTOR_POWER: off stops the wheels and holds them until on",
                           "RESET_ODOM, SET_ODOM: the reported pose moved, the controller's counts untouched"},
              .example = "position:0 ( driver \"er1_position\" port \"/dev/ttyUSB0\" axle 0.38 )",
              .schema = er1::er1_option_schema()},
  };
}

}  // namespace playerkit::drivers
