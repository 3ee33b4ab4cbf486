#pragma once
// An emulated Evolution Robotics ER1: its Robot Control Module on the serial
// line and the robot it drives, written from er1.md §6 ("what a faithful
// emulator must do") so that Player 1.5's er1_position works against it
// unmodified:
//
//  * commands are cut by opcode (4, 6 or 8 bytes) and each is answered at
//    once with the number of bytes 1.5 reads: 6 for INIT and the position,
//    4 for the status and the voltage, 2 for the rest; status, a byte
//    balancing the sum, data;
//  * a command whose checksum is wrong (1.5's ACCL_3) is answered with
//    status 1 and otherwise ignored;
//  * each motor latches the velocity of its last 0x11 and runs at it from
//    its next EXECUTE (0x1A); 0x39 zeroes its position count;
//  * the counts follow the wheels through the odometry error: the left
//    motor is mounted mirrored, so its count falls as the robot drives
//    forward; `left_motor_port` says which port it is on (the driver's
//    motor_dir).

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "emulators/device_emulator.hpp"
#include "emulators/mobile_base/differential_drive.hpp"
#include "families/er1/protocol/er1_commands.hpp"

namespace playerkit::emulators {

struct Er1EmulatorOptions {
  double axle = 0.38;       // m between the wheels (er1.md §4)
  int left_motor_port = 0;  // 1: the left motor is on the RCM's motor-1 port
  geometry::Pose2 initial_pose;
  mobile_base::OdometryError odometry_error;
  const grid::OccupancyGrid* map = nullptr;
};

class Er1Emulator final : public DeviceEmulator {
 public:
  using Motor = hardware::er1::Motor;

  explicit Er1Emulator(Er1EmulatorOptions options = {});

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] std::optional<geometry::Pose2> world_pose() const override { return drive_.true_pose(); }

  // For tests and `--stats`.
  [[nodiscard]] std::int32_t running_velocity(Motor motor) const { return motor_state(motor).running; }
  [[nodiscard]] std::int32_t latched_velocity(Motor motor) const { return motor_state(motor).latched; }
  [[nodiscard]] std::int32_t count(Motor motor) const;
  [[nodiscard]] const geometry::Pose2& true_pose() const { return drive_.true_pose(); }
  [[nodiscard]] bool moving() const;
  [[nodiscard]] std::uint64_t commands() const { return commands_; }
  [[nodiscard]] std::uint64_t bad_checksums() const { return bad_checksums_; }
  [[nodiscard]] std::uint64_t inits() const { return inits_; }
  [[nodiscard]] std::uint64_t executes() const { return executes_; }

 private:
  struct MotorState {
    std::int32_t latched = 0;  // from 0x11, taken at EXECUTE
    std::int32_t running = 0;
    double ticks = 0.0;        // the position count, unwrapped
  };
  [[nodiscard]] const MotorState& motor_state(Motor motor) const { return motors_[static_cast<int>(motor)]; }
  MotorState& motor_state(Motor motor) { return motors_[static_cast<int>(motor)]; }
  [[nodiscard]] Motor left_port() const { return options_.left_motor_port == 0 ? Motor::port0 : Motor::port1; }
  [[nodiscard]] Motor right_port() const { return options_.left_motor_port == 0 ? Motor::port1 : Motor::port0; }

  void obey(std::span<const std::uint8_t> command);
  void command_wheels();
  void run_for(double seconds);

  Er1EmulatorOptions options_;
  mobile_base::DifferentialDrive drive_;
  std::array<MotorState, 2> motors_{};
  std::vector<std::uint8_t> pending_;  // bytes of a command not yet whole
  Duration now_{0};
  std::vector<Telegram> output_;
  std::uint64_t commands_ = 0;
  std::uint64_t bad_checksums_ = 0;
  std::uint64_t inits_ = 0;
  std::uint64_t executes_ = 0;
};

}  // namespace playerkit::emulators
