#pragma once
// An emulated Directed Perception PTU-46 pan-tilt unit, written from
// ptu46.md §6 ("what a faithful emulator must do"), so that Player 1.5's
// ptu46 driver works against it unmodified:
//
//  * commands end at a space, CR or LF, in either case; empty ones get no answer;
//  * one reply line per command, ended by CR LF, at once: `*`, `* <n>` (terse,
//    after FT) or `* Current Pan position is <n>` (verbose, the power-up
//    mode), `! <why>` for what the unit refuses;
//  * echo is on at power-up (each byte sent back as it arrives) until ED;
//  * PP/TP move toward the target at the axis's speed in independent mode
//    (CI); in pure-velocity mode (CV) the signed PS/TS speed drives the axis,
//    which stops at its limits;
//  * limits and resolution are configurable and never 0; R answers
//    `!T!T!P!P*` and recalibrates to 0;
//  * nothing unsolicited (no `!P`/`!T` limit messages).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "emulators/device_emulator.hpp"
#include "families/ptu46/protocol/ptu_commands.hpp"

namespace playerkit::emulators {

struct Ptu46EmulatorOptions {
  // The PTU-46-17.5 of the manual's examples (ptu46.md §6.5).
  double resolution_arc_seconds = 185.1428;  // both axes
  std::int64_t pan_min = -3090;
  std::int64_t pan_max = 3090;
  std::int64_t tilt_min = -907;
  std::int64_t tilt_max = 604;
  // PL/TL and PU/TU, positions/s. The lower limit is 0 so that a velocity
  // mode "stop" passes the driver's check (the manual's units say 31).
  std::int64_t lower_speed = 0;
  std::int64_t upper_speed = 2902;
  std::int64_t start_speed = 1000;  // the desired speed at power-up
  bool echo_at_power_up = true;
};

class Ptu46Emulator final : public DeviceEmulator {
 public:
  using Axis = hardware::ptu46::Axis;
  using ControlMode = hardware::ptu46::ControlMode;

  // Throws std::invalid_argument for limits the unit cannot have (a zero
  // limit or resolution, min >= max, speeds out of order).
  explicit Ptu46Emulator(Ptu46EmulatorOptions options = {});

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  [[nodiscard]] std::string describe() const override;

  // For tests and `--stats`.
  [[nodiscard]] double position(Axis axis) const { return state(axis).position; }
  [[nodiscard]] std::int64_t target(Axis axis) const { return state(axis).target; }
  [[nodiscard]] std::int64_t speed(Axis axis) const { return state(axis).speed; }
  [[nodiscard]] ControlMode mode() const { return mode_; }
  [[nodiscard]] bool terse() const { return terse_; }
  [[nodiscard]] bool echo() const { return echo_; }
  [[nodiscard]] std::uint64_t commands() const { return commands_; }

 private:
  struct AxisState {
    double position = 0;      // positions; fractional while moving
    std::int64_t target = 0;  // PP/TP in independent mode
    std::int64_t speed = 0;   // desired speed, positions/s (signed in CV)
    std::int64_t min = 0;
    std::int64_t max = 0;
  };
  [[nodiscard]] const AxisState& state(Axis axis) const { return axes_[axis == Axis::pan ? 0 : 1]; }
  AxisState& state(Axis axis) { return axes_[axis == Axis::pan ? 0 : 1]; }

  void execute(const std::string& text);
  // The reply line for one command ("" for none).
  std::string answer(const hardware::ptu46::ParsedCommand& command);
  std::string axis_command(Axis axis, char quantity, const hardware::ptu46::ParsedCommand& command);
  std::string value(Axis axis, std::string_view what, double number) const;
  void reply(const std::string& line);
  [[nodiscard]] bool moving() const;

  Ptu46EmulatorOptions options_;
  std::array<AxisState, 2> axes_;
  ControlMode mode_ = ControlMode::independent;
  bool terse_ = false;
  bool echo_ = true;
  std::string typed_;  // the command being typed
  Duration now_{0};
  std::vector<Telegram> output_;
  std::uint64_t commands_ = 0;
};

}  // namespace playerkit::emulators
