#pragma once
// One UBot on one serial line, shared by its reb devices, on
// hardware_driver::RobotConnection (the line, the I/O thread woken by the
// devices, losing and finding the robot, counters, trace). The first device
// set up opens the line and switches the IR emitters off (connect()); then
// the I/O thread, in serve():
//
//  * answers the devices' requests and takes position commands at once,
//    sending the motors' set-points (D) the moment they change;
//  * polls the board every cycle for what the attached devices need (W for
//    ir, I,15 for power, K,0 in position mode, H,2 and H,0 for odometry)
//    and publishes each device's data, all with one timestamp;
//  * notices a board that stopped answering (a command unanswered twice),
//    after which reconnect() tries one command per attempt.
//
// When the last device leaves, the motors are stopped and the IR emitters
// switched off (stop_motion()), as 1.5 did, and the line is closed.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/device.hpp"
#include "core/driver.hpp"
#include "core/logger.hpp"
#include "families/reb/driver/reb_options.hpp"
#include "families/reb/protocol/reb_lines.hpp"
#include "families/reb/protocol/reb_params.hpp"
#include "framing/terminated_line_format.hpp"
#include "hardware_driver/robot_connection.hpp"
#include "interfaces/odometry_integrator.hpp"
#include "interfaces/position_requests.hpp"
#include "interfaces/ranger_requests.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::drivers::reb {

// The board's control modes (reb.md §3.2).
enum class ControlMode { direct_velocity, heading, position };

class RebConnection final : public hardware_driver::RobotConnection,
                            private interfaces::PositionBase,
                            private interfaces::RangerArray {
 public:
  RebConnection(RebLinkOptions options, core::Logger& logger);
  ~RebConnection() override;

  // From a device's setup(), holding a Use. Throws core::DriverError while
  // the board is not answering. `heading_control`: reb_position's option.
  void add_device(RebRole role, core::Device& device, bool heading_control = false);
  // From its shutdown(); afterwards the I/O thread no longer touches it.
  void remove_device(core::Device& device);
  // A device's request, on the I/O thread.
  core::RequestResult handle_request(RebRole role, const core::Request& request);

  [[nodiscard]] const RebLinkOptions& options() const { return options_; }
  [[nodiscard]] ControlMode control_mode() const { return mode_.load(); }

 private:
  struct View {
    RebRole role;
    core::Device* device;
  };

  // --- RobotConnection
  void connect(links::ByteLink& link) override;
  bool reconnect(links::ByteLink& link, Attempt attempt, const std::stop_token& stop) override;
  void serve(links::ByteLink& link, const core::Wakeup::Woken& woke) override;
  [[nodiscard]] Clock::time_point next_deadline() const override { return next_cycle_; }
  void serve_while_away() override;
  void robot_lost() override;
  void stop_motion(links::ByteLink& link) noexcept override;
  [[nodiscard]] std::vector<core::DriverCounter> protocol_counters() const override;

  // --- the board (reb_connection.cpp)
  void start_session(links::ByteLink& link);
  // One command and its reply (then the prompt); throws ExchangeError when
  // the board says nothing twice, LinkError when the line fails.
  hardware::reb::Reply exchange(const hardware::reb::Command& command);
  void exchange_both(hardware::reb::Command (*make)(hardware::reb::Motor, std::int32_t), std::int32_t left,
                     std::int32_t right);
  void await_prompt();
  void drain_input();

  // --- the cycle (reb_cycle.cpp), views_mutex_ held
  void reconcile_subscriptions();
  void start_position();
  void serve_requests();
  void take_commands();
  void send_motor_speeds(bool even_if_unchanged);
  void poll();
  void read_odometry();
  void publish();
  [[nodiscard]] bool has(RebRole role) const;

  // --- requests (reb_requests.cpp)
  std::optional<interfaces::BaseGeometry> geometry() override;
  bool set_motor_power(bool on) override;
  bool set_velocity_mode(std::uint8_t mode) override;
  bool reset_odometry() override;
  bool set_odometry(const geometry::Pose2& pose) override;
  bool set_position_mode(bool position_control) override;
  bool set_speed_pid(const interfaces::PidGains& gains) override;
  bool set_position_pid(const interfaces::PidGains& gains) override;
  bool set_speed_profile(const interfaces::SpeedProfile& profile) override;
  std::optional<std::vector<geometry::Pose2>> sensor_poses() override;
  bool set_power(bool on) override;
  // Runs `work` against the board, false when it is away or stops answering
  // (the loss is then noted for serve()).
  template <class Work>
  bool with_board(Work work);
  void zero_counters();

  const RebLinkOptions options_;
  const hardware::reb::RebParams& params_;
  const framing::TerminatedLineFormat format_;

  mutable std::mutex views_mutex_;
  std::vector<View> views_;
  bool heading_default_ = false;

  std::atomic<bool> session_up_{false};
  std::atomic<ControlMode> mode_{ControlMode::direct_velocity};
  std::atomic<std::uint64_t> cycles_{0};
  std::atomic<std::uint64_t> missing_prompts_{0};
  std::atomic<std::uint64_t> stray_lines_{0};  // lines that were neither the reply nor a prompt
  std::atomic<std::uint64_t> noisy_lines_{0};  // a reply or prompt behind line noise, taken

  // --- the I/O thread's (and open()/close()'s while it is not running)
  std::unique_ptr<links::FramedReader> reader_;
  std::unique_ptr<links::Exchanger> exchanger_;
  std::optional<std::string> lost_;  // a request found the board silent
  Clock::time_point next_cycle_{};
  bool position_started_ = false;   // the first position subscriber's set-up was sent
  bool position_resumed_ = false;   // the set-up is owed again after a reconnection, not to a new subscriber
  std::optional<bool> ir_sent_;     // what Y last said this session
  bool ir_attached_ = false;        // an ir device was there at the last look
  bool motors_enabled_ = false;     // MOTOR_POWER
  protocol::PositionCommand command_;
  std::optional<hardware::reb::MotorSpeeds> speeds_sent_;
  // Odometry: the counters as last read, each when its reply came (nothing:
  // the next reading is a new baseline). The two are read one exchange
  // apart, so the right one is brought to the left one's time.
  struct CounterReading {
    std::int32_t value = 0;
    Clock::time_point at{};
  };
  std::optional<CounterReading> left_counter_;
  std::optional<CounterReading> right_counter_;
  double right_lag_ = 0.0;  // pulses: the right counter at the left reading's time, minus its reading
  interfaces::OdometryIntegrator odometry_;
  geometry::Pose2 velocity_;  // m/s, 0, rad/s
  bool on_target_ = false;
  std::vector<std::int32_t> ir_readings_;
  std::optional<std::int32_t> battery_reading_;
};

}  // namespace playerkit::drivers::reb
