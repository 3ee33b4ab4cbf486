#pragma once
// One Pioneer on one serial line, shared by the robot's p2os devices
// (core::SharedConnection): the first device set up opens the line and runs
// the handshake, then one I/O thread does everything else until the last
// device leaves:
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
//  * notices a silent robot (no SIP for sip_timeout): one log line, the
//    devices unavailable, then handshakes in the background until the robot
//    answers again (one log line); 1.5 never noticed (quirk 3).
//
// When the last device leaves, the robot is stopped (STOP, ENABLE 0), sent
// CLOSE, and the line closed.

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
#include "core/shared_connection.hpp"
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
#include "links/byte_link.hpp"
#include "links/framed_reader.hpp"
#include "links/link_counters.hpp"

namespace playerkit::drivers::p2os {

class P2osConnection final : public core::SharedConnection {
 public:
  P2osConnection(RobotLinkOptions options, core::Logger& logger);
  ~P2osConnection() override;

  // From a device's setup(), holding a Use: its data starts with the next
  // SIP. Throws core::DriverError while the robot is not answering.
  void add_device(P2osRole role, core::Device& device, const MotorLimits& limits = {});
  // From its shutdown(), before letting go of the Use. Once this returns the
  // I/O thread no longer touches the device.
  void remove_device(const core::Device& device);

  // A device's request, on the I/O thread (through Device::service_requests).
  core::RequestResult handle_request(P2osRole role, const core::Request& request);

  // The link's counters summed over every session, plus the robot's.
  [[nodiscard]] std::vector<core::DriverCounter> counters() const;
  // Every byte of the line from now on (also across reopening).
  void set_byte_trace(core::ByteTrace trace);

  [[nodiscard]] const RobotLinkOptions& options() const { return options_; }
  // A session is up: the handshake succeeded and SIPs are arriving.
  [[nodiscard]] bool robot_answering() const { return session_up_.load(); }
  // The SYNC2 reply of the current (or last) session.
  [[nodiscard]] std::optional<hardware::p2os::Sync2Reply> identity() const;
  // The speed the robot answered at (0 on TCP, or before the first session).
  [[nodiscard]] int baud() const { return baud_.load(); }
  // CPU time the I/O thread has used, while it runs.
  [[nodiscard]] std::optional<std::chrono::nanoseconds> io_thread_cpu_time() const;

 protected:
  void open() override;
  void close() noexcept override;

 private:
  struct View {
    P2osRole role;
    core::Device* device;
    MotorLimits limits;
  };
  enum class CmucamPhase { off, resetting, tracking };

  // --- lifecycle (p2os_connection.cpp)
  void run(const std::stop_token& stop);
  void step();
  void handle_telegram(const std::vector<std::uint8_t>& telegram);
  void start_session(const HandshakeResult& result);
  void lose_robot(const std::string& reason);
  void reconnect(const std::stop_token& stop);
  [[nodiscard]] HandshakeSettings handshake_settings() const;
  [[nodiscard]] std::string label() const;  // "p2os /dev/ttyS0"

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
  core::Logger& logger_;
  const hardware::p2os::P2osFrameFormat format_;

  // The link: replaced at open(), read by counters() and set_byte_trace()
  // from other threads under link_mutex_.
  mutable std::mutex link_mutex_;
  std::shared_ptr<links::ByteLink> link_;
  core::ByteTrace trace_;
  links::LinkCounterSnapshot closed_totals_;  // of links closed before

  mutable std::mutex views_mutex_;
  std::vector<View> views_;

  std::jthread thread_;
  std::atomic<bool> session_up_{false};
  std::atomic<int> baud_{0};
  mutable std::mutex identity_mutex_;
  std::optional<hardware::p2os::Sync2Reply> identity_;

  // Figures for counters(), written by the I/O thread.
  std::atomic<std::uint64_t> poll_timeouts_{0};  // the loop's own short waits, not timeouts
  std::atomic<std::uint64_t> sips_{0};
  std::atomic<std::uint64_t> unknown_packets_{0};
  std::atomic<std::uint64_t> bad_packets_{0};
  std::atomic<std::uint64_t> robot_losses_{0};
  std::atomic<std::uint64_t> reconnects_{0};

  // --- everything below belongs to the I/O thread (and to open()/close()
  // while it is not running)
  std::unique_ptr<links::FramedReader> reader_;
  const hardware::p2os::RobotParams* params_;
  RobotReadings readings_;
  OdometryTracker odometry_;
  std::optional<std::string> link_error_;  // a write failed: lose the robot
  std::chrono::steady_clock::time_point last_sip_;
  std::chrono::steady_clock::time_point lost_at_;
  int reconnect_attempt_ = 0;
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
