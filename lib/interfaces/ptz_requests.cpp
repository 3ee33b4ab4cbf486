#include "interfaces/ptz_requests.hpp"

#include "protocol/binary_codec.hpp"
#include "protocol/errors.hpp"

namespace playerkit::interfaces {

core::RequestResult answer_ptz_request(PtzHead& head, const core::Request& request) {
  const auto& payload = request.payload;
  switch (request.subtype()) {
    case protocol::kPtzControlModeReq:
      if (payload.size() != protocol::PtzVelocityModeConfig::kWireSize) break;
      return head.set_control_mode(payload[1]) ? core::RequestResult::ack() : core::RequestResult::nack();
    case protocol::kPtzGenericConfigReq: {
      if (payload.size() != protocol::PtzGenericConfig::kWireSize) break;
      protocol::PtzGenericConfig command;
      try {
        command = protocol::decode<protocol::PtzGenericConfig>(payload);
      } catch (const protocol::DecodeError&) {
        break;  // a length over the 32 bytes there are
      }
      const auto reply = head.generic_config(command);
      if (!reply) break;
      return core::RequestResult::ack(protocol::encode(*reply));
    }
    default: break;
  }
  return core::RequestResult::nack();
}

}  // namespace playerkit::interfaces
