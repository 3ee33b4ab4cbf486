// The trogdor driver: the O-Bot's cerebellum as a position device. The kit's
// SerialDeviceDriver opens the port, wakes this driver for commands,
// requests and the next odometry reading, and looks for the robot again
// when it goes quiet; what is here is the sequence of trogdor.md §2 and the
// mapping of §3.
#include "families/trogdor/driver/trogdor_driver.hpp"

#include <memory>
#include <optional>

#include "families/trogdor/driver/cerebellum.hpp"
#include "families/trogdor/driver/trogdor_options.hpp"
#include "families/trogdor/driver/wheel_odometry.hpp"
#include "families/trogdor/protocol/trogdor_units.hpp"
#include "hardware_driver/serial_device_driver.hpp"
#include "interfaces/position_data.hpp"
#include "interfaces/position_requests.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::drivers {

namespace {

using namespace std::chrono_literals;
namespace hw = hardware::trogdor;
using trogdor::Cerebellum;

// 1.5's loop slept 10 ms after two exchanges of a few ms each.
constexpr auto kCycle = 15ms;
constexpr int kBaud = 57600;

class TrogdorDriver final : public hardware_driver::SerialDeviceDriver, private interfaces::PositionBase {
 public:
  explicit TrogdorDriver(std::string port) : SerialDeviceDriver(std::move(port), {.baud = kBaud}, {}) {}

  core::RequestResult handle_request(const core::Request& request) override {
    return interfaces::answer_position_request(*this, request);
  }

 private:
  // --- the kit's hooks
  void start_device(links::ByteLink& link, bool recovering) override {
    robot_ = std::make_unique<Cerebellum>(link, [this] { return stopping(); });
    hw::OdometryReading first;
    try {
      first = robot_->start();
    } catch (const links::ExchangeError& e) {
      if (e.kind() == links::ExchangeError::Kind::stopped) throw hardware_driver::Stopping();
      throw std::runtime_error(std::string(e.what()) + " (is the robot on, and is this its cerebellum's port?)");
    }
    // Found again, the robot's counters carry what it drove while the line
    // was down (it kept the last command): that motion is counted, unless
    // the counters jumped further than the wheels could have (a robot
    // restarted), when they are followed from here and the pose carries on.
    const auto now = Clock::now();
    if (!recovering) odometry_.restart();  // a new session: its first reading is the origin
    odometry_.update(first, recovering ? std::chrono::duration<double>(now - last_reading_).count() : 0.0);
    last_reading_ = now;
    sent_.reset();  // the current command goes out again
    next_reading_ = Clock::now() + kCycle;
  }

  void serve(links::ByteLink& /*link*/, const core::Wakeup::Woken& /*woke*/) override {
    if (auto command = device().take_command()) {
      const auto decoded = protocol::decode<protocol::PositionCommand>(command->payload);
      wanted_ = hw::wheel_units_for(decoded.xspeed, decoded.yawspeed);
    }
    if (wanted_ != sent_) send_velocities(wanted_);
    device().service_requests();
    if (Clock::now() >= next_reading_) {
      publish_reading();
      next_reading_ = Clock::now() + kCycle;
    }
  }

  [[nodiscard]] Clock::time_point next_deadline() const override { return next_reading_; }

  void stop_device(links::ByteLink& /*link*/) noexcept override {
    if (!robot_) return;
    try {
      robot_->tell("SET_VELOCITIES (stop)", hw::set_velocities({}));
      robot_->tell("DEINIT", hw::deinit());
    } catch (const std::exception& e) {
      device().logger().warning(device().name() + ": stopping the robot: " + e.what());
    }
  }

  void link_closing() noexcept override { robot_.reset(); }
  [[nodiscard]] std::string subject() const override { return "the Trogdor on " + port(); }
  [[nodiscard]] std::vector<core::DriverCounter> protocol_counters() const override {
    return {{"refused_messages", refused_},
            {"skipped_readings", odometry_.skipped()},
            {"encoder_errors", encoder_errors_}};
  }

  // A NACK means the message arrived damaged: sent again, then the robot
  // counts as lost (1.5 ended its thread at the first).
  void send_velocities(hw::WheelPair units) {
    if (!robot_->tell("SET_VELOCITIES", hw::set_velocities(units)) &&
        !robot_->tell("SET_VELOCITIES", hw::set_velocities(units))) {
      ++refused_;
      throw hardware_driver::DeviceLost("the robot refused SET_VELOCITIES twice");
    }
    sent_ = units;
  }

  void publish_reading() {
    const hw::OdometryReading reading = robot_->odometry();
    const auto now = Clock::now();
    odometry_.update(reading, std::chrono::duration<double>(now - last_reading_).count());
    last_reading_ = now;
    if (reading.encoder_error && !encoder_error_) {
      device().logger().warning(device().name() + ": the robot reports an encoder board error");
    }
    if (reading.encoder_error) ++encoder_errors_;
    encoder_error_ = reading.encoder_error;
    // The robot reports no stall (1.5's field was left uninitialised).
    device().publish(protocol::encode(interfaces::position_data(odometry_.reported(), odometry_.velocity(), false,
                                                                interfaces::HeadingRange::from_0_to_360)));
  }

  // --- requests (interfaces::PositionBase), on the driver's thread
  std::optional<interfaces::BaseGeometry> geometry() override {
    return interfaces::BaseGeometry{.pose = {}, .length = hw::kBodySize, .width = hw::kBodySize};
  }

  bool set_motor_power(bool on) override {
    if (!robot_ || lost()) return false;
    return robot_->tell(on ? "ENABLE_VEL_CONTROL" : "DISABLE_VEL_CONTROL",
                        on ? hw::enable_velocity_control() : hw::disable_velocity_control());
  }

  bool reset_odometry() override {
    odometry_.pose().reset_reported();
    return true;
  }

  bool set_odometry(const geometry::Pose2& pose) override {
    odometry_.pose().set_reported(pose);
    return true;
  }

  std::unique_ptr<Cerebellum> robot_;
  trogdor::WheelOdometry odometry_;
  hw::WheelPair wanted_{};
  std::optional<hw::WheelPair> sent_;
  Clock::time_point next_reading_{};
  Clock::time_point last_reading_{};
  bool encoder_error_ = false;
  std::uint64_t refused_ = 0;
  std::uint64_t encoder_errors_ = 0;
};

}  // namespace

core::DriverSpec trogdor_driver_spec() {
  return {
      .name = "trogdor",
      .interfaces = {protocol::kPositionCode},
      .access = protocol::Access::kAll,
      .factory = [](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
        return std::make_unique<TrogdorDriver>(trogdor::read_trogdor_port(context.section));
      },
      .limits = {},
      .summary = "Botrics O-Bot (\"Trogdor\") differential-drive base (position)",
      .family = "trogdor",
      .doc = {.manual_section = "7.42",
              .needs_hardware = true,
              .options = {},
              .requests = {"GET_GEOM: pose (0, 0, 0), size 450 x 450 mm",
                           "MOTOR_POWER: enables ('e') or disables ('d') the wheels' velocity control",
                           "RESET_ODOM, SET_ODOM: the reported pose (1.5 NACKed them)"},
              .example = "position:0 ( driver \"trogdor\" port \"/dev/ttyUSB1\" )",
              .schema = trogdor::trogdor_option_schema()},
  };
}

}  // namespace playerkit::drivers
