#include "client/typed/pose.hpp"

#include "protocol/si_units.hpp"

namespace playerkit::client {

Pose2D planar_pose(const std::array<std::int16_t, 3>& wire) {
  using protocol::WireUnit;
  return {protocol::to_si(WireUnit::kMillimetre, wire[0]), protocol::to_si(WireUnit::kMillimetre, wire[1]),
          protocol::to_si(WireUnit::kDegree, wire[2])};
}

}  // namespace playerkit::client
