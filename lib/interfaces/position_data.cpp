#include "interfaces/position_data.hpp"

namespace playerkit::interfaces {

protocol::PositionData position_data(const geometry::Pose2& pose, const geometry::Pose2& velocity, bool stalled,
                                     HeadingRange heading_range) {
  protocol::PositionData data;
  data.xpos = wire_value<std::int32_t>(pose.x * kMillimetresPerMetre);
  data.ypos = wire_value<std::int32_t>(pose.y * kMillimetresPerMetre);
  data.yaw = heading_degrees(pose.yaw, heading_range);
  data.xspeed = wire_value<std::int32_t>(velocity.x * kMillimetresPerMetre);
  data.yspeed = wire_value<std::int32_t>(velocity.y * kMillimetresPerMetre);
  data.yawspeed = wire_value<std::int32_t>(degrees(velocity.yaw));
  data.stall = stalled ? 1 : 0;
  return data;
}

}  // namespace playerkit::interfaces
