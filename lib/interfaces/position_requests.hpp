#pragma once
// The position interface's requests (wire-format.md §5 "position", manual
// §6.19), decoded and answered once for every mobile base: a driver
// implements PositionBase and hands each request to
// answer_position_request().
//
// Every subtype of Player 1.5 is decoded, including the PID, speed-profile
// and Segway RMP ones no base of 1.5's p2os or Stage answered. A payload
// must be exactly its struct's size, as p2os checked in 1.5 (p2os.md §3.1;
// GET_GEOM is the subtype alone); anything else, an unknown subtype, or a
// request the base declines is NACKed. GET_GEOM is answered with the
// 11-byte player_position_geom_t, every other request with an empty ACK.

#include <cstdint>
#include <optional>
#include <span>
#include <variant>

#include "algorithms/geometry/pose2.hpp"
#include "core/exchange.hpp"
#include "protocol/messages/position.hpp"

namespace playerkit::interfaces {

// Where the base's body is and how big it is, in SI units.
struct BaseGeometry {
  geometry::Pose2 pose;  // the body's centre in the robot's frame: m, m, rad
  double length = 0.0;   // m
  double width = 0.0;    // m
};

// GET_GEOM carries nothing but its subtype.
struct GeometryQuery {
  friend bool operator==(const GeometryQuery&, const GeometryQuery&) = default;
};

using PositionRequest =
    std::variant<GeometryQuery, protocol::PositionPowerConfig, protocol::PositionVelocityModeConfig,
                 protocol::PositionResetOdomConfig, protocol::PositionPositionModeRequest,
                 protocol::PositionSpeedPidRequest, protocol::PositionPositionPidRequest,
                 protocol::PositionSpeedProfRequest, protocol::PositionSetOdomRequest, protocol::RmpConfig>;

// The request a payload holds; nothing for an unknown subtype or a payload
// that is not exactly its struct's size.
[[nodiscard]] std::optional<PositionRequest> decode_position_request(std::span<const std::uint8_t> payload);

// Gains and profile values are the driver's own units (1.5 defined none).
struct PidGains {
  std::int32_t kp = 0;
  std::int32_t ki = 0;
  std::int32_t kd = 0;
};
struct SpeedProfile {
  std::int16_t speed = 0;         // mm/s on P2OS
  std::int16_t acceleration = 0;  // mm/s² on P2OS
};

// What a base does with each request. Every method answers whether it was
// done; the defaults decline (NACK), so a base overrides what it supports.
// A base that cannot reach its hardware right now declines too.
class PositionBase {
 public:
  virtual ~PositionBase() = default;

  // Nothing: GET_GEOM is NACKed.
  [[nodiscard]] virtual std::optional<BaseGeometry> geometry() { return std::nullopt; }
  virtual bool set_motor_power(bool /*on*/) { return false; }
  // The mode value is the driver's (p2os: 0 direct wheel, other separate).
  virtual bool set_velocity_mode(std::uint8_t /*mode*/) { return false; }
  // The reported pose becomes (0, 0, 0).
  virtual bool reset_odometry() { return false; }
  // The reported pose becomes `pose` (m, m, rad; theta taken whole).
  virtual bool set_odometry(const geometry::Pose2& /*pose*/) { return false; }
  virtual bool set_position_mode(bool /*position_control*/) { return false; }
  virtual bool set_speed_pid(const PidGains& /*gains*/) { return false; }
  virtual bool set_position_pid(const PidGains& /*gains*/) { return false; }
  virtual bool set_speed_profile(const SpeedProfile& /*profile*/) { return false; }
  // One of the Segway RMP settings (subtypes 51..57) and its argument.
  virtual bool rmp_setting(std::uint8_t /*subtype*/, std::uint16_t /*value*/) { return false; }
};

// GET_GEOM's reply: pose in mm, mm, degrees, size in mm, rounded and clamped.
[[nodiscard]] protocol::PositionGeom position_geometry_reply(const BaseGeometry& geometry);

[[nodiscard]] core::RequestResult answer_position_request(PositionBase& base, const core::Request& request);

}  // namespace playerkit::interfaces
