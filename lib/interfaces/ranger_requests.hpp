#pragma once
// The sonar and ir interfaces' requests (wire-format.md §5), answered once
// for every ring of sensors: GET_GEOM (the subtype alone) with the poses,
// POWER (the 2-byte struct). A payload of any other size, an unknown
// subtype, or a request the device declines is NACKed; POWER's ACK is empty.

#include <optional>
#include <vector>

#include "algorithms/geometry/pose2.hpp"
#include "core/exchange.hpp"

namespace playerkit::interfaces {

// A sonar ring or an IR array. The defaults decline.
class RangerArray {
 public:
  virtual ~RangerArray() = default;

  // Each sensor's pose on the robot (m, m, rad); nothing: GET_GEOM is NACKed.
  [[nodiscard]] virtual std::optional<std::vector<geometry::Pose2>> sensor_poses() { return std::nullopt; }
  virtual bool set_power(bool /*on*/) { return false; }
};

[[nodiscard]] core::RequestResult answer_sonar_request(RangerArray& sonar, const core::Request& request);
[[nodiscard]] core::RequestResult answer_ir_request(RangerArray& ir, const core::Request& request);

}  // namespace playerkit::interfaces
