#pragma once
// A UBot: the Robotics Extension Board running LPRSerCom on a differential
// drive, written from reb.md §6 ("what a faithful emulator must do"):
//
//  * CR-ended command lines; each answered, after the time its characters
//    and the reply's take at 38400 baud 8N2 (at least 2 ms, so a driver's
//    cycle of six round trips lasts well over 10 ms), with `<reply>\r\n`
//    then the prompt `:\r\n`;
//  * motors 0 (right, mounted reversed) and 2 (left): a speed in pulses per
//    10 ms (D, read by E), a 32-bit position counter (G sets, H reads),
//    position moves at the J profile's speed (C, status by K); every 10 ms
//    the wheels move the body (mobile_base::DifferentialDrive, stalling on
//    the map) and the counters count what its odometry saw, error included;
//  * W: eight IR readings in 4 mV steps (zero while the emitters are off, Y),
//    I,15: the battery in 20 mV steps; A, F, J, Q acknowledged.

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "emulators/device_emulator.hpp"
#include "emulators/mobile_base/differential_drive.hpp"
#include "emulators/mobile_base/range_ring.hpp"
#include "emulators/mobile_base/robot_options.hpp"
#include "families/reb/protocol/reb_lines.hpp"
#include "families/reb/protocol/reb_params.hpp"

namespace playerkit::emulators {

struct RebEmulatorOptions {
  std::string subclass = "slow";  // the encoders of reb.md §3.1's row
  double battery_volts = 7.2;
  double ir_range = 0.8;  // m: farther obstacles read nothing
  mobile_base::RobotBodyOptions body;
  const grid::OccupancyGrid* map = nullptr;
};

class RebEmulator final : public DeviceEmulator {
 public:
  explicit RebEmulator(RebEmulatorOptions options);

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  [[nodiscard]] std::optional<geometry::Pose2> world_pose() const override { return drive_.true_pose(); }
  [[nodiscard]] std::string describe() const override;

  // For tests.
  struct Motor {
    std::int32_t speed = 0;          // pulses per 10 ms, set by D (or by a position move)
    double counter = 0.0;            // pulses; H reads it rounded
    std::optional<std::int32_t> target;  // a C move under way or reached
    std::int32_t profile_speed = 24;     // J
    std::int32_t profile_acceleration = 24;
  };
  [[nodiscard]] const Motor& motor(hardware::reb::Motor which) const;
  [[nodiscard]] bool ir_on() const { return ir_on_; }
  [[nodiscard]] const mobile_base::DifferentialDrive& drive() const { return drive_; }
  [[nodiscard]] std::uint64_t commands_answered() const { return answered_; }
  // The IR reading (4 mV steps) of sensor `index` now.
  [[nodiscard]] std::int32_t ir_reading(int index) const;

 private:
  struct Pending {
    Duration due;
    std::vector<Telegram> telegrams;
  };
  void handle_line(const std::string& line, Duration now);
  std::optional<hardware::reb::Reply> answer(const hardware::reb::Command& command);
  [[nodiscard]] bool moving() const;
  void tick();
  Motor* motor_numbered(std::int32_t number);

  const hardware::reb::RebParams& params_;
  RebEmulatorOptions options_;
  mobile_base::DifferentialDrive drive_;
  mobile_base::RangeRing ir_ring_;
  Motor left_;
  Motor right_;
  bool ir_on_ = false;
  std::string partial_line_;
  std::deque<Pending> pending_;
  std::vector<Telegram> output_;
  Duration now_{0};
  Duration next_tick_{0};
  std::uint64_t answered_ = 0;
};

}  // namespace playerkit::emulators
