#pragma once
// One RFLEX robot on one serial line, shared by its rflex devices, on
// hardware_driver::RobotConnection (the line, its I/O thread woken by the
// devices, losing and finding the robot, the counters and the trace).
//
// connect() sends 1.5's start-up (motion and DIO reports every 100 ms, the
// motion defaults, both axes at rest) and waits for the controller's first
// packet (1.5 never looked: a dead line hung it). Then the I/O thread:
//
//  * reads every whole packet the moment it arrives (1.5 waited for more
//    than 32 queued bytes and then for 10 ms of silence after each command);
//  * publishes every device's data once per pair of motion reports;
//  * every 100 ms sends the velocity (a stop while no position device is
//    there; the controller's failsafe wants one), SYS_STATUS and, with
//    rflex_joystick, the joystick query; a position command goes out at once;
//  * sonar and IR on with their first device, off after the last; POWER
//    requests in between;
//  * no packet for report_timeout: the robot is lost and sought again with
//    the start-up sequence (1.5 never noticed).
//
// After the last device the robot is stopped, braked, its sonar, IR and
// reports switched off (stop_motion()) and the line closed.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/device.hpp"
#include "core/logger.hpp"
#include "families/rflex/driver/rflex_options.hpp"
#include "families/rflex/driver/rflex_readings.hpp"
#include "families/rflex/driver/rflex_role.hpp"
#include "families/rflex/protocol/rflex_packet.hpp"
#include "hardware_driver/robot_connection.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::drivers::rflex {

class RflexConnection final : public hardware_driver::RobotConnection {
 public:
  RflexConnection(RflexSettings settings, core::Logger& logger);
  ~RflexConnection() override;

  // From a device's setup(), holding a Use. Throws core::DriverError while
  // the robot is not answering.
  void add_device(RflexRole role, core::Device& device);
  // From its shutdown(); afterwards the I/O thread no longer touches it.
  void remove_device(core::Device& device);
  // A device's request, on the I/O thread.
  core::RequestResult handle_request(RflexRole role, const core::Request& request);

  [[nodiscard]] const RflexSettings& settings() const { return settings_; }

  // Velocity commands and cycles: 100 ms, the period of the motion reports.
  static constexpr std::chrono::milliseconds kCycle{100};

 private:
  struct View {
    RflexRole role;
    core::Device* device;
  };

  void connect(links::ByteLink& link) override;
  bool reconnect(links::ByteLink& link, Attempt attempt, const std::stop_token& stop) override;
  void serve(links::ByteLink& link, const core::Wakeup::Woken& woke) override;
  [[nodiscard]] Clock::time_point next_deadline() const override;
  void serve_while_away() override;
  void robot_lost() override;
  void stop_motion(links::ByteLink& link) noexcept override;
  [[nodiscard]] std::vector<core::DriverCounter> protocol_counters() const override;
  [[nodiscard]] std::uint64_t own_timeouts() const override { return line_looks_.load(); }

  // Start-up, then the first packet by `deadline`; false when none came.
  bool start_session(links::ByteLink& link, Clock::time_point deadline, const std::stop_token* stop);
  void read_packets();
  void handle_packet(const hardware::rflex::Packet& packet);

  // On the I/O thread with views_mutex_ held (rflex_cycle.cpp).
  void reconcile_subscriptions();
  void serve_requests();
  void take_commands();
  void send_velocity();
  void cycle();
  void publish();
  [[nodiscard]] int count_views(RflexRole role) const;
  bool send(const hardware::rflex::Packet& packet);

  core::RequestResult position_request(const core::Request& request);
  core::RequestResult ranger_request(RflexRole role, const core::Request& request);
  core::RequestResult bumper_request(const core::Request& request);

  const RflexSettings settings_;
  const hardware::rflex::RflexFrameFormat format_;

  mutable std::mutex views_mutex_;
  std::vector<View> views_;

  std::atomic<bool> session_up_{false};
  std::atomic<std::uint64_t> line_looks_{0};
  std::atomic<std::uint64_t> motion_reports_{0};
  std::atomic<std::uint64_t> bad_packets_{0};
  std::atomic<std::uint64_t> unknown_packets_{0};

  // --- the I/O thread's (and open()/close()'s while it is not running)
  std::unique_ptr<links::FramedReader> reader_;
  RflexReadings readings_;
  std::optional<std::string> link_error_;
  Clock::time_point last_packet_{};
  Clock::time_point next_cycle_{};
  bool new_pair_ = false;
  bool odometry_was_ready_ = false;

  bool position_active_ = false;
  double xspeed_ = 0.0;    // mm/s, the last command
  double yawspeed_ = 0.0;  // deg/s
  int joystick_holds_ = 0;  // Player commands still ignored after the joystick drove
  int sonar_views_ = 0;
  bool sonar_wanted_ = false;
  std::optional<bool> sonar_sent_;
  int ir_views_ = 0;
  bool ir_wanted_ = false;
  std::optional<bool> ir_sent_;
};

}  // namespace playerkit::drivers::rflex
