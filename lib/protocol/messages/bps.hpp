#pragma once
// Player 1.5 `bps` payloads: constants and packed structs, field for field
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

inline constexpr std::uint8_t kBpsSetConfig = 1;  // BPS set config (empty)
inline constexpr std::uint8_t kBpsGetConfig = 2;  // BPS get config
inline constexpr std::uint8_t kBpsSetBeacon = 3;  // set beacon pose
inline constexpr std::uint8_t kBpsGetBeacon = 4;  // get beacon pose

struct BpsData {
  static constexpr std::string_view kWireName = "player_bps_data_t";
  static constexpr std::size_t kWireSize = 28;

  std::int32_t px = 0;  // global x, mm
  std::int32_t py = 0;  // global y, mm
  std::int32_t pa = 0;  // heading, degrees
  std::int32_t ux = 0;  // uncertainty x, mm
  std::int32_t uy = 0;  // uncertainty y, mm
  std::int32_t ua = 0;  // uncertainty heading, degrees
  std::int32_t err = 0;  // residual error times 1e6

  static constexpr auto fields() {
    return std::tuple{field("px", &BpsData::px),
                      field("py", &BpsData::py),
                      field("pa", &BpsData::pa),
                      field("ux", &BpsData::ux),
                      field("uy", &BpsData::uy),
                      field("ua", &BpsData::ua),
                      field("err", &BpsData::err)};
  }
  friend bool operator==(const BpsData&, const BpsData&) = default;
};

struct BpsConfig {
  static constexpr std::string_view kWireName = "player_bps_config_t";
  static constexpr std::size_t kWireSize = 1;

  std::uint8_t subtype = 0;  // PLAYER_BPS_SET_CONFIG (1) or _GET_CONFIG (2)

  static constexpr auto fields() {
    return std::tuple{field("subtype", &BpsConfig::subtype)};
  }
  friend bool operator==(const BpsConfig&, const BpsConfig&) = default;
};

struct BpsBeacon {
  static constexpr std::string_view kWireName = "player_bps_beacon_t";
  static constexpr std::size_t kWireSize = 26;

  std::uint8_t subtype = 0;  // PLAYER_BPS_SET_BEACON (3) or _GET_BEACON (4)
  std::uint8_t id = 0;  // beacon id (non-zero)
  std::int32_t px = 0;  // beacon x, mm
  std::int32_t py = 0;  // beacon y, mm
  std::int32_t pa = 0;  // beacon heading, degrees
  std::int32_t ux = 0;  // uncertainty x, mm
  std::int32_t uy = 0;  // uncertainty y, mm
  std::int32_t ua = 0;  // uncertainty heading, degrees

  static constexpr auto fields() {
    return std::tuple{field("subtype", &BpsBeacon::subtype),
                      field("id", &BpsBeacon::id),
                      field("px", &BpsBeacon::px),
                      field("py", &BpsBeacon::py),
                      field("pa", &BpsBeacon::pa),
                      field("ux", &BpsBeacon::ux),
                      field("uy", &BpsBeacon::uy),
                      field("ua", &BpsBeacon::ua)};
  }
  friend bool operator==(const BpsBeacon&, const BpsBeacon&) = default;
};

}  // namespace playerkit::protocol
