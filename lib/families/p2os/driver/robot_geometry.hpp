#pragma once
// The GET_GEOM replies of p2os_position and p2os_sonar (p2os.md §3.1, §3.2,
// §4.3).

#include "families/p2os/protocol/robot_params.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::drivers::p2os {

// 1.5's answer for every robot: the centre of rotation 100 mm behind the
// body's centre, a 500 × 450 mm body.
protocol::PositionGeom position_geometry();

// pose_count = the row's SonarNum, the poses of the sheet's table, zeros
// after SonarNum (1.5 sent 32 entries read past its table there) and zeros
// for the rows the sheet gives no poses for.
protocol::SonarGeom sonar_geometry(const hardware::p2os::RobotParams& params);

}  // namespace playerkit::drivers::p2os
