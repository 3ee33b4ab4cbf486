#pragma once
// An emulated Botrics O-Bot ("Trogdor") cerebellum, written from trogdor.md
// §6 ("what a faithful emulator must do"), so that Player 1.5's trogdor
// driver works against it unmodified:
//
//  * every complete host message is answered at once with ACK (06); INIT's
//    three bytes get one; 'v' and 'a' are 10-byte messages whose XOR is
//    checked (NACK, 21, when it fails); a byte no message starts with is
//    NACKed;
//  * 'o' is answered by the ACK and the 18-byte odometry block in one write;
//  * two wheel velocities (ticks per 1.9375 ms PID period) drive the body
//    (mobile_base::DifferentialDrive: true pose, odometry error, stalls
//    against the map) and two int32 counters, which start at 1 000 000 and
//    never read exactly 0;
//  * 'e'/'d' enable and disable motion (enabled at power-up, since 1.5
//    never sends 'e'); DEINIT stops the wheels and is ACKed; 'a' is
//    accepted and its values ignored;
//  * it listens at 57600 baud only: bytes at another speed get no answer;
//  * a message left half written for 100 ms is dropped (a host that died
//    mid-write must not swallow the next one's bytes).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/grid/occupancy_grid.hpp"
#include "emulators/device_emulator.hpp"
#include "emulators/mobile_base/differential_drive.hpp"
#include "emulators/mobile_base/robot_options.hpp"
#include "families/trogdor/protocol/trogdor_messages.hpp"

namespace playerkit::emulators {

struct TrogdorEmulatorOptions {
  mobile_base::RobotBodyOptions body;
  std::int32_t start_count = 1'000'000;
  // Reported in the error byte of every odometry block.
  bool encoder_error = false;
  // GET_VOLTAGE's value (the sheet gives no unit: the reference never asks).
  std::int32_t voltage = 120;
};

class TrogdorEmulator final : public DeviceEmulator {
 public:
  TrogdorEmulator(TrogdorEmulatorOptions options, const grid::OccupancyGrid* map);

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] std::optional<geometry::Pose2> world_pose() const override { return drive_.true_pose(); }
  [[nodiscard]] int baud() const override { return kBaud; }
  static constexpr int kBaud = 57600;

  // For tests and `--stats`.
  [[nodiscard]] const hardware::trogdor::WheelPair& velocities() const { return velocities_; }
  [[nodiscard]] hardware::trogdor::OdometryReading reading() const;
  [[nodiscard]] bool motion_enabled() const { return enabled_; }
  [[nodiscard]] bool initialised() const { return initialised_; }
  [[nodiscard]] const hardware::trogdor::WheelPair& accelerations() const { return accelerations_; }
  [[nodiscard]] const mobile_base::DifferentialDrive& drive() const { return drive_; }
  [[nodiscard]] std::uint64_t messages() const { return messages_; }
  [[nodiscard]] std::uint64_t refused() const { return refused_; }

 private:
  void execute(const hardware::trogdor::Bytes& message);
  void apply_velocities();
  void send(hardware::trogdor::Bytes bytes, bool has_checksum);
  void integrate(Duration until);

  TrogdorEmulatorOptions options_;
  mobile_base::DifferentialDrive drive_;
  hardware::trogdor::WheelPair velocities_;
  hardware::trogdor::WheelPair accelerations_;
  // Ticks counted since power-up, fractional: the counters are these rounded.
  double left_ticks_ = 0;
  double right_ticks_ = 0;
  bool enabled_ = true;
  bool initialised_ = false;
  hardware::trogdor::Bytes partial_;
  Duration partial_since_{0};
  Duration now_{0};
  std::vector<Telegram> output_;
  std::uint64_t messages_ = 0;
  std::uint64_t refused_ = 0;
};

}  // namespace playerkit::emulators
