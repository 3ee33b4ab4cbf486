#pragma once
// The options of khepera_position and khepera_ir (khepera.md §4, manual
// §7.21), declared once in schemas that the reader, `player-serve --check`,
// `player-drivers info` and the README's table all use.
//
// The robot's options (port, scale_factor, and playerkit's timing) may be
// written on either section, as 1.5 read them from the first khepera
// section it met; two sections that disagree are an error at the second.
// Lengths are millimetres and angles degrees, as 1.5 read them (plain
// numbers, not the file's units).

#include <chrono>
#include <string>
#include <string_view>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "core/driver_registry.hpp"
#include "core/option_schema.hpp"
#include "families/khepera/protocol/khepera_units.hpp"

namespace playerkit::drivers::khepera {

inline constexpr std::string_view kDefaultKheperaPort = "/dev/ttyUSB0";
inline constexpr int kKheperaBaud = 38400;
inline constexpr std::string_view kPositionDriver = "khepera_position";
inline constexpr std::string_view kIrDriver = "khepera_ir";

struct KheperaRobotOptions {
  std::string port{kDefaultKheperaPort};
  // Geometry (GET_GEOM, the IR poses) and IR ranges are multiplied by this,
  // as in 1.5, so that the tiny robot shows at a useful size; odometry never.
  double scale = 10.0;
  std::chrono::milliseconds reply_timeout{200};
  std::chrono::milliseconds cycle{50};
  std::chrono::milliseconds connect_timeout{2000};

  friend bool operator==(const KheperaRobotOptions&, const KheperaRobotOptions&) = default;
};

struct KheperaPositionOptions {
  hardware::khepera::WheelGeometry wheels;  // encoder_res; the wheelbase is size's x
  geometry::Pose2 pose;                     // mm, mm, rad: GET_GEOM's pose before scaling
  double length_mm = 57.0;
  double width_mm = 57.0;
};

struct KheperaIrSensor {
  geometry::Pose2 pose;  // mm, mm, rad, before scaling
  hardware::khepera::IrCalibration calibration;
};

struct KheperaIrOptions {
  std::vector<KheperaIrSensor> sensors;
};

const core::OptionSchema& khepera_robot_schema();
const core::OptionSchema& khepera_position_schema();
const core::OptionSchema& khepera_ir_schema();

// Throw config::ConfigError at the offending value.
KheperaRobotOptions read_khepera_robot_options(const core::DriverContext& context);
KheperaPositionOptions read_khepera_position_options(const core::DriverContext& context);
KheperaIrOptions read_khepera_ir_options(const core::DriverContext& context);

// The sheet's eight sensors (khepera.md §3.4), in mm, mm, degrees.
std::vector<KheperaIrSensor> default_ir_sensors();

// "khepera /dev/ttyUSB0": the key of the robot's shared connection.
std::string connection_key(const KheperaRobotOptions& options);

}  // namespace playerkit::drivers::khepera
