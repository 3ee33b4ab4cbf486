#pragma once
// Player 1.5 `ir` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kIrMaxSamples = 32;  // capacity of IR arrays
inline constexpr std::uint8_t kIrPoseReq = 1;  // get IR poses
inline constexpr std::uint8_t kIrPowerReq = 2;  // IR power on/off

struct IrData {
  static constexpr std::string_view kWireName = "player_ir_data_t";
  static constexpr std::size_t kWireSize = 130;

  std::uint16_t range_count = 0;  // number of valid samples
  std::array<std::uint16_t, 32> voltages{};  // raw voltages (units unspecified)
  std::array<std::uint16_t, 32> ranges{};  // ranges, mm

  static constexpr auto fields() {
    return std::tuple{field("range_count", &IrData::range_count),
                      counted("voltages", &IrData::voltages, &IrData::range_count),
                      counted("ranges", &IrData::ranges, &IrData::range_count)};
  }
  friend bool operator==(const IrData&, const IrData&) = default;
};

struct IrPose {
  static constexpr std::string_view kWireName = "player_ir_pose_t";
  static constexpr std::size_t kWireSize = 194;

  std::uint16_t pose_count = 0;  // number of valid poses
  std::array<std::array<std::int16_t, 3>, 32> poses{};  // per sensor: x mm, y mm, yaw deg

  static constexpr auto fields() {
    return std::tuple{field("pose_count", &IrPose::pose_count),
                      counted("poses", &IrPose::poses, &IrPose::pose_count)};
  }
  friend bool operator==(const IrPose&, const IrPose&) = default;
};

struct IrPoseRequest {
  static constexpr std::string_view kWireName = "player_ir_pose_req_t";
  static constexpr std::size_t kWireSize = 195;

  std::uint8_t subtype = 0;  // PLAYER_IR_POSE_REQ (1)
  IrPose poses{};  // embedded player_ir_pose_t (194 bytes)

  static constexpr auto fields() {
    return std::tuple{field("subtype", &IrPoseRequest::subtype),
                      field("poses", &IrPoseRequest::poses)};
  }
  friend bool operator==(const IrPoseRequest&, const IrPoseRequest&) = default;
};

struct IrPowerRequest {
  static constexpr std::string_view kWireName = "player_ir_power_req_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint8_t subtype = 0;  // PLAYER_IR_POWER_REQ (2)
  std::uint8_t state = 0;  // 0 off, 1 on

  static constexpr auto fields() {
    return std::tuple{field("subtype", &IrPowerRequest::subtype),
                      field("state", &IrPowerRequest::state)};
  }
  friend bool operator==(const IrPowerRequest&, const IrPowerRequest&) = default;
};

}  // namespace playerkit::protocol
