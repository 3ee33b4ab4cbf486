#pragma once
// Player 1.5 `idarturret` payloads: constants and packed structs, field for field
// as in wire-format.md §5 (names, order, sizes). Values are in wire units.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <tuple>
#include <vector>

#include "protocol/fields.hpp"
#include "protocol/fixed_string.hpp"
#include "protocol/messages/idar.hpp"

namespace playerkit::protocol {

inline constexpr std::size_t kIdarturretIdarCount = 8;  // IDARs per turret

struct IdarTurretReply {
  static constexpr std::string_view kWireName = "player_idarturret_reply_t";
  static constexpr std::size_t kWireSize = 232;

  std::array<IdarRx, 8> rx{};  // one received message per IDAR (29 bytes each)

  static constexpr auto fields() {
    return std::tuple{field("rx", &IdarTurretReply::rx)};
  }
  friend bool operator==(const IdarTurretReply&, const IdarTurretReply&) = default;
};

struct IdarTurretConfig {
  static constexpr std::string_view kWireName = "player_idarturret_config_t";
  static constexpr std::size_t kWireSize = 145;

  std::uint8_t instruction = 0;  // IDAR_* instruction
  std::array<IdarTx, 8> tx{};  // one message per IDAR (18 bytes each)

  static constexpr auto fields() {
    return std::tuple{field("instruction", &IdarTurretConfig::instruction),
                      field("tx", &IdarTurretConfig::tx)};
  }
  friend bool operator==(const IdarTurretConfig&, const IdarTurretConfig&) = default;
};

}  // namespace playerkit::protocol
