#pragma once
// An emulated Pioneer (P2OS/AROS controller), written from p2os.md §6 "What
// a faithful emulator must do": the SYNC0/1/2 handshake, SIPs every 100 ms
// after OPEN until CLOSE, motors that start disabled, VEL2/VEL/RVEL/STOP
// with the claimed row's conversions, sonar, gripper, gyro and CMUcam
// packets, and the 2 s watchdog. Pure: bytes in, time from outside,
// telegrams out (device_emulator.hpp).

#include "algorithms/geometry/pose2.hpp"
#include "emulators/device_emulator.hpp"
#include "emulators/mobile_base/differential_drive.hpp"
#include "families/p2os/emulator/gripper_model.hpp"
#include "families/p2os/emulator/p2os_emulator_options.hpp"
#include "families/p2os/emulator/sonar_array.hpp"
#include "families/p2os/protocol/commands.hpp"
#include "families/p2os/protocol/frame_format.hpp"
#include "families/p2os/protocol/robot_params.hpp"
#include "families/p2os/protocol/sip.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace playerkit::emulators {

// Where the handshake stands (p2os.md §2.4).
enum class P2osLinkState {
  unconnected,  // waiting for SYNC0
  got_sync0,    // SYNC0 echoed, waiting for SYNC1
  got_sync1,    // SYNC1 echoed, waiting for SYNC2
  synced,       // SYNC2 answered, waiting for OPEN
  connected,    // OPEN received: SIPs flowing until CLOSE
};

struct P2osLinkCounters {
  std::uint64_t frames = 0;           // well-formed frames from the host
  std::uint64_t bad_checksums = 0;    // framed right, wrong sum: ignored
  std::uint64_t noise_bytes = 0;      // skipped while hunting for FA FB, or sent at a wrong baud
  std::uint64_t undecodable = 0;      // frames whose command could not be parsed
  std::uint64_t ignored = 0;          // commands that do not apply in the current state
  std::uint64_t sips_sent = 0;
};

class P2osRobotEmulator final : public DeviceEmulator {
 public:
  // Throws std::invalid_argument for a subclass outside the table, a name
  // longer than 19 characters, or non-positive periods.
  explicit P2osRobotEmulator(P2osEmulatorOptions options = {});

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  void host_disconnected(Duration now) override;
  [[nodiscard]] int baud() const override { return options_.model_baud; }
  [[nodiscard]] std::string describe() const override;

  // The claimed parameter row.
  const hardware::p2os::RobotParams& params() const { return params_; }

  // Ground truth and odometry, as of the last receive()/advance().
  geometry::Pose2 true_pose() const { return drive_.true_pose(); }
  [[nodiscard]] std::optional<geometry::Pose2> world_pose() const override { return true_pose(); }
  // The controller's own odometry (what XPOS/YPOS/THPOS encode, before the
  // 12-bit wrap); zeroed by OPEN and SETO.
  geometry::Pose2 odometry_pose() const { return drive_.odometry(); }
  void set_true_pose(const geometry::Pose2& pose);
  mobile_base::WheelVelocities wheel_velocities() const { return drive_.wheels(); }

  P2osLinkState link_state() const { return state_; }
  bool connected() const { return state_ == P2osLinkState::connected; }
  bool motors_enabled() const { return motors_enabled_; }
  bool sonar_enabled() const { return sonar_on_; }
  bool gyro_enabled() const { return gyro_on_; }

  // Packets received, by command number (0 counts SYNC0 and PULSE alike).
  std::uint64_t packets_received(std::uint8_t command) const { return received_[command]; }
  const P2osLinkCounters& counters() const { return counters_; }

  // What the next SIP reports for transducer `index`, in metres.
  double sonar_range(int index) const;
  const p2os::SonarArray& sonar_array() const { return sonar_; }
  const p2os::GripperModel& gripper() const { return gripper_; }

  void set_battery_volts(double volts) { options_.battery_volts = volts; }
  void set_digital_inputs(std::uint8_t bits) { options_.digital_inputs = bits; }
  void set_analog_input(std::uint8_t value) { options_.analog_input = value; }
  void set_gripper_beams(bool outer_obstructed, bool inner_obstructed) {
    gripper_.set_beams(outer_obstructed, inner_obstructed);
  }

 private:
  enum class VelocityMode { translate_rotate, wheels };

  void parse_input(Duration now);
  void handle_frame(std::span<const std::uint8_t> payload, Duration now);
  void handle_handshake(const hardware::p2os::Command& command, Duration now);
  void handle_connected(const hardware::p2os::Command& command);
  void open(Duration now);
  void close();
  void apply_velocity_setpoints();
  void integrate_to(Duration t);
  std::optional<Duration> watchdog_deadline() const;
  std::optional<Duration> stale_input_deadline() const;
  void send(std::vector<std::uint8_t> payload);
  void send_sip();
  void send_gyro_packet();
  void send_cmucam(int byte_count);
  hardware::p2os::StandardSip build_sip();

  P2osEmulatorOptions options_;
  const hardware::p2os::RobotParams& params_;
  hardware::p2os::P2osFrameFormat format_;
  mobile_base::DifferentialDrive drive_;
  p2os::GripperModel gripper_;
  p2os::SonarArray sonar_;

  P2osLinkState state_ = P2osLinkState::unconnected;
  bool motors_enabled_ = false;
  bool sonar_on_ = false;
  bool gyro_on_ = false;
  VelocityMode velocity_mode_ = VelocityMode::translate_rotate;
  int translation_setpoint_ = 0;  // mm/s, from VEL
  int rotation_setpoint_ = 0;     // deg/s, from RVEL
  int next_sonar_ = 0;            // round-robin cursor when not all are sent

  Duration now_{0};
  Duration integrated_until_{0};
  Duration next_sip_{0};
  Duration last_packet_{0};
  bool watchdog_tripped_ = false;

  std::vector<std::uint8_t> input_;
  std::optional<Duration> input_waiting_since_;
  std::vector<Telegram> output_;
  std::array<std::uint64_t, 256> received_{};
  P2osLinkCounters counters_;
};

}  // namespace playerkit::emulators
