#pragma once
// Player 1.5 `truth` payloads: constants and packed structs, field for field
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

inline constexpr std::uint8_t kTruthGetPose = 0;  // read pose (value 0)
inline constexpr std::uint8_t kTruthSetPose = 1;  // set pose
inline constexpr std::uint8_t kTruthSetPoseOnRoot = 2;  // set pose and drop object on background
inline constexpr std::uint8_t kTruthGetFiducialId = 3;  // read fiducial id
inline constexpr std::uint8_t kTruthSetFiducialId = 4;  // set fiducial id

struct TruthData {
  static constexpr std::string_view kWireName = "player_truth_data_t";
  static constexpr std::size_t kWireSize = 12;

  std::int32_t px = 0;  // world x, mm
  std::int32_t py = 0;  // world y, mm
  std::int32_t pa = 0;  // world heading, degrees

  static constexpr auto fields() {
    return std::tuple{field("px", &TruthData::px),
                      field("py", &TruthData::py),
                      field("pa", &TruthData::pa)};
  }
  friend bool operator==(const TruthData&, const TruthData&) = default;
};

struct TruthPose {
  static constexpr std::string_view kWireName = "player_truth_pose_t";
  static constexpr std::size_t kWireSize = 13;

  std::uint8_t subtype = 0;  // PLAYER_TRUTH_GET_POSE (0), _SET_POSE (1) or _SET_POSE_ON_ROOT (2)
  std::int32_t px = 0;  // world x, mm
  std::int32_t py = 0;  // world y, mm
  std::int32_t pa = 0;  // heading, degrees

  static constexpr auto fields() {
    return std::tuple{field("subtype", &TruthPose::subtype),
                      field("px", &TruthPose::px),
                      field("py", &TruthPose::py),
                      field("pa", &TruthPose::pa)};
  }
  friend bool operator==(const TruthPose&, const TruthPose&) = default;
};

struct TruthFiducialId {
  static constexpr std::string_view kWireName = "player_truth_fiducial_id_t";
  static constexpr std::size_t kWireSize = 3;

  std::uint8_t subtype = 0;  // PLAYER_TRUTH_GET_FIDUCIAL_ID (3) or _SET_FIDUCIAL_ID (4)
  std::int16_t id = 0;  // fiducial id

  static constexpr auto fields() {
    return std::tuple{field("subtype", &TruthFiducialId::subtype),
                      field("id", &TruthFiducialId::id)};
  }
  friend bool operator==(const TruthFiducialId&, const TruthFiducialId&) = default;
};

}  // namespace playerkit::protocol
