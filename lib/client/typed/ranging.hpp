#pragma once
// Sonar and IR: ranges and sensor poses in SI units.

#include <cstdint>
#include <vector>

#include "client/typed/pose.hpp"
#include "protocol/messages/ir.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::client {

struct SonarScan {
  std::vector<double> ranges;  // m, one per transducer
};

struct IrScan {
  std::vector<double> ranges;           // m
  std::vector<std::uint16_t> voltages;  // raw, as on the wire (the spec gives no unit)
};

// Sensor poses in the robot frame (sonar get-geom, IR pose replies).
struct SensorPoses {
  std::vector<Pose2D> poses;
};

SonarScan to_si(const protocol::SonarData& data);
SensorPoses to_si(const protocol::SonarGeom& geom);
IrScan to_si(const protocol::IrData& data);
SensorPoses to_si(const protocol::IrPose& poses);
SensorPoses to_si(const protocol::IrPoseRequest& reply);

}  // namespace playerkit::client
