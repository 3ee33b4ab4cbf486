#pragma once
// An emulated Amtec PowerCube wrist, written from amtecpowercube.md §6
// ("what a faithful emulator must do"), so that Player 1.5's driver works
// against it unmodified:
//
//  * frames decoded with their DLE escapes; a frame whose check byte is
//    wrong, or addressed to a module not on the line, gets no answer;
//  * every other frame exactly one reply frame (one write), at once: the
//    request's header with the reply's length, data, check, escaped;
//  * GET_EXTENDED of position (0x3C), velocity (0x41), state (0x27) and the
//    position limits (0x45, 0x46); RESET clears an error and a halt; HOME
//    drives to 0 and then sets the homed bit; HALT brakes and sets halted;
//  * SET_MOTION step (arrive at a position after a time) and velocity, with
//    the module's top speed and acceleration, inside its position limits;
//    a module not homed, halted or in error does not move;
//  * nothing unsolicited; 38400 baud (bytes at another speed are noise).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "emulators/device_emulator.hpp"
#include "families/amtecpowercube/protocol/powercube_frames.hpp"

namespace playerkit::emulators {

struct PowercubeEmulatorOptions {
  double max_speed = 90;       // deg/s, either module
  double acceleration = 360;   // deg/s^2
  double pan_min = -170, pan_max = 170;   // degrees, module convention
  double tilt_min = -110, tilt_max = 110;
  double pan_start = 0, tilt_start = 0;   // where the modules stand at power-up, not homed
  bool pan_present = true, tilt_present = true;
};

class PowercubeEmulator final : public DeviceEmulator {
 public:
  using Module = hardware::powercube::Module;
  static constexpr int kBaud = 38400;

  // Throws std::invalid_argument for settings no module can have.
  explicit PowercubeEmulator(PowercubeEmulatorOptions options = {});

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  [[nodiscard]] int baud() const override { return kBaud; }
  [[nodiscard]] std::string describe() const override;

  // For tests: radians and rad/s in module convention.
  [[nodiscard]] double position(Module module) const { return axis(module).position; }
  [[nodiscard]] double velocity(Module module) const { return axis(module).velocity; }
  [[nodiscard]] std::uint32_t state(Module module) const { return axis(module).state; }
  [[nodiscard]] double target(Module module) const { return axis(module).target; }
  [[nodiscard]] std::uint64_t frames() const { return frames_; }
  [[nodiscard]] std::uint64_t bad_checks() const { return bad_checks_; }
  [[nodiscard]] std::uint64_t homings(Module module) const { return axis(module).homings; }
  // The time the last step was given to arrive in, ms.
  [[nodiscard]] int step_time(Module module) const { return axis(module).step_time; }
  // A module fault (a following error, an overheated motor): it stops and
  // sets its error bit until RESET.
  void raise_error(Module module);

 private:
  enum class Motion { idle, step, velocity, homing };
  struct Axis {
    bool present = true;
    double position = 0, velocity = 0;  // rad, rad/s
    double min = 0, max = 0;            // rad
    std::uint32_t state = 0;
    Motion motion = Motion::idle;
    double target = 0;        // step and homing: rad; velocity: rad/s
    double cruise = 0;        // step: the speed that arrives on time, rad/s
    std::uint64_t homings = 0;
    int step_time = 0;
  };
  [[nodiscard]] const Axis& axis(Module module) const { return axes_[module == Module::pan ? 0 : 1]; }
  Axis& axis(Module module) { return axes_[module == Module::pan ? 0 : 1]; }
  Axis* axis_with_id(std::uint8_t id);

  void handle(std::span<const std::uint8_t> telegram);
  std::vector<std::uint8_t> execute(Axis& axis, const std::vector<std::uint8_t>& data);
  void start_motion(Axis& axis, const std::vector<std::uint8_t>& data);
  void step(Axis& axis, double seconds) const;
  [[nodiscard]] bool moving() const;

  PowercubeEmulatorOptions options_;
  std::array<Axis, 2> axes_;
  double max_speed_ = 0, acceleration_ = 0;  // rad/s, rad/s^2
  std::vector<std::uint8_t> received_;
  Duration now_{0};
  std::vector<Telegram> output_;
  std::uint64_t frames_ = 0;
  std::uint64_t bad_checks_ = 0;
};

}  // namespace playerkit::emulators
