#include "interfaces/ranger_requests.hpp"

#include "interfaces/ranger_geometry.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/ir.hpp"
#include "protocol/messages/sonar.hpp"

namespace playerkit::interfaces {

namespace {

// POWER: the subtype and one byte, 0 off and anything else on, for both.
core::RequestResult answer_power(RangerArray& sensors, const core::Request& request) {
  if (request.payload.size() != 2) return core::RequestResult::nack();
  return sensors.set_power(request.payload[1] != 0) ? core::RequestResult::ack() : core::RequestResult::nack();
}

}  // namespace

core::RequestResult answer_sonar_request(RangerArray& sonar, const core::Request& request) {
  static_assert(protocol::SonarPowerConfig::kWireSize == 2);
  switch (request.subtype()) {
    case protocol::kSonarGetGeomReq: {
      if (request.payload.size() != 1) break;
      const auto poses = sonar.sensor_poses();
      if (!poses) break;
      return core::RequestResult::ack(protocol::encode(sonar_geometry_reply(*poses)));
    }
    case protocol::kSonarPowerReq: return answer_power(sonar, request);
    default: break;
  }
  return core::RequestResult::nack();
}

core::RequestResult answer_ir_request(RangerArray& ir, const core::Request& request) {
  static_assert(protocol::IrPowerRequest::kWireSize == 2);
  switch (request.subtype()) {
    case protocol::kIrPoseReq: {
      if (request.payload.size() != 1) break;
      const auto poses = ir.sensor_poses();
      if (!poses) break;
      return core::RequestResult::ack(protocol::encode(ir_pose_reply(*poses)));
    }
    case protocol::kIrPowerReq: return answer_power(ir, request);
    default: break;
  }
  return core::RequestResult::nack();
}

}  // namespace playerkit::interfaces
