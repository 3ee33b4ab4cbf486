#pragma once
// An emulated Sony EVI-D30 camera on VISCA, written from sonyevid30.md §6
// ("what a faithful emulator must do"), so that Player 1.5's sonyevid30
// driver works against it unmodified:
//
//  * packets `81 ... FF` (and the broadcasts `88 30 01 FF`, `88 01 00 01 FF`);
//  * inquiries answered at once (`90 50 ... FF`, unknown ones too; power on
//    and the EVI-D30's device type as the camera answers them);
//  * a command takes a free socket: `90 4y FF` at once, `90 5y FF` when its
//    motion ends (a drive, or a command the camera does not model, ends at
//    once); a new pan/tilt or zoom command ends the one of the same kind
//    still running (its completion first); no free socket: `90 60 03 FF`;
//  * pan, tilt and zoom move toward their targets at the commanded speeds,
//    clamped to the EVI-D30's ranges; drives run until stopped or a limit;
//  * cancel `81 2y FF`: `90 6y 04 FF` and the motion held where it is, or
//    `90 6y 05 FF` for a free socket;
//  * `90 60 02 FF` only for malformed input; nothing unsolicited.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "emulators/device_emulator.hpp"
#include "families/sonyevid30/protocol/camera_commands.hpp"

namespace playerkit::emulators {

struct Evid30EmulatorOptions {
  // Degrees per second at the top speeds 0x18 and 0x14 (Sony's EVI-D30: 80
  // and 50); a lower speed v turns at v/0x18 (v/0x14) of it.
  double pan_top_speed = 80;
  double tilt_top_speed = 50;
  // Seconds from full wide to full tele at zoom direct's speed.
  double zoom_travel_seconds = 2.0;
};

class Evid30Emulator final : public DeviceEmulator {
 public:
  // Throws std::invalid_argument for speeds or a travel time not above 0.
  explicit Evid30Emulator(Evid30EmulatorOptions options = {});

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  [[nodiscard]] std::string describe() const override;

  // Where the camera points (its units), for tests and `--stats`.
  [[nodiscard]] double pan_units() const { return axes_[kPan].position; }
  [[nodiscard]] double tilt_units() const { return axes_[kTilt].position; }
  [[nodiscard]] double zoom_units() const { return axes_[kZoom].position; }
  [[nodiscard]] int busy_sockets() const;
  [[nodiscard]] std::uint64_t commands() const { return commands_; }
  [[nodiscard]] std::uint64_t cancels() const { return cancels_; }
  [[nodiscard]] std::uint64_t syntax_errors() const { return syntax_errors_; }

 private:
  enum Function { kPanTilt, kZoomFunction };
  static constexpr std::size_t kPan = 0, kTilt = 1, kZoom = 2;
  struct AxisState {
    double position = 0;
    double target = 0;
    double speed = 0;  // units/s toward the target (> 0), or signed while driving
    bool driving = false;
    double min = 0;
    double max = 0;
  };

  void execute(std::span<const std::uint8_t> packet);
  void command(const hardware::sonyevid30::HostMessage& message);
  void start(const hardware::sonyevid30::HostMessage& message);
  void hold(Function function);
  [[nodiscard]] bool in_motion(Function function) const;
  [[nodiscard]] bool moving(const AxisState& axis) const;
  void send(hardware::sonyevid30::Bytes bytes);

  Evid30EmulatorOptions options_;
  std::array<AxisState, 3> axes_;
  // What each socket (1, 2) holds until its completion.
  std::array<std::optional<Function>, 2> sockets_;
  std::vector<std::uint8_t> received_;
  Duration now_{0};
  std::vector<Telegram> output_;
  std::uint64_t commands_ = 0;
  std::uint64_t cancels_ = 0;
  std::uint64_t syntax_errors_ = 0;
};

}  // namespace playerkit::emulators
