#pragma once
// Player 1.5 `position` payloads: constants and packed structs, field for field
// as in wire-format.md §5 (names, order, sizes). Values are in wire units.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <tuple>
#include <vector>

#include "protocol/fields.hpp"
#include "protocol/fixed_string.hpp"

namespace playerkit::protocol {

inline constexpr std::uint8_t kPositionGetGeomReq = 1;  // get base geometry
inline constexpr std::uint8_t kPositionMotorPowerReq = 2;  // motors on/off
inline constexpr std::uint8_t kPositionVelocityModeReq = 3;  // select velocity control scheme
inline constexpr std::uint8_t kPositionResetOdomReq = 4;  // zero odometry
inline constexpr std::uint8_t kPositionPositionModeReq = 5;  // select velocity vs position control
inline constexpr std::uint8_t kPositionSpeedPidReq = 6;  // set speed PID gains
inline constexpr std::uint8_t kPositionPositionPidReq = 7;  // set position PID gains
inline constexpr std::uint8_t kPositionSpeedProfReq = 8;  // set speed/accel profile
inline constexpr std::uint8_t kPositionSetOdomReq = 9;  // set odometry to a pose
inline constexpr std::uint8_t kPositionRmpVelocityScale = 51;  // Segway RMP: velocity scale
inline constexpr std::uint8_t kPositionRmpAccelScale = 52;  // Segway RMP: acceleration scale
inline constexpr std::uint8_t kPositionRmpTurnScale = 53;  // Segway RMP: turn scale
inline constexpr std::uint8_t kPositionRmpGainSchedule = 54;  // Segway RMP: gain schedule
inline constexpr std::uint8_t kPositionRmpCurrentLimit = 55;  // Segway RMP: current limit
inline constexpr std::uint8_t kPositionRmpRstIntegrators = 56;  // Segway RMP: reset integrators (value = bit mask below)
inline constexpr std::uint8_t kPositionRmpShutdown = 57;  // Segway RMP: shut down
inline constexpr std::uint16_t kPositionRmpRstIntRight = 1;  // integrator mask bit: right wheel
inline constexpr std::uint16_t kPositionRmpRstIntLeft = 2;  // mask bit: left wheel
inline constexpr std::uint16_t kPositionRmpRstIntYaw = 4;  // mask bit: yaw
inline constexpr std::uint16_t kPositionRmpRstIntForeaft = 8;  // mask bit: fore/aft

struct PositionData {
  static constexpr std::string_view kWireName = "player_position_data_t";
  static constexpr std::size_t kWireSize = 25;

  std::int32_t xpos = 0;  // odometric x, mm
  std::int32_t ypos = 0;  // odometric y, mm
  std::int32_t yaw = 0;  // heading, degrees
  std::int32_t xspeed = 0;  // forward speed, mm/s
  std::int32_t yspeed = 0;  // sideways speed, mm/s
  std::int32_t yawspeed = 0;  // turn rate, deg/s
  std::uint8_t stall = 0;  // non-zero when motors are stalled

  static constexpr auto fields() {
    return std::tuple{field("xpos", &PositionData::xpos),
                      field("ypos", &PositionData::ypos),
                      field("yaw", &PositionData::yaw),
                      field("xspeed", &PositionData::xspeed),
                      field("yspeed", &PositionData::yspeed),
                      field("yawspeed", &PositionData::yawspeed),
                      field("stall", &PositionData::stall)};
  }
  friend bool operator==(const PositionData&, const PositionData&) = default;
};

struct PositionCommand {
  static constexpr std::string_view kWireName = "player_position_cmd_t";
  static constexpr std::size_t kWireSize = 26;

  std::int32_t xpos = 0;  // target x, mm (position mode)
  std::int32_t ypos = 0;  // target y, mm
  std::int32_t yaw = 0;  // target heading, degrees
  std::int32_t xspeed = 0;  // forward speed, mm/s
  std::int32_t yspeed = 0;  // sideways speed, mm/s
  std::int32_t yawspeed = 0;  // turn rate, deg/s
  std::uint8_t state = 0;  // motor enable (0 = off/locked, driver specific)
  std::uint8_t type = 0;  // 0 = velocity command, 1 = position command

  static constexpr auto fields() {
    return std::tuple{field("xpos", &PositionCommand::xpos),
                      field("ypos", &PositionCommand::ypos),
                      field("yaw", &PositionCommand::yaw),
                      field("xspeed", &PositionCommand::xspeed),
                      field("yspeed", &PositionCommand::yspeed),
                      field("yawspeed", &PositionCommand::yawspeed),
                      field("state", &PositionCommand::state),
                      field("type", &PositionCommand::type)};
  }
  friend bool operator==(const PositionCommand&, const PositionCommand&) = default;
};

// Geometry/angles are declared uint16 in player.h, but carries a signed offset and yaw; same bits (wire-format.md §7).
struct PositionGeom {
  static constexpr std::string_view kWireName = "player_position_geom_t";
  static constexpr std::size_t kWireSize = 11;

  std::uint8_t subtype = 0;  // PLAYER_POSITION_GET_GEOM_REQ (1)
  std::array<std::int16_t, 3> pose{};  // base pose in robot frame: x mm, y mm, yaw deg (declared unsigned)
  std::array<std::uint16_t, 2> size{};  // base footprint: length mm, width mm

  static constexpr auto fields() {
    return std::tuple{field("subtype", &PositionGeom::subtype),
                      field("pose", &PositionGeom::pose),
                      field("size", &PositionGeom::size)};
  }
  friend bool operator==(const PositionGeom&, const PositionGeom&) = default;
};

struct PositionPowerConfig {
  static constexpr std::string_view kWireName = "player_position_power_config_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint8_t request = 0;  // PLAYER_POSITION_MOTOR_POWER_REQ (2)
  std::uint8_t value = 0;  // 0 = motors off, 1 = on

  static constexpr auto fields() {
    return std::tuple{field("request", &PositionPowerConfig::request),
                      field("value", &PositionPowerConfig::value)};
  }
  friend bool operator==(const PositionPowerConfig&, const PositionPowerConfig&) = default;
};

struct PositionVelocityModeConfig {
  static constexpr std::string_view kWireName = "player_position_velocitymode_config_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint8_t request = 0;  // PLAYER_POSITION_VELOCITY_MODE_REQ (3)
  std::uint8_t value = 0;  // driver-specific velocity control mode

  static constexpr auto fields() {
    return std::tuple{field("request", &PositionVelocityModeConfig::request),
                      field("value", &PositionVelocityModeConfig::value)};
  }
  friend bool operator==(const PositionVelocityModeConfig&, const PositionVelocityModeConfig&) = default;
};

struct PositionResetOdomConfig {
  static constexpr std::string_view kWireName = "player_position_resetodom_config_t";
  static constexpr std::size_t kWireSize = 1;

  std::uint8_t request = 0;  // PLAYER_POSITION_RESET_ODOM_REQ (4)

  static constexpr auto fields() {
    return std::tuple{field("request", &PositionResetOdomConfig::request)};
  }
  friend bool operator==(const PositionResetOdomConfig&, const PositionResetOdomConfig&) = default;
};

struct PositionPositionModeRequest {
  static constexpr std::string_view kWireName = "player_position_position_mode_req_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint8_t subtype = 0;  // PLAYER_POSITION_POSITION_MODE_REQ (5)
  std::uint8_t state = 0;  // 0 = velocity mode, 1 = position mode

  static constexpr auto fields() {
    return std::tuple{field("subtype", &PositionPositionModeRequest::subtype),
                      field("state", &PositionPositionModeRequest::state)};
  }
  friend bool operator==(const PositionPositionModeRequest&, const PositionPositionModeRequest&) = default;
};

struct PositionSetOdomRequest {
  static constexpr std::string_view kWireName = "player_position_set_odom_req_t";
  static constexpr std::size_t kWireSize = 13;

  std::uint8_t subtype = 0;  // PLAYER_POSITION_SET_ODOM_REQ (9)
  std::int32_t x = 0;  // new odometric x, mm
  std::int32_t y = 0;  // new odometric y, mm
  std::int32_t theta = 0;  // new heading, degrees

  static constexpr auto fields() {
    return std::tuple{field("subtype", &PositionSetOdomRequest::subtype),
                      field("x", &PositionSetOdomRequest::x),
                      field("y", &PositionSetOdomRequest::y),
                      field("theta", &PositionSetOdomRequest::theta)};
  }
  friend bool operator==(const PositionSetOdomRequest&, const PositionSetOdomRequest&) = default;
};

struct PositionSpeedPidRequest {
  static constexpr std::string_view kWireName = "player_position_speed_pid_req_t";
  static constexpr std::size_t kWireSize = 13;

  std::uint8_t subtype = 0;  // PLAYER_POSITION_SPEED_PID_REQ (6)
  std::int32_t kp = 0;  // proportional gain (driver units)
  std::int32_t ki = 0;  // integral gain
  std::int32_t kd = 0;  // derivative gain

  static constexpr auto fields() {
    return std::tuple{field("subtype", &PositionSpeedPidRequest::subtype),
                      field("kp", &PositionSpeedPidRequest::kp),
                      field("ki", &PositionSpeedPidRequest::ki),
                      field("kd", &PositionSpeedPidRequest::kd)};
  }
  friend bool operator==(const PositionSpeedPidRequest&, const PositionSpeedPidRequest&) = default;
};

struct PositionPositionPidRequest {
  static constexpr std::string_view kWireName = "player_position_position_pid_req_t";
  static constexpr std::size_t kWireSize = 13;

  std::uint8_t subtype = 0;  // PLAYER_POSITION_POSITION_PID_REQ (7)
  std::int32_t kp = 0;  // proportional gain (driver units)
  std::int32_t ki = 0;  // integral gain
  std::int32_t kd = 0;  // derivative gain

  static constexpr auto fields() {
    return std::tuple{field("subtype", &PositionPositionPidRequest::subtype),
                      field("kp", &PositionPositionPidRequest::kp),
                      field("ki", &PositionPositionPidRequest::ki),
                      field("kd", &PositionPositionPidRequest::kd)};
  }
  friend bool operator==(const PositionPositionPidRequest&, const PositionPositionPidRequest&) = default;
};

struct PositionSpeedProfRequest {
  static constexpr std::string_view kWireName = "player_position_speed_prof_req_t";
  static constexpr std::size_t kWireSize = 5;

  std::uint8_t subtype = 0;  // PLAYER_POSITION_SPEED_PROF_REQ (8)
  std::int16_t speed = 0;  // maximum speed (driver units, mm/s on P2OS)
  std::int16_t acc = 0;  // maximum acceleration (driver units)

  static constexpr auto fields() {
    return std::tuple{field("subtype", &PositionSpeedProfRequest::subtype),
                      field("speed", &PositionSpeedProfRequest::speed),
                      field("acc", &PositionSpeedProfRequest::acc)};
  }
  friend bool operator==(const PositionSpeedProfRequest&, const PositionSpeedProfRequest&) = default;
};

struct RmpConfig {
  static constexpr std::string_view kWireName = "player_rmp_config_t";
  static constexpr std::size_t kWireSize = 3;

  std::uint8_t subtype = 0;  // one of PLAYER_POSITION_RMP_* (51..57)
  std::uint16_t value = 0;  // argument for that RMP setting

  static constexpr auto fields() {
    return std::tuple{field("subtype", &RmpConfig::subtype),
                      field("value", &RmpConfig::value)};
  }
  friend bool operator==(const RmpConfig&, const RmpConfig&) = default;
};

}  // namespace playerkit::protocol
