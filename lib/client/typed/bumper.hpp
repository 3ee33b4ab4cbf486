#pragma once
// Bumper states and geometry in SI units.

#include <vector>

#include "client/typed/pose.hpp"
#include "protocol/messages/bumper.hpp"

namespace playerkit::client {

struct BumperState {
  std::vector<bool> pressed;  // one per bumper
};

struct BumperDefinition {
  Pose2D pose;        // centre and orientation in the robot frame
  double length = 0;  // m
  double radius = 0;  // m of curvature; 0 = straight
};

BumperState to_si(const protocol::BumperData& data);
std::vector<BumperDefinition> to_si(const protocol::BumperGeom& geom);

}  // namespace playerkit::client
