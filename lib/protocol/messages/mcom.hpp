#pragma once
// Player 1.5 `mcom` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kMcomDataLen = 128;  // mcom payload bytes
inline constexpr std::size_t kMcomCommandBufferSize = 140;  // size of player_mcom_config_t
inline constexpr std::size_t kMcomDataBufferSize = 0;  // mcom has no data packet
inline constexpr std::size_t kMcomNBufs = 10;  // messages kept per channel
inline constexpr std::size_t kMcomChannelLen = 8;  // channel name bytes
inline constexpr std::uint8_t kMcomPushReq = 0;  // push message
inline constexpr std::uint8_t kMcomPopReq = 1;  // pop message
inline constexpr std::uint8_t kMcomReadReq = 2;  // read without removing
inline constexpr std::uint8_t kMcomClearReq = 3;  // clear channel
inline constexpr std::uint8_t kMcomSetCapacityReq = 4;  // set channel capacity

struct McomData {
  static constexpr std::string_view kWireName = "player_mcom_data_t";
  static constexpr std::size_t kWireSize = 129;

  std::uint8_t full = 0;  // flag: non-zero if the slot holds data
  FixedString<128> data{};  // message bytes

  static constexpr auto fields() {
    return std::tuple{field("full", &McomData::full),
                      field("data", &McomData::data)};
  }
  friend bool operator==(const McomData&, const McomData&) = default;
};

struct McomConfig {
  static constexpr std::string_view kWireName = "player_mcom_config_t";
  static constexpr std::size_t kWireSize = 140;

  std::uint8_t command = 0;  // PLAYER_MCOM_*_REQ (0..4)
  std::uint16_t type = 0;  // message type tag
  FixedString<8> channel{};  // channel name
  McomData data{};  // payload (129 bytes)

  static constexpr auto fields() {
    return std::tuple{field("command", &McomConfig::command),
                      field("type", &McomConfig::type),
                      field("channel", &McomConfig::channel),
                      field("data", &McomConfig::data)};
  }
  friend bool operator==(const McomConfig&, const McomConfig&) = default;
};

struct McomReturn {
  static constexpr std::string_view kWireName = "player_mcom_return_t";
  static constexpr std::size_t kWireSize = 139;

  std::uint16_t type = 0;  // message type tag
  FixedString<8> channel{};  // channel name
  McomData data{};  // payload (129 bytes)

  static constexpr auto fields() {
    return std::tuple{field("type", &McomReturn::type),
                      field("channel", &McomReturn::channel),
                      field("data", &McomReturn::data)};
  }
  friend bool operator==(const McomReturn&, const McomReturn&) = default;
};

}  // namespace playerkit::protocol
