#pragma once
// One Segway RMP on one CAN bus, shared by its position, position3d and
// power devices, as 1.5's hidden SegwayRMP device was (core::SharedConnection:
// the first device set up opens the bus, the last one's shutdown stops the
// robot and closes it). The I/O thread:
//
//  * gathers the robot's five status messages into sets; each complete set
//    moves the odometry, is published to every device, and is answered by
//    one 0x413 velocity command (the bus paces the loop, as in 1.5);
//  * the command is the newest client command within max_xspeed and
//    max_yawspeed, ramped by max_xaccel and max_yawaccel, zero while the
//    motors are not enabled (MOTOR_POWER) and once no new command has come
//    for command_timeout;
//  * answers requests at once (status commands on the bus, odometry reset);
//  * a robot silent for status_timeout, or a bus that fails: one log line,
//    the devices unavailable, the bus reopened every second until the robot
//    is heard again (the robot's own watchdog stops it meanwhile).

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <thread>
#include <vector>

#include "core/device.hpp"
#include "core/driver.hpp"
#include "core/logger.hpp"
#include "core/shared_connection.hpp"
#include "core/wakeup.hpp"
#include "families/segwayrmp/driver/rmp_options.hpp"
#include "families/segwayrmp/protocol/rmp_frames.hpp"
#include "families/segwayrmp/protocol/rmp_odometry.hpp"
#include "interfaces/position_requests.hpp"
#include "links/byte_link.hpp"
#include "links/can/can_bus.hpp"
#include "links/link_counters.hpp"

namespace playerkit::drivers::segwayrmp {

enum class RmpRole { position, position3d, power };

class RmpConnection final : public core::SharedConnection, private interfaces::PositionBase {
 public:
  using Clock = std::chrono::steady_clock;

  RmpConnection(RmpSettings settings, core::Logger& logger);
  ~RmpConnection() override;

  // From a device's setup(), holding a Use. Throws core::DriverError while
  // the robot is not answering.
  void add_device(RmpRole role, core::Device& device);
  void remove_device(core::Device& device);
  // On the I/O thread (through Device::service_requests).
  core::RequestResult handle_request(RmpRole role, const core::Request& request);

  [[nodiscard]] std::vector<core::DriverCounter> counters() const;
  void set_byte_trace(core::ByteTrace trace);
  [[nodiscard]] const RmpSettings& settings() const { return settings_; }

 private:
  struct View {
    RmpRole role;
    core::Device* device;
  };

  void open() override;
  void close() noexcept override;

  void run(const std::stop_token& stop);
  void connect(const std::stop_token* stop);
  void drop_bus() noexcept;
  void serve(const core::Wakeup::Woken& woke);
  void serve_requests();
  void lose(const std::string& reason);
  void try_to_reconnect(const std::stop_token& stop);
  [[nodiscard]] Clock::time_point next_deadline() const;
  void take_commands(Clock::time_point now);
  void cycle(const hardware::segwayrmp::Status& status);
  void send_velocity(Clock::time_point now);
  void write(const framing::CanFrame& frame);
  bool write_status(hardware::segwayrmp::StatusCommand command, std::uint8_t value, int times);
  void install_trace();

  // interfaces::PositionBase
  std::optional<interfaces::BaseGeometry> geometry() override;
  bool set_motor_power(bool on) override;
  bool reset_odometry() override;
  bool rmp_setting(std::uint8_t subtype, std::uint16_t value) override;

  const RmpSettings settings_;
  core::Logger& logger_;
  const std::string label_;
  const std::shared_ptr<core::Wakeup> wakeup_ = std::make_shared<core::Wakeup>();

  mutable std::mutex views_mutex_;
  std::vector<View> views_;

  mutable std::mutex link_mutex_;  // link_ as a pointer, trace_, released_
  std::unique_ptr<links::ByteLink> link_;
  core::ByteTrace trace_;
  links::LinkCounterSnapshot released_;

  std::jthread thread_;
  std::atomic<bool> answering_{false};
  std::atomic<std::uint64_t> status_sets_{0};
  std::atomic<std::uint64_t> commands_sent_{0};
  std::atomic<std::uint64_t> command_timeouts_{0};
  std::atomic<std::uint64_t> losses_{0};
  std::atomic<std::uint64_t> reconnects_{0};
  std::atomic<std::uint64_t> own_looks_{0};

  // The I/O thread's (and open()'s before it starts).
  std::unique_ptr<links::can::CanBus> bus_;
  hardware::segwayrmp::StatusAssembler assembler_;
  hardware::segwayrmp::Status status_;
  hardware::segwayrmp::RmpOdometry odometry_;
  Clock::time_point last_status_{};
  Clock::time_point last_command_{};
  Clock::time_point last_sent_{};
  Clock::time_point lost_at_{};
  Clock::time_point next_attempt_{};
  bool motors_enabled_ = false;
  bool timed_out_ = true;              // no client command is in force
  double wanted_xspeed_ = 0;           // mm/s, within the limits
  double wanted_yawspeed_ = 0;         // deg/s
  double sent_xspeed_ = 0;             // what the last 0x413 asked for, after the ramps
  double sent_yawspeed_ = 0;
  hardware::segwayrmp::Command last_command_sent_{};
  std::optional<std::string> failed_write_;  // a request's write failed: the bus is lost after the requests
};

[[nodiscard]] std::string connection_key(const RmpSettings& settings);

}  // namespace playerkit::drivers::segwayrmp
