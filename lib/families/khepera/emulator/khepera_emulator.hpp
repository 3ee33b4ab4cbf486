#pragma once
// An emulated K-Team Khepera, written from khepera.md §6 ("what a faithful
// emulator must do"), so that Player 1.5's khepera drivers work against it
// unmodified:
//
//  * commands are lines ended by LF (CR and empty lines tolerated: the
//    start-up CR LF gets no answer); each is answered at once with one line
//    `<lower-case letter>[,v...]` CR LF;
//  * two wheel speeds in pulses per 10 ms (D sets, E reads), limited to the
//    BIOS's +-127, and two 32-bit position counters (G sets, H reads) to
//    which the wheels add every 10 ms what they turned;
//  * N: one proximity reading per sensor, 1..1023 (never 0), brighter the
//    nearer an occupied cell of the map lies along the sensor's axis;
//  * the body (lib/emulators/mobile_base): the commanded wheel speeds drive
//    a true pose in the map, stalling against its walls, and the counters
//    see the motion through the configured odometry error;
//  * it listens at 38400 baud only (bytes at another speed are noise);
//  * unknown commands and malformed arguments get no answer (the sheet
//    names none).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "algorithms/grid/occupancy_grid.hpp"
#include "emulators/device_emulator.hpp"
#include "emulators/mobile_base/differential_drive.hpp"
#include "emulators/mobile_base/range_ring.hpp"
#include "families/khepera/protocol/khepera_commands.hpp"
#include "families/khepera/protocol/khepera_units.hpp"

namespace playerkit::emulators {

struct KheperaEmulatorOptions {
  // 12 pulses a millimetre, and the wheel distance 1.5's configuration
  // assumes (its default size, 57 mm).
  hardware::khepera::WheelGeometry wheels{};
  double footprint_radius = 0.0285;  // m: a Khepera is 57 mm across
  // Sensor poses on the robot, m and rad; empty: the sheet's eight.
  std::vector<geometry::Pose2> ir_poses;
  // How readings follow distance; the sheet's calibration, so a driver
  // using it reads the distance back.
  hardware::khepera::IrCalibration ir_calibration{};
  geometry::Pose2 initial_pose{};
  mobile_base::OdometryError odometry_error{};
  // Not owned; may be null (open space: every reading 1).
  const grid::OccupancyGrid* map = nullptr;
  // 0: any line speed.
  int model_baud = 38400;
};

class KheperaEmulator final : public DeviceEmulator {
 public:
  explicit KheperaEmulator(KheperaEmulatorOptions options = {});

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  [[nodiscard]] int baud() const override { return options_.model_baud; }
  [[nodiscard]] std::optional<geometry::Pose2> world_pose() const override { return drive_.true_pose(); }
  [[nodiscard]] std::string describe() const override;

  // For tests.
  [[nodiscard]] const hardware::khepera::WheelSpeeds& speeds() const { return speeds_; }
  [[nodiscard]] std::int64_t left_counter() const;
  [[nodiscard]] std::int64_t right_counter() const;
  [[nodiscard]] std::vector<std::int64_t> proximity() const;
  [[nodiscard]] const geometry::Pose2& true_pose() const { return drive_.true_pose(); }
  [[nodiscard]] std::uint64_t commands() const { return commands_; }
  [[nodiscard]] std::uint64_t set_speed_commands() const { return set_speed_commands_; }

 private:
  void execute(std::string_view line);
  // The answer's values, or nothing when the command gets no answer.
  std::optional<std::vector<std::int64_t>> answer(const hardware::khepera::Message& command);
  void tick();

  KheperaEmulatorOptions options_;
  mobile_base::DifferentialDrive drive_;
  mobile_base::RangeRing ring_;
  hardware::khepera::WheelSpeeds speeds_;
  // Pulses turned since the counters were last set, fractional (odometry
  // error makes them so); the counters report them rounded.
  double left_pulses_ = 0.0;
  double right_pulses_ = 0.0;
  std::int64_t left_origin_ = 0;
  std::int64_t right_origin_ = 0;
  std::string typed_;
  Duration next_tick_{0};
  std::vector<Telegram> output_;
  std::uint64_t commands_ = 0;
  std::uint64_t set_speed_commands_ = 0;
};

}  // namespace playerkit::emulators
