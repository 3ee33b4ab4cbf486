#pragma once
// Player 1.5 `ptz` payloads: constants and packed structs, field for field
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

inline constexpr std::uint8_t kPtzGenericConfigReq = 1;  // raw unit-specific command
inline constexpr std::uint8_t kPtzControlModeReq = 2;  // select velocity/position control
inline constexpr std::size_t kPtzMaxConfigLen = 32;  // capacity of generic config buffer
inline constexpr std::uint8_t kPtzVelocityControl = 0;  // control mode value: velocity
inline constexpr std::uint8_t kPtzPositionControl = 1;  // control mode value: position

struct PtzData {
  static constexpr std::string_view kWireName = "player_ptz_data_t";
  static constexpr std::size_t kWireSize = 10;

  std::int16_t pan = 0;  // pan, degrees
  std::int16_t tilt = 0;  // tilt, degrees
  std::int16_t zoom = 0;  // field of view, degrees
  std::int16_t panspeed = 0;  // pan rate, deg/s
  std::int16_t tiltspeed = 0;  // tilt rate, deg/s

  static constexpr auto fields() {
    return std::tuple{field("pan", &PtzData::pan),
                      field("tilt", &PtzData::tilt),
                      field("zoom", &PtzData::zoom),
                      field("panspeed", &PtzData::panspeed),
                      field("tiltspeed", &PtzData::tiltspeed)};
  }
  friend bool operator==(const PtzData&, const PtzData&) = default;
};

struct PtzCommand {
  static constexpr std::string_view kWireName = "player_ptz_cmd_t";
  static constexpr std::size_t kWireSize = 10;

  std::int16_t pan = 0;  // desired pan, degrees (absolute)
  std::int16_t tilt = 0;  // desired tilt, degrees
  std::int16_t zoom = 0;  // desired field of view, degrees
  std::int16_t panspeed = 0;  // pan rate, deg/s
  std::int16_t tiltspeed = 0;  // tilt rate, deg/s

  static constexpr auto fields() {
    return std::tuple{field("pan", &PtzCommand::pan),
                      field("tilt", &PtzCommand::tilt),
                      field("zoom", &PtzCommand::zoom),
                      field("panspeed", &PtzCommand::panspeed),
                      field("tiltspeed", &PtzCommand::tiltspeed)};
  }
  friend bool operator==(const PtzCommand&, const PtzCommand&) = default;
};

struct PtzGenericConfig {
  static constexpr std::string_view kWireName = "player_ptz_generic_config_t";
  static constexpr std::size_t kWireSize = 35;

  std::uint8_t subtype = 0;  // PLAYER_PTZ_GENERIC_CONFIG_REQ (1)
  std::uint16_t length = 0;  // bytes used in config[]
  std::array<std::uint8_t, 32> config{};  // raw unit-specific command/reply bytes

  static constexpr auto fields() {
    return std::tuple{field("subtype", &PtzGenericConfig::subtype),
                      field("length", &PtzGenericConfig::length),
                      counted("config", &PtzGenericConfig::config, &PtzGenericConfig::length)};
  }
  friend bool operator==(const PtzGenericConfig&, const PtzGenericConfig&) = default;
};

struct PtzVelocityModeConfig {
  static constexpr std::string_view kWireName = "player_ptz_velocitymode_config_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint8_t subtype = 0;  // PLAYER_PTZ_CONTROL_MODE_REQ (2)
  std::uint8_t mode = 0;  // PLAYER_PTZ_VELOCITY_CONTROL (0) or _POSITION_CONTROL (1)

  static constexpr auto fields() {
    return std::tuple{field("subtype", &PtzVelocityModeConfig::subtype),
                      field("mode", &PtzVelocityModeConfig::mode)};
  }
  friend bool operator==(const PtzVelocityModeConfig&, const PtzVelocityModeConfig&) = default;
};

}  // namespace playerkit::protocol
