#pragma once
// An emulated Segway RMP behind an slcan USB-CAN adapter, written from
// segwayrmp.md §6 ("what a faithful emulator must do") and the Lawicel
// protocol the adapter speaks:
//
//  * the adapter: S0-S8 set the bit rate and O opens the channel only while
//    it is closed, C closes it, V and N answer a version and a serial
//    number; each accepted command is acknowledged with CR, a refused one
//    with BEL; a frame sent while open is acknowledged with "z";
//  * while open, the robot sends one each of 0x400-0x404 every 1/rate s
//    (100 Hz), its counters in the sheet's units: fore/aft 33215 counts a
//    metre, yaw 112644 a revolution growing counter-clockwise, wheel speeds
//    332 counts per m/s, yaw rate 7.8 counts per deg/s clockwise positive,
//    the battery slot so that x 7.2 gives decivolts;
//  * 0x413 sets the speeds (trans / 0.32882963 mm/s, rot / 7.8 deg/s
//    counter-clockwise), and its status commands: 10 and 12 scale the
//    top speed and turn rate by value/16, 11 the acceleration, 50 zeroes the
//    counters its bits name; 0x412 stops the robot and silences it until
//    the channel is opened again;
//  * a watchdog: no 0x413 for `watchdog` seconds stops the robot;
//  * the body is a mobile_base::DifferentialDrive, so odometry error, a map
//    and riders (a laser on it) work as on the Pioneer.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "emulators/device_emulator.hpp"
#include "emulators/mobile_base/odometry_error.hpp"
#include "families/segwayrmp/protocol/rmp_frames.hpp"

namespace playerkit::grid {
class OccupancyGrid;
}

namespace playerkit::emulators::mobile_base {
class DifferentialDrive;
}

namespace playerkit::emulators {

struct SegwayRmpEmulatorOptions {
  double status_rate = 100;     // Hz, each of the five messages
  double watchdog = 0.25;       // s without 0x413 before the robot stops; 0: never
  double battery_percent = 100; // 0x400 slot 2: 100 reads as 72.0 V
  double max_acceleration = 0;  // m/s², at an acceleration scale of 16; 0: reaches any speed at once
  double pitch_degrees = 0;     // the balancing robot's lean
  geometry::Pose2 initial_pose;
  mobile_base::OdometryError odometry_error;
  const grid::OccupancyGrid* map = nullptr;
};

class SegwayRmpEmulator final : public DeviceEmulator {
 public:
  explicit SegwayRmpEmulator(SegwayRmpEmulatorOptions options = {});
  ~SegwayRmpEmulator() override;

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] std::optional<geometry::Pose2> world_pose() const override;

  // For tests and `--stats`.
  [[nodiscard]] bool channel_open() const { return open_; }
  [[nodiscard]] bool shut_down() const { return shut_down_; }
  [[nodiscard]] int bitrate() const { return bitrate_; }
  [[nodiscard]] double commanded_speed() const;       // m/s, after the watchdog
  [[nodiscard]] double commanded_turn_rate() const;   // rad/s
  [[nodiscard]] std::uint64_t commands() const { return commands_; }
  [[nodiscard]] std::uint64_t watchdog_stops() const { return watchdog_stops_; }
  [[nodiscard]] std::uint64_t status_sets() const { return status_sets_; }
  [[nodiscard]] const hardware::segwayrmp::Status& status() const { return status_; }
  [[nodiscard]] std::uint8_t scale(hardware::segwayrmp::StatusCommand which) const;

 private:
  void execute(const std::string& line);
  void take_frame(const framing::CanFrame& frame);
  void apply(const hardware::segwayrmp::Command& command);
  void move_to(Duration now);
  void send_status();
  void reply(const std::string& text);
  void set_target(double speed, double turn_rate);

  SegwayRmpEmulatorOptions options_;
  std::unique_ptr<mobile_base::DifferentialDrive> drive_;
  Duration now_{0};
  Duration next_status_{0};
  Duration last_command_{0};
  std::string typed_;
  std::vector<Telegram> output_;
  bool open_ = false;
  bool shut_down_ = false;
  int bitrate_ = 500000;
  // What 0x413 asked for, m/s and rad/s; the drive follows at the acceleration limit.
  double target_speed_ = 0;
  double target_turn_rate_ = 0;
  bool watchdog_stopped_ = false;
  std::uint8_t velocity_scale_ = 16;
  std::uint8_t acceleration_scale_ = 16;
  std::uint8_t turn_scale_ = 16;
  std::uint8_t gain_schedule_ = 0;
  std::uint8_t current_limit_ = 0;
  // Displacements as the encoders saw them since their last reset: m and rad.
  double fore_aft_ = 0;
  double yaw_ = 0;
  double left_wheel_ = 0;
  double right_wheel_ = 0;
  geometry::Pose2 last_odometry_;
  hardware::segwayrmp::Status status_;
  std::uint64_t commands_ = 0;
  std::uint64_t watchdog_stops_ = 0;
  std::uint64_t status_sets_ = 0;
};

}  // namespace playerkit::emulators
