#pragma once
// Player 1.5 `position3d` payloads: constants and packed structs, field for field
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

inline constexpr std::uint8_t kPosition3dGetGeomReq = 1;  // get geometry
inline constexpr std::uint8_t kPosition3dMotorPowerReq = 2;  // motors on/off
inline constexpr std::uint8_t kPosition3dVelocityModeReq = 3;  // velocity control scheme
inline constexpr std::uint8_t kPosition3dPositionModeReq = 5;  // velocity vs position control (note: value 5, no 4)

struct Position3dData {
  static constexpr std::string_view kWireName = "player_position3d_data_t";
  static constexpr std::size_t kWireSize = 49;

  std::int32_t xpos = 0;  // x, mm
  std::int32_t ypos = 0;  // y, mm
  std::int32_t zpos = 0;  // z, mm
  std::int32_t roll = 0;  // roll, arc-seconds
  std::int32_t pitch = 0;  // pitch, arc-seconds
  std::int32_t yaw = 0;  // yaw, arc-seconds
  std::int32_t xspeed = 0;  // x speed, mm/s
  std::int32_t yspeed = 0;  // y speed, mm/s
  std::int32_t zspeed = 0;  // z speed, mm/s
  std::int32_t rollspeed = 0;  // roll rate, arcsec/s
  std::int32_t pitchspeed = 0;  // pitch rate, arcsec/s
  std::int32_t yawspeed = 0;  // yaw rate, arcsec/s
  std::uint8_t stall = 0;  // non-zero when stalled

  static constexpr auto fields() {
    return std::tuple{field("xpos", &Position3dData::xpos),
                      field("ypos", &Position3dData::ypos),
                      field("zpos", &Position3dData::zpos),
                      field("roll", &Position3dData::roll),
                      field("pitch", &Position3dData::pitch),
                      field("yaw", &Position3dData::yaw),
                      field("xspeed", &Position3dData::xspeed),
                      field("yspeed", &Position3dData::yspeed),
                      field("zspeed", &Position3dData::zspeed),
                      field("rollspeed", &Position3dData::rollspeed),
                      field("pitchspeed", &Position3dData::pitchspeed),
                      field("yawspeed", &Position3dData::yawspeed),
                      field("stall", &Position3dData::stall)};
  }
  friend bool operator==(const Position3dData&, const Position3dData&) = default;
};

// Geometry/angles are declared uint32 in player.h, int32 in the data packet; same bits (wire-format.md §7).
struct Position3dCommand {
  static constexpr std::string_view kWireName = "player_position3d_cmd_t";
  static constexpr std::size_t kWireSize = 48;

  std::int32_t xpos = 0;  // x, mm
  std::int32_t ypos = 0;  // y, mm
  std::int32_t zpos = 0;  // z, mm
  std::int32_t roll = 0;  // roll, arc-seconds (declared unsigned here)
  std::int32_t pitch = 0;  // pitch, arc-seconds (unsigned)
  std::int32_t yaw = 0;  // yaw, arc-seconds (unsigned)
  std::int32_t xspeed = 0;  // x speed, mm/s
  std::int32_t yspeed = 0;  // y speed, mm/s
  std::int32_t zspeed = 0;  // z speed, mm/s
  std::int32_t rollspeed = 0;  // roll rate, arcsec/s
  std::int32_t pitchspeed = 0;  // pitch rate, arcsec/s
  std::int32_t yawspeed = 0;  // yaw rate, arcsec/s

  static constexpr auto fields() {
    return std::tuple{field("xpos", &Position3dCommand::xpos),
                      field("ypos", &Position3dCommand::ypos),
                      field("zpos", &Position3dCommand::zpos),
                      field("roll", &Position3dCommand::roll),
                      field("pitch", &Position3dCommand::pitch),
                      field("yaw", &Position3dCommand::yaw),
                      field("xspeed", &Position3dCommand::xspeed),
                      field("yspeed", &Position3dCommand::yspeed),
                      field("zspeed", &Position3dCommand::zspeed),
                      field("rollspeed", &Position3dCommand::rollspeed),
                      field("pitchspeed", &Position3dCommand::pitchspeed),
                      field("yawspeed", &Position3dCommand::yawspeed)};
  }
  friend bool operator==(const Position3dCommand&, const Position3dCommand&) = default;
};

struct Position3dPowerConfig {
  static constexpr std::string_view kWireName = "player_position3d_power_config_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint8_t request = 0;  // PLAYER_POSITION3D_MOTOR_POWER_REQ (2)
  std::uint8_t value = 0;  // 0 = off, 1 = on

  static constexpr auto fields() {
    return std::tuple{field("request", &Position3dPowerConfig::request),
                      field("value", &Position3dPowerConfig::value)};
  }
  friend bool operator==(const Position3dPowerConfig&, const Position3dPowerConfig&) = default;
};

}  // namespace playerkit::protocol
