#pragma once
// One Khepera on one serial line, shared by khepera_position and
// khepera_ir, on hardware_driver::RobotConnection (the line, its I/O
// thread woken by the devices, losing and finding the robot, the counters
// and the trace). The robot only ever answers: every reading is a command
// and its reply (khepera.md §2). The I/O thread:
//
//  * at setup sends CR LF (ending whatever was half typed) and `E`, which
//    must be answered;
//  * on the first position device: `D,0,0` and `G,0,0` (odometry from zero);
//    on the last: `D,0,0`;
//  * sends a client's velocity command at once as `D,l,r`, in the
//    interface's units (1.5 drove at about 0.69x the command), `D,0,0`
//    while the motors are off (MOTOR_POWER; off after each first
//    subscription, as in 1.5);
//  * every cycle_time: `D` again while a position device is there, `N`, `H`
//    and `E`; then publishes odometry (integrated in the world frame,
//    counter-clockwise positive: 1.5 did neither) and the IR readings;
//  * a reply missing after three tries loses the robot (RobotLost): one log
//    line, the devices unavailable, `E` tried in the background;
//  * when the last device leaves: `D,0,0` before the line closes (1.5 left
//    the robot driving).

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <stop_token>
#include <string>
#include <vector>

#include "core/device.hpp"
#include "core/driver.hpp"
#include "core/logger.hpp"
#include "families/khepera/driver/khepera_options.hpp"
#include "families/khepera/protocol/khepera_commands.hpp"
#include "families/khepera/protocol/khepera_units.hpp"
#include "hardware_driver/robot_connection.hpp"
#include "interfaces/odometry_integrator.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"
#include "framing/terminated_line_format.hpp"

namespace playerkit::drivers::khepera {

enum class KheperaRole : std::uint8_t { position, ir };

class KheperaConnection final : public hardware_driver::RobotConnection {
 public:
  KheperaConnection(KheperaRobotOptions options, core::Logger& logger);
  ~KheperaConnection() override;

  // From a device's setup(), holding a Use. Throws core::DriverError while
  // the robot is not answering.
  void add_position(core::Device& device, const KheperaPositionOptions& options);
  void add_ir(core::Device& device, const KheperaIrOptions& options);
  // From its shutdown(); afterwards the I/O thread no longer touches it.
  void remove_device(core::Device& device);

  // A device's request, on the I/O thread (through Device::service_requests).
  core::RequestResult handle_request(KheperaRole role, const core::Request& request);

  [[nodiscard]] const KheperaRobotOptions& options() const { return options_; }

 private:
  struct View {
    KheperaRole role;
    core::Device* device;
  };
  struct Counters {
    std::int64_t left = 0;
    std::int64_t right = 0;
  };

  // --- the robot's life (khepera_connection.cpp)
  void connect(links::ByteLink& link) override;
  bool reconnect(links::ByteLink& link, Attempt attempt, const std::stop_token& stop) override;
  void serve(links::ByteLink& link, const core::Wakeup::Woken& woke) override;
  [[nodiscard]] Clock::time_point next_deadline() const override;
  void serve_while_away() override;
  void robot_lost() override;
  void stop_motion(links::ByteLink& link) noexcept override;
  [[nodiscard]] std::vector<core::DriverCounter> protocol_counters() const override;
  void start_session();
  // One command and its reply with `count` values; throws RobotLost when
  // none came after three tries.
  hardware::khepera::Message ask(const hardware::khepera::Message& command, std::optional<std::size_t> count);

  // --- the cycle (khepera_cycle.cpp), with views_mutex_ held
  void reconcile_subscriptions();
  void serve_requests();
  void take_commands();
  void send_speeds();
  [[nodiscard]] hardware::khepera::WheelSpeeds wheel_command() const;
  // For requests, which must be answered whatever happens: false when the
  // robot did not answer, which serve() then reports as lost.
  bool try_ask(const hardware::khepera::Message& command);
  void run_cycle();
  void publish();
  [[nodiscard]] bool has_view(KheperaRole role) const;

  // --- requests (khepera_cycle.cpp)
  core::RequestResult position_request(const core::Request& request);
  core::RequestResult ir_request(const core::Request& request);

  const KheperaRobotOptions options_;
  const framing::TerminatedLineFormat format_{hardware::khepera::reply_line_options()};

  mutable std::mutex views_mutex_;
  std::vector<View> views_;

  std::atomic<bool> session_up_{false};
  std::atomic<std::uint64_t> cycles_{0};
  std::atomic<std::uint64_t> stray_lines_{0};

  // --- the I/O thread's (and open()'s and close()'s while it is not running)
  std::unique_ptr<links::FramedReader> reader_;
  std::unique_ptr<links::Exchanger> exchanger_;
  KheperaPositionOptions position_options_;
  KheperaIrOptions ir_options_;
  Clock::time_point next_cycle_{};
  bool position_active_ = false;
  bool ir_active_ = false;
  bool motors_on_ = false;
  double speed_ = 0.0;      // commanded, m/s
  double turn_rate_ = 0.0;  // commanded, rad/s
  std::optional<Counters> last_counters_;  // none: the next H starts afresh
  interfaces::OdometryIntegrator odometry_;
  geometry::Pose2 velocity_;  // m/s, 0, rad/s from E
  std::vector<std::int64_t> proximity_;
  bool fresh_readings_ = false;
  std::optional<std::string> lost_reason_;
};

}  // namespace playerkit::drivers::khepera
