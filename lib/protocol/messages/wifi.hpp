#pragma once
// Player 1.5 `wifi` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kWifiMaxLinks = 16;  // capacity of wifi link list
inline constexpr std::uint8_t kWifiQualDbm = 1;  // quality values are dBm
inline constexpr std::uint8_t kWifiQualRel = 2;  // quality values are relative
inline constexpr std::uint8_t kWifiQualUnknown = 3;  // quality type unknown
inline constexpr std::uint8_t kWifiModeUnknown = 0;  // mode unknown
inline constexpr std::uint8_t kWifiModeAuto = 1;  // driver chooses
inline constexpr std::uint8_t kWifiModeAdhoc = 2;  // ad hoc
inline constexpr std::uint8_t kWifiModeInfra = 3;  // infrastructure
inline constexpr std::uint8_t kWifiModeMaster = 4;  // access point
inline constexpr std::uint8_t kWifiModeRepeat = 5;  // repeater
inline constexpr std::uint8_t kWifiModeSecond = 6;  // secondary repeater
inline constexpr std::uint8_t kWifiMacReq = 1;  // get MAC address
inline constexpr std::uint8_t kWifiIwspyAddReq = 10;  // add iwspy address
inline constexpr std::uint8_t kWifiIwspyDelReq = 11;  // remove iwspy address
inline constexpr std::uint8_t kWifiIwspyPingReq = 12;  // ping iwspy addresses

struct WifiMacRequest {
  static constexpr std::string_view kWireName = "player_wifi_mac_req_t";
  static constexpr std::size_t kWireSize = 1;

  std::uint8_t subtype = 0;  // PLAYER_WIFI_MAC_REQ (1)

  static constexpr auto fields() {
    return std::tuple{field("subtype", &WifiMacRequest::subtype)};
  }
  friend bool operator==(const WifiMacRequest&, const WifiMacRequest&) = default;
};

struct WifiIwspyAddrRequest {
  static constexpr std::string_view kWireName = "player_wifi_iwspy_addr_req_t";
  static constexpr std::size_t kWireSize = 33;

  std::uint8_t subtype = 0;  // PLAYER_WIFI_IWSPY_ADD/DEL/PING_REQ (10..12)
  FixedString<32> address{};  // address text, NUL-terminated

  static constexpr auto fields() {
    return std::tuple{field("subtype", &WifiIwspyAddrRequest::subtype),
                      field("address", &WifiIwspyAddrRequest::address)};
  }
  friend bool operator==(const WifiIwspyAddrRequest&, const WifiIwspyAddrRequest&) = default;
};

struct WifiLink {
  static constexpr std::string_view kWireName = "player_wifi_link_t";
  static constexpr std::size_t kWireSize = 38;

  FixedString<32> ip{};  // remote IP address as text
  std::uint16_t qual = 0;  // link quality
  std::uint16_t level = 0;  // signal level
  std::uint16_t noise = 0;  // noise level

  static constexpr auto fields() {
    return std::tuple{field("ip", &WifiLink::ip),
                      field("qual", &WifiLink::qual),
                      field("level", &WifiLink::level),
                      field("noise", &WifiLink::noise)};
  }
  friend bool operator==(const WifiLink&, const WifiLink&) = default;
};

struct WifiData {
  static constexpr std::string_view kWireName = "player_wifi_data_t";
  static constexpr std::size_t kWireSize = 658;

  std::array<WifiLink, 16> links{};  // per-host link info (38 bytes each)
  std::uint16_t link_count = 0;  // number of valid links
  std::uint32_t throughput = 0;  // driver-computed throughput
  std::int32_t bitrate = 0;  // current bit rate
  std::uint8_t mode = 0;  // PLAYER_WIFI_MODE_* (0..6)
  std::uint8_t qual_type = 0;  // PLAYER_WIFI_QUAL_* (1..3)
  std::uint16_t maxqual = 0;  // maximum quality
  std::uint16_t maxlevel = 0;  // maximum level
  std::uint16_t maxnoise = 0;  // maximum noise
  FixedString<32> ap{};  // MAC address of access point, text

  static constexpr auto fields() {
    return std::tuple{counted("links", &WifiData::links, &WifiData::link_count),
                      field("link_count", &WifiData::link_count),
                      field("throughput", &WifiData::throughput),
                      field("bitrate", &WifiData::bitrate),
                      field("mode", &WifiData::mode),
                      field("qual_type", &WifiData::qual_type),
                      field("maxqual", &WifiData::maxqual),
                      field("maxlevel", &WifiData::maxlevel),
                      field("maxnoise", &WifiData::maxnoise),
                      field("ap", &WifiData::ap)};
  }
  friend bool operator==(const WifiData&, const WifiData&) = default;
};

}  // namespace playerkit::protocol
