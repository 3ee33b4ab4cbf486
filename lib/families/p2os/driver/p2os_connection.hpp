#pragma once
// One Pioneer on one serial line, shared by the robot's p2os devices, on
// hardware_driver::RobotConnection (the line, its I/O thread woken by the
// devices, losing and finding the robot, the counters and the trace). The
// first device set up opens the line and runs the handshake (connect());
// then the I/O thread, in serve():
//
//  * reads packets: SIPs (odometry, sensors), GYROPAC, SERAUX2 (CMUcam);
//  * publishes every attached device's data once per SIP, all with the same
//    timestamp (1.5 stamped only some of them, quirk 14);
//  * sends what the devices ask for: motor packets (at once when a command
//    arrives, and at least one per SIP cycle, which keeps the robot's
//    watchdog fed; PULSE when nothing else went), SONAR/GYRO/ENABLE on
//    subscription edges, GRIPPER, SOUND, CMUcam polling;
//  * answers the devices' requests, each device with its own queue (1.5
//    shared one queue of length 1 between all eleven, quirk 15);
//  * notices a silent robot (no SIP for sip_timeout; 1.5 never noticed,
//    quirk 3), after which reconnect() handshakes in the background, one
//    speed per attempt, the last good one first.
//
// When the last device leaves, the robot is stopped (STOP, ENABLE 0), sent
// CLOSE (stop_motion()), and the line closed.

#include <atomic>
#include <chrono>
#include <cstdint>
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
#include "families/p2os/driver/handshake.hpp"
#include "families/p2os/driver/motor_commands.hpp"
#include "families/p2os/driver/odometry_tracker.hpp"
#include "families/p2os/driver/p2os_options.hpp"
#include "families/p2os/driver/p2os_role.hpp"
#include "families/p2os/driver/robot_readings.hpp"
#include "families/p2os/protocol/commands.hpp"
#include "families/p2os/protocol/frame_format.hpp"
#include "families/p2os/protocol/robot_params.hpp"
#include "families/p2os/protocol/sync.hpp"
#include "hardware_driver/robot_connection.hpp"
#include "links/byte_link.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::drivers::p2os {

class P2osConnection final : public hardware_driver::RobotConnection {
 public:
  P2osConnection(RobotLinkOptions options, core::Logger& logger);
  ~P2osConnection() override;

  // From a device's setup(), holding a Use: its data starts with the next
  // SIP. Throws core::DriverError while the robot is not answering.
  void add_device(P2osRole role, core::Device& device, const MotorLimits& limits = {});
  // From its shutdown(), before letting go of the Use. Once this returns the
  // I/O thread no longer touches the device.
  void remove_device(core::Device& device);

  // A device's request, on the I/O thread (through Device::service_requests).
  core::RequestResult handle_request(P2osRole role, const core::Request& request);

  [[nodiscard]] const RobotLinkOptions& options() const { return options_; }
  // The SYNC2 reply of the current (or last) session.
  [[nodiscard]] std::optional<hardware::p2os::Sync2Reply> identity() const;
  // The speed the robot answered at (0 on TCP, or before the first session).
  [[nodiscard]] int baud() const { return baud_.load(); }

 private:
  struct View {
    P2osRole role;
    core::Device* device;
    MotorLimits limits;
  };
  enum class CmucamPhase { off, resetting, tracking };

  // --- the robot's life (p2os_connection.cpp)
  void connect(links::ByteLink& link) override;
  bool reconnect(links::ByteLink& link, Attempt attempt, const std::stop_token& stop) override;
  void serve(links::ByteLink& link, const core::Wakeup::Woken& woke) override;
  [[nodiscard]] Clock::time_point next_deadline() const override;
  void serve_while_away() override;
  void robot_lost() override;
  void stop_motion(links::ByteLink& link) noexcept override;
  // sips, unknown_packets, bad_packets.
  [[nodiscard]] std::vector<core::DriverCounter> protocol_counters() const override;
  [[nodiscard]] std::uint64_t own_timeouts() const override { return line_looks_.load(); }
  // Every whole packet the line holds now, without waiting for more.
  void read_packets();
  void handle_telegram(const std::vector<std::uint8_t>& telegram);
  void start_session(const HandshakeResult& result);
  [[nodiscard]] HandshakeSettings handshake_settings() const;

  // --- the cycle (p2os_cycle.cpp), all on the I/O thread with views_mutex_ held
  void serve_views(std::chrono::steady_clock::time_point now);
  void reconcile_subscriptions(std::chrono::steady_clock::time_point now);
  void serve_requests();
  void take_commands();
  void send_motor_command();
  void end_of_cycle(std::chrono::steady_clock::time_point now);
  void publish();
  [[nodiscard]] int count_views(P2osRole role) const;
  // Writes one packet; false (and the loop loses the robot) when the link fails.
  bool send(const hardware::p2os::Command& command);
  bool send_all(const std::vector<hardware::p2os::Command>& commands);

  // --- requests (p2os_requests.cpp), on the I/O thread
  core::RequestResult position_request(const core::Request& request);
  core::RequestResult sonar_request(const core::Request& request);
  core::RequestResult blobfinder_request(const core::Request& request);

  const RobotLinkOptions options_;
  const hardware::p2os::P2osFrameFormat format_;

  mutable std::mutex views_mutex_;
  std::vector<View> views_;

  // The handshake succeeded and the robot has not been lost since.
  std::atomic<bool> session_up_{false};
  std::atomic<int> baud_{0};
  mutable std::mutex identity_mutex_;
  std::optional<hardware::p2os::Sync2Reply> identity_;

  // Figures for counters(), written by the I/O thread.
  std::atomic<std::uint64_t> line_looks_{0};  // reads that found no whole packet: not timeouts
  std::atomic<std::uint64_t> sips_{0};
  std::atomic<std::uint64_t> unknown_packets_{0};
  std::atomic<std::uint64_t> bad_packets_{0};

  // --- everything below belongs to the I/O thread (and to open()/close()
  // while it is not running)
  std::unique_ptr<links::FramedReader> reader_;
  const hardware::p2os::RobotParams* params_;
  RobotReadings readings_;
  OdometryTracker odometry_;
  std::optional<std::string> link_error_;  // a write failed: lose the robot
  std::chrono::steady_clock::time_point last_sip_;
  bool new_sip_ = false;
  bool motor_sent_this_cycle_ = false;
  bool packet_sent_this_cycle_ = false;
  std::vector<std::uint8_t> unknown_types_logged_;

  bool position_active_ = false;  // a p2os_position device is attached
  bool motors_wanted_ = false;    // MOTOR_POWER
  bool motors_sent_ = false;      // what ENABLE last said this session
  VelocityCommand velocity_;
  VelocityMode velocity_mode_ = VelocityMode::direct_wheel;
  MotorLimits motor_limits_;
  int sonar_views_ = 0;
  bool sonar_wanted_ = false;
  std::optional<bool> sonar_sent_;  // unknown at the start of a session
  bool gyro_sent_ = false;
  std::optional<std::pair<std::uint8_t, std::uint8_t>> gripper_sent_;
  CmucamPhase cmucam_phase_ = CmucamPhase::off;
  std::chrono::steady_clock::time_point cmucam_track_at_;
  std::chrono::steady_clock::time_point cmucam_polled_at_;
  bool cmucam_answered_ = false;
  std::string cmucam_tracking_text_;
};

}  // namespace playerkit::drivers::p2os
