#pragma once
// The GET_GEOM answers of p2os_position and p2os_sonar (p2os.md §3.1, §3.2,
// §4.3), in SI for the interface adapters (lib/interfaces) and as the
// replies they make of them.

#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "families/p2os/protocol/robot_params.hpp"
#include "interfaces/position_requests.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::drivers::p2os {

// 1.5's answer for every robot: the centre of rotation 100 mm behind the
// body's centre, a 500 × 450 mm body.
interfaces::BaseGeometry base_geometry();
protocol::PositionGeom position_geometry();

// SonarNum poses (m, m, rad): the sheet's table, then zeros past it (1.5
// sent 32 entries read past its table there) and for the rows the sheet
// gives no poses for.
std::vector<geometry::Pose2> sonar_poses(const hardware::p2os::RobotParams& params);
protocol::SonarGeom sonar_geometry(const hardware::p2os::RobotParams& params);

}  // namespace playerkit::drivers::p2os
