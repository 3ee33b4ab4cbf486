#include "interfaces/position_requests.hpp"

#include "interfaces/wire_units.hpp"
#include "protocol/binary_codec.hpp"

namespace playerkit::interfaces {

namespace {

// The struct T, when the payload is exactly its size.
template <class T>
std::optional<PositionRequest> decode_exact_size(std::span<const std::uint8_t> payload) {
  if (payload.size() != T::kWireSize) return std::nullopt;
  return protocol::decode<T>(payload);
}

// One visitor per request kind: what the base is asked, and the reply.
struct PositionDispatch {
  PositionBase& base;

  static core::RequestResult done(bool accepted) {
    return accepted ? core::RequestResult::ack() : core::RequestResult::nack();
  }

  core::RequestResult operator()(const GeometryQuery&) const {
    const std::optional<BaseGeometry> geometry = base.geometry();
    if (!geometry) return core::RequestResult::nack();
    return core::RequestResult::ack(protocol::encode(position_geometry_reply(*geometry)));
  }
  core::RequestResult operator()(const protocol::PositionPowerConfig& power) const {
    return done(base.set_motor_power(power.value != 0));
  }
  core::RequestResult operator()(const protocol::PositionVelocityModeConfig& mode) const {
    return done(base.set_velocity_mode(mode.value));
  }
  core::RequestResult operator()(const protocol::PositionResetOdomConfig&) const {
    return done(base.reset_odometry());
  }
  core::RequestResult operator()(const protocol::PositionPositionModeRequest& mode) const {
    return done(base.set_position_mode(mode.state != 0));
  }
  core::RequestResult operator()(const protocol::PositionSpeedPidRequest& pid) const {
    return done(base.set_speed_pid({pid.kp, pid.ki, pid.kd}));
  }
  core::RequestResult operator()(const protocol::PositionPositionPidRequest& pid) const {
    return done(base.set_position_pid({pid.kp, pid.ki, pid.kd}));
  }
  core::RequestResult operator()(const protocol::PositionSpeedProfRequest& profile) const {
    return done(base.set_speed_profile({profile.speed, profile.acc}));
  }
  core::RequestResult operator()(const protocol::PositionSetOdomRequest& pose) const {
    // The whole theta (1.5's p2os used its upper 16 bits, p2os.md quirk 6).
    return done(base.set_odometry({pose.x / kMillimetresPerMetre, pose.y / kMillimetresPerMetre,
                                   geometry::normalize_angle(radians(pose.theta))}));
  }
  core::RequestResult operator()(const protocol::RmpConfig& setting) const {
    return done(base.rmp_setting(setting.subtype, setting.value));
  }
};

}  // namespace

std::optional<PositionRequest> decode_position_request(std::span<const std::uint8_t> payload) {
  if (payload.empty()) return std::nullopt;
  switch (payload.front()) {
    case protocol::kPositionGetGeomReq:
      if (payload.size() != 1) return std::nullopt;
      return GeometryQuery{};
    case protocol::kPositionMotorPowerReq: return decode_exact_size<protocol::PositionPowerConfig>(payload);
    case protocol::kPositionVelocityModeReq: return decode_exact_size<protocol::PositionVelocityModeConfig>(payload);
    case protocol::kPositionResetOdomReq: return decode_exact_size<protocol::PositionResetOdomConfig>(payload);
    case protocol::kPositionPositionModeReq: return decode_exact_size<protocol::PositionPositionModeRequest>(payload);
    case protocol::kPositionSpeedPidReq: return decode_exact_size<protocol::PositionSpeedPidRequest>(payload);
    case protocol::kPositionPositionPidReq: return decode_exact_size<protocol::PositionPositionPidRequest>(payload);
    case protocol::kPositionSpeedProfReq: return decode_exact_size<protocol::PositionSpeedProfRequest>(payload);
    case protocol::kPositionSetOdomReq: return decode_exact_size<protocol::PositionSetOdomRequest>(payload);
    case protocol::kPositionRmpVelocityScale:
    case protocol::kPositionRmpAccelScale:
    case protocol::kPositionRmpTurnScale:
    case protocol::kPositionRmpGainSchedule:
    case protocol::kPositionRmpCurrentLimit:
    case protocol::kPositionRmpRstIntegrators:
    case protocol::kPositionRmpShutdown: return decode_exact_size<protocol::RmpConfig>(payload);
    default: return std::nullopt;
  }
}

protocol::PositionGeom position_geometry_reply(const BaseGeometry& geometry) {
  protocol::PositionGeom reply;
  reply.subtype = protocol::kPositionGetGeomReq;
  reply.pose = {wire_value<std::int16_t>(geometry.pose.x * kMillimetresPerMetre),
                wire_value<std::int16_t>(geometry.pose.y * kMillimetresPerMetre),
                wire_value<std::int16_t>(degrees(geometry.pose.yaw))};
  reply.size = {wire_value<std::uint16_t>(geometry.length * kMillimetresPerMetre),
                wire_value<std::uint16_t>(geometry.width * kMillimetresPerMetre)};
  return reply;
}

core::RequestResult answer_position_request(PositionBase& base, const core::Request& request) {
  const std::optional<PositionRequest> decoded = decode_position_request(request.payload);
  if (!decoded) return core::RequestResult::nack();
  return std::visit(PositionDispatch{base}, *decoded);
}

}  // namespace playerkit::interfaces
