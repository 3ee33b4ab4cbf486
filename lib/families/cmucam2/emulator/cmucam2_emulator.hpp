#pragma once
// An emulated CMUcam2 with its servos, written from cmucam2.md §6 ("what a
// faithful emulator must do"), so that Player 1.5's driver works against it:
//
//  * 115200 8N1 ASCII commands ended by CR, extra spaces ignored; nothing is
//    sent until the camera is spoken to;
//  * `PM 0|1`, a lone CR, `SV`, `CP`, `CR` answer `ACK` CR `:`; GS and GV
//    answer `ACK` CR, a line, `:`; anything else `NCK` CR `:`;
//  * `TC` (six bounds, or none for the last ones) answers `ACK` CR at once,
//    never NCK (bounds beyond a byte are clamped),
//    and then, one frame later, the T packet of the tracked colour in the
//    scene as the servos point the camera: in poll mode one packet (then
//    `:` when `prompt_after_packet`, as the real camera; without it every
//    1.5 cycle parses a fresh packet, §6.6), otherwise one per frame until
//    the next command;
//  * the servos (0 pan, 1 tilt, 2-4 spare) slew toward their SV positions
//    at a servo's speed; GS reports the position commanded, as the camera
//    knows no other.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "emulators/device_emulator.hpp"
#include "families/cmucam2/emulator/cmucam_scene.hpp"
#include "families/cmucam2/protocol/cmucam_protocol.hpp"

namespace playerkit::emulators {

struct Cmucam2EmulatorOptions {
  std::chrono::milliseconds frame_period{30};  // the CMUcam2's low-resolution frame time
  bool prompt_after_packet = true;              // cmucam2.md §6.6, device-accurate
  double servo_speed = 400;                      // positions/s, a hobby servo's 60 degrees in 0.2 s
  double degrees_per_position = 0.75;            // of both servos, around position 128
};

class Cmucam2Emulator final : public DeviceEmulator {
 public:
  static constexpr int kServos = 5;
  static constexpr int kServoCentre = 128;
  static constexpr std::string_view kVersion = "CMUcam2 v1.00 c6";

  explicit Cmucam2Emulator(cmucam2::Scene scene, Cmucam2EmulatorOptions options = {});
  // The synthetic scene: a red disc 10 degrees left of centre, a green one to the right.
  [[nodiscard]] static cmucam2::Scene default_scene();

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  [[nodiscard]] std::string describe() const override;

  // For tests and `--stats`.
  [[nodiscard]] int servo_target(int servo) const { return servos_[static_cast<std::size_t>(servo)].target; }
  [[nodiscard]] double servo_position(int servo) const { return servos_[static_cast<std::size_t>(servo)].position; }
  [[nodiscard]] bool poll_mode() const { return poll_mode_; }
  [[nodiscard]] bool streaming() const { return next_packet_.has_value(); }
  [[nodiscard]] std::optional<hardware::cmucam2::ColorBounds> tracked() const { return tracked_; }
  [[nodiscard]] std::uint64_t packets() const { return packets_; }
  [[nodiscard]] std::uint64_t refused() const { return refused_; }
  // Where the camera looks now, degrees (pan left, tilt up).
  [[nodiscard]] double pan_degrees() const;
  [[nodiscard]] double tilt_degrees() const;

 private:
  struct Servo {
    int target = kServoCentre;
    double position = kServoCentre;
  };
  void execute(const std::string& line);
  void say(const std::string& text);
  void send_packet();
  void move_servos(Duration until);

  cmucam2::Scene scene_;
  Cmucam2EmulatorOptions options_;
  std::array<Servo, kServos> servos_{};
  bool poll_mode_ = false;  // off at power-up
  std::optional<hardware::cmucam2::ColorBounds> tracked_;
  std::optional<Duration> next_packet_;
  std::string typed_;
  Duration now_{0};
  std::vector<Telegram> output_;
  std::uint64_t packets_ = 0;
  std::uint64_t refused_ = 0;
};

}  // namespace playerkit::emulators
