#pragma once
// Player 1.5 `localize` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kLocalizeMaxHypoths = 10;  // capacity of hypothesis list
inline constexpr std::uint8_t kLocalizeSetPoseReq = 1;  // set pose estimate
inline constexpr std::uint8_t kLocalizeGetConfigReq = 2;  // read filter config
inline constexpr std::uint8_t kLocalizeSetConfigReq = 3;  // set filter config
inline constexpr std::uint8_t kLocalizeGetMapInfoReq = 4;  // map size and scale
inline constexpr std::uint8_t kLocalizeGetMapDataReq = 5;  // one map tile

struct LocalizeHypothesis {
  static constexpr std::string_view kWireName = "player_localize_hypoth_t";
  static constexpr std::size_t kWireSize = 88;

  std::array<std::int32_t, 3> mean{};  // x mm, y mm, heading arc-seconds
  std::array<std::array<std::int64_t, 3>, 3> cov{};  // 3x3 covariance, row-major, int64 big-endian (mm^2, arcsec^2)
  std::uint32_t alpha = 0;  // weight times 1e6

  static constexpr auto fields() {
    return std::tuple{field("mean", &LocalizeHypothesis::mean),
                      field("cov", &LocalizeHypothesis::cov),
                      field("alpha", &LocalizeHypothesis::alpha)};
  }
  friend bool operator==(const LocalizeHypothesis&, const LocalizeHypothesis&) = default;
};

struct LocalizeData {
  static constexpr std::string_view kWireName = "player_localize_data_t";
  static constexpr std::size_t kWireSize = 894;

  std::uint16_t pending_count = 0;  // number of unprocessed observations
  std::uint32_t pending_time_sec = 0;  // time of last processed observation, s
  std::uint32_t pending_time_usec = 0;  // same, us
  std::uint32_t hypoth_count = 0;  // number of valid hypotheses (uint32)
  std::array<LocalizeHypothesis, 10> hypoths{};  // hypotheses (88 bytes each)

  static constexpr auto fields() {
    return std::tuple{field("pending_count", &LocalizeData::pending_count),
                      field("pending_time_sec", &LocalizeData::pending_time_sec),
                      field("pending_time_usec", &LocalizeData::pending_time_usec),
                      field("hypoth_count", &LocalizeData::hypoth_count),
                      counted_tail("hypoths", &LocalizeData::hypoths, &LocalizeData::hypoth_count)};
  }
  friend bool operator==(const LocalizeData&, const LocalizeData&) = default;
};

struct LocalizeSetPose {
  static constexpr std::string_view kWireName = "player_localize_set_pose_t";
  static constexpr std::size_t kWireSize = 85;

  std::uint8_t subtype = 0;  // PLAYER_LOCALIZE_SET_POSE_REQ (1)
  std::array<std::int32_t, 3> mean{};  // x mm, y mm, heading arc-seconds
  std::array<std::array<std::int64_t, 3>, 3> cov{};  // 3x3 covariance, int64 big-endian (mm^2, arcsec^2)

  static constexpr auto fields() {
    return std::tuple{field("subtype", &LocalizeSetPose::subtype),
                      field("mean", &LocalizeSetPose::mean),
                      field("cov", &LocalizeSetPose::cov)};
  }
  friend bool operator==(const LocalizeSetPose&, const LocalizeSetPose&) = default;
};

struct LocalizeConfig {
  static constexpr std::string_view kWireName = "player_localize_config_t";
  static constexpr std::size_t kWireSize = 5;

  std::uint8_t subtype = 0;  // PLAYER_LOCALIZE_GET_CONFIG_REQ (2) or _SET_CONFIG_REQ (3)
  std::uint32_t num_particles = 0;  // maximum particle count

  static constexpr auto fields() {
    return std::tuple{field("subtype", &LocalizeConfig::subtype),
                      field("num_particles", &LocalizeConfig::num_particles)};
  }
  friend bool operator==(const LocalizeConfig&, const LocalizeConfig&) = default;
};

struct LocalizeMapInfo {
  static constexpr std::string_view kWireName = "player_localize_map_info_t";
  static constexpr std::size_t kWireSize = 13;

  std::uint8_t subtype = 0;  // PLAYER_LOCALIZE_GET_MAP_INFO_REQ (4)
  std::uint32_t scale = 0;  // map scale, pixels per kilometre
  std::uint32_t width = 0;  // map width, pixels
  std::uint32_t height = 0;  // map height, pixels

  static constexpr auto fields() {
    return std::tuple{field("subtype", &LocalizeMapInfo::subtype),
                      field("scale", &LocalizeMapInfo::scale),
                      field("width", &LocalizeMapInfo::width),
                      field("height", &LocalizeMapInfo::height)};
  }
  friend bool operator==(const LocalizeMapInfo&, const LocalizeMapInfo&) = default;
};

// A tile request carries only the 17-byte tile header; the reply carries the cells.
struct LocalizeMapData {
  static constexpr std::string_view kWireName = "player_localize_map_data_t";
  static constexpr std::size_t kWireSize = 4096;

  std::uint8_t subtype = 0;  // PLAYER_LOCALIZE_GET_MAP_DATA_REQ (5)
  std::uint32_t col = 0;  // tile origin column, pixels
  std::uint32_t row = 0;  // tile origin row, pixels
  std::uint32_t width = 0;  // tile width, pixels
  std::uint32_t height = 0;  // tile height, pixels
  std::vector<std::int8_t> data{};  // cells: -1 empty, 0 unknown, +1 occupied

  static constexpr auto fields() {
    return std::tuple{field("subtype", &LocalizeMapData::subtype),
                      field("col", &LocalizeMapData::col),
                      field("row", &LocalizeMapData::row),
                      field("width", &LocalizeMapData::width),
                      field("height", &LocalizeMapData::height),
                      tail("data", &LocalizeMapData::data, 4079, 4079)};
  }
  friend bool operator==(const LocalizeMapData&, const LocalizeMapData&) = default;
};

}  // namespace playerkit::protocol
