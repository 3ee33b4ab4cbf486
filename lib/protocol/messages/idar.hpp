#pragma once
// Player 1.5 `idar` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kIdarBufferLength = 16;  // IDAR message capacity
inline constexpr std::uint8_t kRaysPerSensor = 5;  // IDAR ray resolution (driver internal)
inline constexpr std::uint8_t kIdarTransmit = 0;  // instruction: transmit
inline constexpr std::uint8_t kIdarReceive = 1;  // instruction: receive and flush
inline constexpr std::uint8_t kIdarReceiveNoflush = 2;  // instruction: receive, keep
inline constexpr std::uint8_t kIdarTransmitReceive = 3;  // instruction: transmit then receive

struct IdarTx {
  static constexpr std::string_view kWireName = "idartx_t";
  static constexpr std::size_t kWireSize = 18;

  std::array<std::uint8_t, 16> mesg{};  // message bytes
  std::uint8_t len = 0;  // valid bytes (0..16)
  std::uint8_t intensity = 0;  // transmit power 0-255

  static constexpr auto fields() {
    return std::tuple{counted("mesg", &IdarTx::mesg, &IdarTx::len),
                      field("len", &IdarTx::len),
                      field("intensity", &IdarTx::intensity)};
  }
  friend bool operator==(const IdarTx&, const IdarTx&) = default;
};

struct IdarRx {
  static constexpr std::string_view kWireName = "idarrx_t";
  static constexpr std::size_t kWireSize = 29;

  std::array<std::uint8_t, 16> mesg{};  // message bytes
  std::uint8_t len = 0;  // valid bytes
  std::uint8_t intensity = 0;  // received intensity 0-255
  std::uint8_t reflection = 0;  // true if own reflection
  std::uint32_t timestamp_sec = 0;  // receive time, s
  std::uint32_t timestamp_usec = 0;  // receive time, us
  std::uint16_t range = 0;  // range, mm

  static constexpr auto fields() {
    return std::tuple{counted("mesg", &IdarRx::mesg, &IdarRx::len),
                      field("len", &IdarRx::len),
                      field("intensity", &IdarRx::intensity),
                      field("reflection", &IdarRx::reflection),
                      field("timestamp_sec", &IdarRx::timestamp_sec),
                      field("timestamp_usec", &IdarRx::timestamp_usec),
                      field("range", &IdarRx::range)};
  }
  friend bool operator==(const IdarRx&, const IdarRx&) = default;
};

struct IdarConfig {
  static constexpr std::string_view kWireName = "player_idar_config_t";
  static constexpr std::size_t kWireSize = 19;

  std::uint8_t instruction = 0;  // IDAR_TRANSMIT/RECEIVE/... (0..3)
  IdarTx tx{};  // message for transmit instructions (18 bytes)

  static constexpr auto fields() {
    return std::tuple{field("instruction", &IdarConfig::instruction),
                      field("tx", &IdarConfig::tx)};
  }
  friend bool operator==(const IdarConfig&, const IdarConfig&) = default;
};

}  // namespace playerkit::protocol
