#pragma once
// Player 1.5 `nomad` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kNomadSonarCount = 16;  // Nomad sonar count
inline constexpr std::size_t kNomadBumperCount = 16;  // Nomad bumper count
inline constexpr std::size_t kNomadIrCount = 16;  // Nomad IR count
inline constexpr int kNomadRadiusMm = 400;  // Nomad radius, mm (driver constant)
inline constexpr std::size_t kNomadConfigBufferSize = 256;  // driver buffer size
inline constexpr std::string_view kNomadSerialPort = "/dev/ttyS0";  // default serial device
inline constexpr int kNomadSerialBaud = 9600;  // default baud rate

struct NomadData {
  static constexpr std::string_view kWireName = "player_nomad_data_t";
  static constexpr std::size_t kWireSize = 104;

  std::int32_t x = 0;  // x, mm
  std::int32_t y = 0;  // y, mm
  std::int32_t a = 0;  // heading, degrees
  std::int32_t vel_trans = 0;  // translational velocity (units unspecified)
  std::int32_t vel_steer = 0;  // steering velocity
  std::int32_t vel_turret = 0;  // turret velocity
  std::array<std::uint16_t, 16> sonar{};  // 16 sonar ranges, mm
  std::array<std::uint16_t, 16> ir{};  // 16 IR ranges, mm
  std::array<std::uint8_t, 16> bumper{};  // 16 bumper flags

  static constexpr auto fields() {
    return std::tuple{field("x", &NomadData::x),
                      field("y", &NomadData::y),
                      field("a", &NomadData::a),
                      field("vel_trans", &NomadData::vel_trans),
                      field("vel_steer", &NomadData::vel_steer),
                      field("vel_turret", &NomadData::vel_turret),
                      field("sonar", &NomadData::sonar),
                      field("ir", &NomadData::ir),
                      field("bumper", &NomadData::bumper)};
  }
  friend bool operator==(const NomadData&, const NomadData&) = default;
};

struct NomadCommand {
  static constexpr std::string_view kWireName = "player_nomad_cmd_t";
  static constexpr std::size_t kWireSize = 12;

  std::int32_t vel_trans = 0;  // translational velocity
  std::int32_t vel_steer = 0;  // steering velocity
  std::int32_t vel_turret = 0;  // turret velocity

  static constexpr auto fields() {
    return std::tuple{field("vel_trans", &NomadCommand::vel_trans),
                      field("vel_steer", &NomadCommand::vel_steer),
                      field("vel_turret", &NomadCommand::vel_turret)};
  }
  friend bool operator==(const NomadCommand&, const NomadCommand&) = default;
};

}  // namespace playerkit::protocol
